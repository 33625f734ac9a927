# One precompiled header for every C++ target of the build: the standard library, Eigen and
# nlohmann::json, which nearly every file includes and which take about a quarter of a file's
# compile time to parse. GCC uses a PCH only where the code-generation flags match, so every
# target of a build shares the same flags (-fPIC everywhere with the Python module, see the
# top-level CMakeLists.txt); where they do not, GCC parses the headers instead (-Winvalid-pch).
option(DASHBED_PCH "Precompile the standard, Eigen and JSON headers once for all targets" ON)

if(DASHBED_PCH)
  add_library(dashbed_pch OBJECT ${CMAKE_CURRENT_LIST_DIR}/pch.cpp)
  # the project's warning flags too: -Wpedantic changes what GCC predefines
  target_link_libraries(dashbed_pch PRIVATE dashbed_warnings Eigen3::Eigen nlohmann_json::nlohmann_json)
  target_precompile_headers(dashbed_pch PRIVATE
    <algorithm> <array> <cmath> <cstdint> <functional> <map> <memory> <optional> <set> <sstream>
    <string> <unordered_map> <utility> <vector>
    <Eigen/Dense> <Eigen/Geometry> <nlohmann/json.hpp>)
endif()

# Every C++ target under `dir` (recursively) reuses the precompiled header, except those that
# must see a header's configuration macros before it (tests/test_main.cpp, Catch2's main).
function(dashbed_reuse_pch dir)
  if(NOT DASHBED_PCH)
    return()
  endif()
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(target STREQUAL dashbed_pch OR target STREQUAL dashbed_test_main OR type STREQUAL INTERFACE_LIBRARY
       OR type STREQUAL UTILITY)
      continue()
    endif()
    target_precompile_headers(${target} REUSE_FROM dashbed_pch)
    # the headers' own paths, where a target would not otherwise have them
    target_link_libraries(${target} PRIVATE Eigen3::Eigen nlohmann_json::nlohmann_json)
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(subdir IN LISTS subdirs)
    dashbed_reuse_pch(${subdir})
  endforeach()
endfunction()

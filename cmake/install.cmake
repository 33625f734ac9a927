# `cmake --install build --prefix P`: the dashbed binary and dashbed-sync, the libraries with their public
# headers, the robot assets and example worlds, and a CMake package so that another project's
# find_package(dashbed) gives dashbed::core, dashbed::planner and dashbed::sim (with
# dashbed::controllers, dashbed::render and dashbed::sim_job, which they build on).
include(CMakePackageConfigHelpers)

set(dashbed_libraries dashbed_core dashbed_controllers dashbed_sim dashbed_render dashbed_replay dashbed_sim_job dashbed_planner)
foreach(library IN LISTS dashbed_libraries)
  string(REPLACE "dashbed_" "" export_name ${library})
  set_target_properties(${library} PROPERTIES EXPORT_NAME ${export_name})
endforeach()
# dashbed_warnings: compile options only, linked privately; exported because static libraries
# name their private dependencies in the export
install(TARGETS ${dashbed_libraries} dashbed_warnings EXPORT dashbedTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dashbed)
install(TARGETS dashbed RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# the synchronisation server of exported URScript programs
install(PROGRAMS ${PROJECT_SOURCE_DIR}/tools/export/dashbed_sync.py DESTINATION ${CMAKE_INSTALL_BINDIR}
        RENAME dashbed-sync)

# public headers, by folder; a folder's internal/ headers stay behind
foreach(folder core controllers sim sim/render sim/replay sim/job planner planner/collision planner/task_space
               planner/sampling planner/motion planner/search planner/scheduling)
  file(GLOB headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${folder}/*.h)
  install(FILES ${headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dashbed/${folder})
endforeach()

install(DIRECTORY ${PROJECT_SOURCE_DIR}/assets/ DESTINATION ${CMAKE_INSTALL_DATADIR}/dashbed/assets
        PATTERN node_modules EXCLUDE)
# of the HTML replay's npm packages, three.js's one file each replay inlines (tools/setup.sh installs it)
install(FILES ${PROJECT_SOURCE_DIR}/assets/web/node_modules/three/build/three.min.js
        DESTINATION ${CMAKE_INSTALL_DATADIR}/dashbed/assets/web/node_modules/three/build OPTIONAL)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/worlds/ DESTINATION ${CMAKE_INSTALL_DATADIR}/dashbed/worlds)

set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/dashbed)
install(EXPORT dashbedTargets NAMESPACE dashbed:: DESTINATION ${config_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/dashbedConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/dashbedConfig.cmake INSTALL_DESTINATION ${config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/dashbedConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/dashbedConfig.cmake ${PROJECT_BINARY_DIR}/dashbedConfigVersion.cmake
        DESTINATION ${config_dir})

# `cmake --install` into a fresh prefix, then use it as a user would: build examples/
# plan_and_simulate against find_package(dashbed) and run it (plan, simulate, every action
# passes), and run the installed binary from another folder, which must find its world and
# assets under the prefix without DASHBED_HOME; with the Python package, import the installed
# one and plan and check a world with it.
# -DBUILD_DIR= -DSOURCE_DIR= -DWORK_DIR= [-DPYTHON= -DPYTHON_DIR=, the package's folder under the prefix]
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
unset(ENV{DASHBED_HOME})

function(run_checked what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err
                  WORKING_DIRECTORY ${WORK_DIR})
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${what} failed (exit ${code}):\n${out}\n${err}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

file(MAKE_DIRECTORY ${WORK_DIR})
run_checked("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(file bin/dashbed share/dashbed/assets/ur5e_hande.urdf share/dashbed/worlds/default.yaml
             include/dashbed/planner/dash_planner.h include/dashbed/sim/run_plan.h
             lib/cmake/dashbed/dashbedConfig.cmake)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "not installed: ${prefix}/${file}")
  endif()
endforeach()
if(EXISTS ${prefix}/include/dashbed/planner/collision/internal)
  message(FATAL_ERROR "internal headers installed: ${prefix}/include/dashbed/planner/collision/internal")
endif()

run_checked("the installed dashbed" ${prefix}/bin/dashbed run --validate-only)
string(FIND "${output}" "${prefix}/share/dashbed/worlds/default.yaml" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the installed dashbed did not take its default world from the prefix:\n${output}")
endif()

run_checked("configuring the example" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/plan_and_simulate
            -B ${WORK_DIR}/example -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
run_checked("building the example" ${CMAKE_COMMAND} --build ${WORK_DIR}/example)
run_checked("the example" ${WORK_DIR}/example/plan_and_simulate ${prefix}/share/dashbed/worlds/default.yaml)
if(NOT output MATCHES "PASS pick [a-z_0-9]+ by r[0-9]" OR NOT output MATCHES "\nPASSED\n")
  message(FATAL_ERROR "the example's run did not pass every action:\n${output}")
endif()
message(STATUS "${output}")

if(PYTHON)
  set(ENV{PYTHONPATH} ${prefix}/${PYTHON_DIR})
  # (no semicolons in the code: run_checked's arguments are a CMake list)
  run_checked("the installed Python package" ${PYTHON} -c
              "import dashbed\nr = dashbed.plan(dashbed.World.default())\nprint(dashbed.__file__, r.status, len(r.plan.actions))")
  if(NOT output MATCHES "^${prefix}/${PYTHON_DIR}/dashbed/__init__.py solved [1-9]")
    message(FATAL_ERROR "the installed Python package did not plan the default world:\n${output}")
  endif()
endif()

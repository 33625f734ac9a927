# Determinism across processes and places: the same world, plans (Greedy and MM-DaSH) and
# report from two separate `dashbed` processes, each writing into its own folder, are the same
# bytes.
#
#   cmake -DDASHBED=<dashbed binary> -DWORK_DIR=<scratch dir> -P determinism.cmake
cmake_minimum_required(VERSION 3.22)

file(REMOVE_RECURSE "${WORK_DIR}")

include(${CMAKE_CURRENT_LIST_DIR}/run_command.cmake)

foreach(place IN ITEMS first second/nested)
  set(dir "${WORK_DIR}/${place}")
  file(MAKE_DIRECTORY "${dir}")
  run("${DASHBED}" gen sort --robots 2 --cubes 4 --start random --seed 5 -o "${dir}/world.yaml")
  run("${DASHBED}" plan "${dir}/world.yaml" --method greedy --seed 3 -o "${dir}/greedy.json")
  run("${DASHBED}" plan "${dir}/world.yaml" --method optimal --seed 3 -o "${dir}/optimal.json")
  run("${DASHBED}" sim "${dir}/optimal.json" --world "${dir}/world.yaml" --report "${dir}/report.json" --quiet)
endforeach()

foreach(name IN ITEMS world.yaml greedy.json optimal.json report.json)
  file(READ "${WORK_DIR}/first/${name}" first)
  file(READ "${WORK_DIR}/second/nested/${name}" second)
  if(first STREQUAL "")
    message(FATAL_ERROR "${name} is empty")
  endif()
  if(NOT first STREQUAL second)
    message(FATAL_ERROR "${name} differs between two processes")
  endif()
endforeach()
message(STATUS "two processes wrote the same world, Greedy and MM-DaSH plans and report")
file(REMOVE_RECURSE "${WORK_DIR}")

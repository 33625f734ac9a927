# MPI smoke test of `dashbed stress`: the same small campaign run by one process and by two
# MPI ranks must write byte-identical results (summary, JUnit, trials.csv, the saved trials),
# and each rank must have run its share of the trials (rank 0 reports what it gathered).
#
#   cmake -DDASHBED=<dashbed binary> -DMPIEXEC=<mpirun> -DWORLD=<world file> -DWORK_DIR=<scratch dir>
#         -P stress_mpi_smoke.cmake
cmake_minimum_required(VERSION 3.22)

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

include(${CMAKE_CURRENT_LIST_DIR}/../../run_command.cmake)

# a grasp 5 mm off the cube's centre: some trials pass, some fail, so trials get saved (the
# statements are separated by a newline: a ';' would split the CMake argument)
run("${DASHBED}" script "${WORLD}" --script "r1 picks cube_0 offset 0 0.005 0\nr1 places cube_0 in bin_green"
    -o "${WORK_DIR}/plan.json")
set(campaign stress "${WORLD}" --plan "${WORK_DIR}/plan.json" --trials 4 --sigma-xy 0.002 --seed 3 --threads 1
    --worst 2)
run("${DASHBED}" ${campaign} --out "${WORK_DIR}/single")
# --oversubscribe: 2 ranks even on a machine with fewer free cores; CI runs as root
run("${MPIEXEC}" --allow-run-as-root --oversubscribe -np 2 "${DASHBED}" ${campaign} --out "${WORK_DIR}/mpi")
# every 2nd trial on each rank: 2 and 2 of the 4 (ranks running the whole campaign on their own
# would each report 1 process and write the same files)
if(NOT output MATCHES "4 trials in [0-9.]+ s on 2 processes \\(2 \\+ 2 trials\\)")
  message(FATAL_ERROR "the 2 ranks did not share the 4 trials 2 + 2:\n${output}")
endif()

file(GLOB_RECURSE single_files RELATIVE "${WORK_DIR}/single" "${WORK_DIR}/single/*")
file(GLOB_RECURSE mpi_files RELATIVE "${WORK_DIR}/mpi" "${WORK_DIR}/mpi/*")
list(SORT single_files)
list(SORT mpi_files)
if(NOT single_files STREQUAL mpi_files)
  message(FATAL_ERROR "different files: single process ${single_files}, 2 ranks ${mpi_files}")
endif()
set(saved_reports ${single_files})
list(FILTER saved_reports INCLUDE REGEX "^trial_[0-9]+/report.json$")
if(NOT saved_reports)
  message(FATAL_ERROR "expected a saved failed trial among ${single_files}")
endif()
foreach(name IN LISTS single_files)
  file(READ "${WORK_DIR}/single/${name}" expected)
  file(READ "${WORK_DIR}/mpi/${name}" actual)
  if(NOT expected STREQUAL actual)
    message(FATAL_ERROR "${name} differs between 1 process and 2 MPI ranks")
  endif()
endforeach()
list(LENGTH single_files count)
message(STATUS "1 process and 2 MPI ranks wrote the same ${count} files")
file(REMOVE_RECURSE "${WORK_DIR}")

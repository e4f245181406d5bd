# Runs a step program once alone and once behind MPI_LAUNCHER (e.g.
# mpiexec -n 2), through run_program.cmake, and checks that every bound in
# results.json is the same number in both runs, and that the second run
# spread the components' builds over its ranks.
set(base "${WORKDIR}")
set(EXPECT success)

set(WORKDIR "${base}/np1")
include(${CMAKE_CURRENT_LIST_DIR}/run_program.cmake)
set(one "${RESULTS_JSON}")

set(WORKDIR "${base}/np2")
set(LAUNCHER "${MPI_LAUNCHER}")
include(${CMAKE_CURRENT_LIST_DIR}/run_program.cmake)
set(two "${RESULTS_JSON}")

string(JSON processes GET "${two}" mpi_processes)
if(NOT processes EQUAL 2)
  message(FATAL_ERROR "the second run used ${processes} process(es)")
endif()
string(JSON n_outputs LENGTH "${one}" outputs)
math(EXPR last "${n_outputs} - 1")
foreach(k RANGE ${last})
  string(JSON name GET "${one}" outputs ${k} name)
  foreach(key lower upper vertex_lower vertex_upper reference_lower reference_upper)
    string(JSON a GET "${one}" outputs ${k} ${key})
    string(JSON b GET "${two}" outputs ${k} ${key})
    if(NOT a STREQUAL b)
      message(FATAL_ERROR "${name} ${key} differs:\n  1 process:   ${a}\n  2 processes: ${b}")
    endif()
  endforeach()
endforeach()
message(STATUS "all bounds identical with 1 and 2 processes")

# The two ranks built one component each (their reduced blocks exchanged).
file(READ "${base}/np2/${OUTPUT}/report.txt" report)
string(FIND "${report}" "built on 2 MPI ranks" spread)
if(spread EQUAL -1)
  message(FATAL_ERROR "the 2-process run did not spread the components' "
                      "builds over the ranks (report.txt)")
endif()

# Runs a step program once alone and once behind MPI_LAUNCHER (e.g.
# mpiexec -n 2), through run_program.cmake, and checks that every bound in
# results.json agrees to round-off in both runs (STUDY_TESTS: the study
# test binary, which compares them), that every method made as
# many evaluations in both, and that the second run spread the components'
# builds over its ranks; RANK_ASSEMBLED and
# RANK_FACTORISED (e.g. "P1|P2") name the components each rank must have
# assembled and factorised, and no others.
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
# The bounds agree to 1e-6 of each output's range (study.cc's MpiRuns.BoundsAgreeToRoundOff):
# each evaluation's contact solve starts from its nearest neighbour's state,
# and the ranks do not see the same neighbours.
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env
    "FUZZYCONTACT_RESULTS_NP1=${base}/np1/${OUTPUT}/results.json"
    "FUZZYCONTACT_RESULTS_NP2=${base}/np2/${OUTPUT}/results.json"
    ${STUDY_TESTS} --gtest_filter=MpiRuns.BoundsAgreeToRoundOff
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE out)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the bounds with 1 and 2 processes differ:\n${out}")
endif()
string(REGEX MATCH "largest difference [^\n]*" agreement "${out}")
message(STATUS "bounds with 1 and 2 processes: ${agreement}")

# One evaluation cache shared by the ranks: each method evaluates as many
# distinct points with 2 processes as with one (ranks that repeated each
# other's work would evaluate about twice as many). The optimisation's
# path follows round-off differences: where a bound lies at a kink (above),
# and because each rank's contact solvers keep their factors from solve to
# solve (an answer then depends, by round-off, on the solves before it:
# GMRES on kept factors to 1e-13), so that ROL's finite-difference
# gradients differ in their last digits (FL2C on prm/column.prm: 750
# evaluations with one process, 571 with two, the bounds identical). Its
# count may differ by up to a third.
string(JSON methods LENGTH "${one}" evaluations)
math(EXPR last "${methods} - 1")
foreach(m RANGE ${last})
  string(JSON method MEMBER "${one}" evaluations ${m})
  string(JSON a GET "${one}" evaluations ${method})
  string(JSON b GET "${two}" evaluations ${method})
  set(allowed 0)
  if(method STREQUAL "optimisation")
    math(EXPR allowed "${a} / 3")
  endif()
  math(EXPR difference "${a} - ${b}")
  if(difference LESS 0)
    math(EXPR difference "0 - ${difference}")
  endif()
  if(difference GREATER allowed)
    message(FATAL_ERROR "${method}: ${a} evaluations with 1 process, ${b} with 2")
  endif()
endforeach()
message(STATUS "as many evaluations with 1 and 2 processes")

# Each rank assembled (RANK_ASSEMBLED) and factorised (RANK_FACTORISED)
# the components named for it only (component c on rank c mod 2), through
# the proofs and the Extension Principle too.
foreach(what assembled factorised)
  string(TOUPPER "RANK_${what}" variable)
  if(NOT DEFINED ${variable})
    continue()
  endif()
  string(REPLACE "|" ";" expected "${${variable}}")
  foreach(rank 0 1)
    list(GET expected ${rank} names)
    string(JSON list GET "${two}" ranks ${rank} ${what})
    string(REGEX REPLACE "[][\" \n]" "" list "${list}")
    if(NOT list STREQUAL names)
      message(FATAL_ERROR "rank ${rank} ${what} ${list}, expected ${names}")
    endif()
  endforeach()
  message(STATUS "each rank ${what} the components named for it: ${${variable}}")
endforeach()

# The two ranks built their own components (their reduced blocks
# exchanged).
file(READ "${base}/np2/${OUTPUT}/report.txt" report)
string(FIND "${report}" "built on 2 MPI ranks" spread)
if(spread EQUAL -1)
  message(FATAL_ERROR "the 2-process run did not spread the components' "
                      "builds over the ranks (report.txt)")
endif()

# Checks the spot checks of a step-4 run asked for 12 (included by
# run_program.cmake with RESULTS_JSON set): 12 of the optimisation's
# points solved by the full-order model too, every output within the
# proofs' tolerance of its range there.
string(JSON checked GET "${RESULTS_JSON}" spot_checks checked)
string(JSON within GET "${RESULTS_JSON}" spot_checks all_within_tolerance)
string(JSON n_outputs LENGTH "${RESULTS_JSON}" spot_checks outputs)
if(NOT checked EQUAL 12 OR NOT within OR n_outputs LESS 1)
  message(FATAL_ERROR "spot checks: ${checked} checked, ${n_outputs} outputs, all within the tolerance: ${within}")
endif()
message(STATUS "spot checks: ${checked} points, every output within the tolerance")

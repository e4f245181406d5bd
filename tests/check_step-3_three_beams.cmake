# Checks step-3's results.json on the three-beams scene (two contact pairs,
# each with the scene's own friction coefficient: lower 0, upper 0.5): the
# per-pair outputs chosen in the .prm are reported for every solver, the
# exact reduced solver agrees with the full-order one to 1e-7 on each, and
# the frictionless pair carries no tangential force.
string(JSON n_cases LENGTH "${RESULTS_JSON}" cases)
if(NOT n_cases EQUAL 1)
  message(FATAL_ERROR "expected 1 case, got ${n_cases}")
endif()
string(JSON mu_lower GET "${RESULTS_JSON}" cases 0 mu lower)
string(JSON mu_upper GET "${RESULTS_JSON}" cases 0 mu upper)
if(NOT mu_lower EQUAL 0 OR NOT mu_upper EQUAL 0.5)
  message(FATAL_ERROR "friction coefficients ${mu_lower}, ${mu_upper}: not the scene's own")
endif()
foreach(key lower.Fn lower.Ft upper.Fn upper.Ft upper.max_pressure upper.contact_length "P3.node(0.1, 0.016).uy")
  string(JSON error GET "${RESULTS_JSON}" cases 0 solvers 1 output_errors "${key}")
  if(error GREATER 1e-7)
    message(FATAL_ERROR "reduced_exact: ${key} is ${error} from full_order")
  endif()
  string(JSON value GET "${RESULTS_JSON}" cases 0 solvers 0 outputs "${key}")
  message(STATUS "full_order ${key} = ${value}; reduced_exact error ${error}")
endforeach()
string(JSON Ft_lower GET "${RESULTS_JSON}" cases 0 solvers 0 outputs lower.Ft)
string(JSON Ft_upper GET "${RESULTS_JSON}" cases 0 solvers 0 outputs upper.Ft)
if(NOT Ft_lower EQUAL 0 OR Ft_upper EQUAL 0)
  message(FATAL_ERROR "lower.Ft = ${Ft_lower} (mu = 0), upper.Ft = ${Ft_upper} (mu = 0.5)")
endif()

# Checks step-4's results.json on the three-beams scene (two contact pairs:
# lower frictionless, upper mu = 0.5; fuzzy modulus of P1 and fuzzy load on
# P3): every output within 0.5 % of the Extension Principle, whose exact
# full-order solves keep each pair's own friction coefficient -- the lower
# pair carries no tangential force at any level, the upper one does.
set(expected lower.Fn lower.Ft upper.Fn upper.Ft upper.max_pressure "P3.node(0.1, 0.016).uy")
set(tolerances 0.005 0.005 0.005 0.005 0.005 0.005)
include(${CMAKE_CURRENT_LIST_DIR}/check_outputs.cmake)
check_outputs("${expected}" "${tolerances}")
string(JSON n_levels LENGTH "${RESULTS_JSON}" outputs 1 alpha)
math(EXPR last_level "${n_levels} - 1")
foreach(side reference_lower reference_upper lower upper)
  foreach(l RANGE ${last_level})
    string(JSON Ft_lower GET "${RESULTS_JSON}" outputs 1 ${side} ${l})
    string(JSON Ft_upper GET "${RESULTS_JSON}" outputs 3 ${side} ${l})
    if(NOT Ft_lower EQUAL 0)
      message(FATAL_ERROR "lower.Ft ${side} ${l} = ${Ft_lower}: the frictionless pair carries a friction force")
    endif()
    if(Ft_upper EQUAL 0)
      message(FATAL_ERROR "upper.Ft ${side} ${l} = 0: no friction force on the pair with mu = 0.5")
    endif()
  endforeach()
  message(STATUS "${side} at alpha 0: lower.Ft 0, upper.Ft ${Ft_upper}")
endforeach()

# Checks step-4's results.json under gravity (prm/column.prm: a column on a
# footing under their own weights; fuzzy column density, moduli of both):
# every output within 1e-7 of the Extension Principle (exact full-order
# solves reusing the nominal factorisations: a density changes no
# stiffness), and the contact force's support moved by the column's density
# (it is not inert with gravity): rho g W H t at 7700 and 8100 kg/m^3, to
# 1e-9.
set(expected Fn "Column.node(0.05, 1.2).uy" "Footing.node(0.05, 0.2).uy")
set(tolerances 1e-7 1e-7 1e-7)
include(${CMAKE_CURRENT_LIST_DIR}/check_outputs.cmake)
check_outputs("${expected}" "${tolerances}")
check_support_is_interval(0)
# 7700 * 9.81 * 0.1 * 1 and 8100 * 9.81 * 0.1 * 1 [N], +- 1e-9 relative
foreach(bound "lower;7553.6999924463;7553.7000075537"
              "upper;7946.0999920539;7946.1000079461")
  list(GET bound 0 side)
  list(GET bound 1 from)
  list(GET bound 2 to)
  string(JSON value GET "${RESULTS_JSON}" outputs 0 ${side} 0)
  if(value LESS from OR value GREATER to)
    message(FATAL_ERROR "Fn ${side} at alpha 0 is ${value}, expected rho g W H t in [${from}, ${to}]")
  endif()
  message(STATUS "Fn ${side} at alpha 0: ${value} (rho g W H t)")
endforeach()

# Checks step-4's results.json where sliding is possible (prm/step-4-slope.prm
# with 5 alpha levels: a block on a 20-degree slope held by friction alone,
# mu triangular (0.3, 0.4, 0.5), the force (5, 10, 20 kN)). Statics: no
# static equilibrium for mu < tan 20 = 0.36397023, so the fuzzy output
# "sliding possible" has the membership (tan 20 - 0.3) / 0.1 = 0.63970234
# (to 1e-6) and starts at mu = tan 20 (to 1e-7); it is possible at alpha 0,
# 0.25 and 0.5 only, where every method left points out. Over the part of
# the box with an equilibrium F_n = F cos 20 deg: the optimisation's bounds
# are the force's cut times cos 20 to 1e-8 of 20 kN, shown converged.
string(JSON checked GET "${RESULTS_JSON}" static_equilibrium checked)
if(NOT checked)
  message(FATAL_ERROR "the static equilibrium was not checked")
endif()
string(JSON membership GET "${RESULTS_JSON}" static_equilibrium sliding_possible membership)
if(membership LESS 0.6397013 OR membership GREATER 0.6397033)
  message(FATAL_ERROR "sliding possible: membership ${membership}, expected (tan 20 - 0.3) / 0.1 = 0.6397023")
endif()
string(JSON mu GET "${RESULTS_JSON}" static_equilibrium sliding_possible starts_at block-on-slope.mu)
if(mu LESS 0.3639701 OR mu GREATER 0.3639703)
  message(FATAL_ERROR "sliding starts at mu = ${mu}, expected tan 20 = 0.36397023")
endif()
message(STATUS "sliding possible below alpha = ${membership}, from mu = ${mu}")

# Per level: its index; the ranges of Fn's lower and upper bounds; whether
# sliding is possible.
set(levels
  "0|4698.462904|4698.463304|18793.852216|18793.852616|1"
  "1|5873.078680|5873.079080|16444.620664|16444.621064|1"
  "2|7047.694456|7047.694856|14095.389112|14095.389512|1"
  "3|8222.310232|8222.310632|11746.157560|11746.157960|0"
  "4|9396.926008|9396.926408|9396.926008|9396.926408|0")
foreach(fields ${levels})
  string(REPLACE "|" ";" level "${fields}")
  list(GET level 0 l)
  list(GET level 1 lo_from)
  list(GET level 2 lo_to)
  list(GET level 3 hi_from)
  list(GET level 4 hi_to)
  list(GET level 5 sliding)
  string(JSON possible GET "${RESULTS_JSON}" static_equilibrium levels ${l} sliding_possible)
  string(JSON left_out GET "${RESULTS_JSON}" static_equilibrium excluded optimisation n_without_equilibrium ${l})
  if(sliding)
    if(NOT possible OR left_out EQUAL 0)
      message(FATAL_ERROR "level ${l}: sliding should be possible and points left out (${possible}, ${left_out})")
    endif()
  elseif(possible OR NOT left_out EQUAL 0)
    message(FATAL_ERROR "level ${l}: sliding should not be possible (${possible}, ${left_out} left out)")
  endif()
  string(JSON lower GET "${RESULTS_JSON}" outputs 0 lower ${l})
  string(JSON upper GET "${RESULTS_JSON}" outputs 0 upper ${l})
  if(lower LESS lo_from OR lower GREATER lo_to OR upper LESS hi_from OR upper GREATER hi_to)
    message(FATAL_ERROR "level ${l}: Fn in [${lower}, ${upper}], expected [${lo_from}..${lo_to}, ${hi_from}..${hi_to}] (F cos 20)")
  endif()
endforeach()
string(JSON converged GET "${RESULTS_JSON}" outputs 0 converged)
if(NOT converged)
  message(FATAL_ERROR "Fn: a bound is not shown converged")
endif()
message(STATUS "Fn = F cos 20 over the part of every box with an equilibrium")

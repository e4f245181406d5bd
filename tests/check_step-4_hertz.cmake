# Checks step-4's results.json on the Hertz scene (Gmsh meshes, a curved
# contact, a prescribed displacement; fuzzy block modulus, displacement and
# friction): the contact force, the contact length and the block's
# indentation within 1e-6 of the Extension Principle (exact full-order
# solves); the largest pressure, a maximum over nodes whose pressures
# alternate (doc/validation.md), within 1e-2.
set(expected Fn roller-on-block.max_pressure roller-on-block.contact_length "Block.node(0, 0).uy")
set(tolerances 1e-6 1e-2 1e-6 1e-6)
string(JSON n_outputs LENGTH "${RESULTS_JSON}" outputs)
list(LENGTH expected n_expected)
if(NOT n_outputs EQUAL n_expected)
  message(FATAL_ERROR "expected ${n_expected} outputs, got ${n_outputs}")
endif()
math(EXPR last "${n_outputs} - 1")
foreach(k RANGE ${last})
  list(GET expected ${k} wanted)
  list(GET tolerances ${k} tolerance)
  string(JSON name GET "${RESULTS_JSON}" outputs ${k} name)
  if(NOT name STREQUAL wanted)
    message(FATAL_ERROR "output ${k} is <${name}>, expected <${wanted}>")
  endif()
  string(JSON error GET "${RESULTS_JSON}" outputs ${k} max_rel_error)
  if(NOT error LESS ${tolerance})
    message(FATAL_ERROR "${name}: ${error} from the Extension Principle (tolerance ${tolerance})")
  endif()
  message(STATUS "${name}: largest relative difference ${error}")
endforeach()
# The contact force's support at alpha = 0 is a proper interval.
string(JSON Fn_lower GET "${RESULTS_JSON}" outputs 0 lower 0)
string(JSON Fn_upper GET "${RESULTS_JSON}" outputs 0 upper 0)
if(NOT Fn_upper GREATER Fn_lower)
  message(FATAL_ERROR "Fn support [${Fn_lower}, ${Fn_upper}] is not an interval")
endif()
message(STATUS "Fn at alpha 0: [${Fn_lower}, ${Fn_upper}]")

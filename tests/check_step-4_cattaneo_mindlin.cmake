# Checks step-4's results.json on a load history (prm/cattaneo-mindlin.prm:
# the roller pressed, then moved sideways; fuzzy sideways displacement and
# friction): the normal and tangential forces and the block's indentation
# within 1e-6 of the Extension Principle (exact full-order solves, stage by
# stage), the largest pressure (a maximum over nodes whose pressures
# alternate, doc/validation.md) within 1e-2.
set(expected Fn Ft roller-on-block.max_pressure "Block.node(0, 0).uy")
set(tolerances 1e-6 1e-6 1e-2 1e-6)
include(${CMAKE_CURRENT_LIST_DIR}/check_outputs.cmake)
check_outputs("${expected}" "${tolerances}")
# The tangential force's support at alpha = 0 is a proper interval: the
# sideways displacement and the friction coefficient move it.
check_support_is_interval(1)

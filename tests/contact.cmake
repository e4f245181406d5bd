## Tests of the contact part (issue 4): one GoogleTest binary and the
## program runs of step-3 (a good run with acceptance checks on
## results.json, and bad input that must fail with a message and write
## nothing). The step-3 runs use the 1510-DoF meshes (mesh refinements = 0).

fuzzycontact_gtest(contact)

set(step3_coarse "-DEDIT2_FILE=step"
  "-DEDIT2_FROM=set mesh refinements        = 2"
  "-DEDIT2_TO=set mesh refinements        = 0")

fuzzycontact_program_test(step-3.default_run step-3 overlap
  -DEXPECT=success
  -DEXTRA_FILES=${CMAKE_SOURCE_DIR}/prm/stacked.prm
  ${step3_coarse}
  -DJSON_CHECKS=${CMAKE_CURRENT_SOURCE_DIR}/check_step-3.cmake)

# A load of zero is no error: zero contact force, not NaN.
fuzzycontact_program_test(step-3.zero_load step-3 overlap
  -DEXPECT=success
  -DEXTRA_FILES=${CMAKE_SOURCE_DIR}/prm/stacked.prm
  ${step3_coarse}
  -DEDIT_FILE=step
  "-DEDIT_FROM=set load                    = 50000"
  "-DEDIT_TO=set load = 0"
  -DJSON_CHECKS=${CMAKE_CURRENT_SOURCE_DIR}/check_step-3_zero_load.cmake)

# Two contact pairs with the scene's own friction (lower: 0, upper: 0.5)
# and per-pair outputs chosen in the .prm. The case line gives each force
# (the scene's two, scaled to the step file's load = 50000 N) and their
# resultant, which must be that load, downwards.
fuzzycontact_program_test(step-3.three_beams step-3 three-beams
  -DEXPECT=success
  ${step3_coarse}
  -DEDIT_FILE=step
  "-DEDIT_FROM=set scenes                  = overlap.prm, stacked.prm"
  "-DEDIT_TO=set scenes = three-beams.prm"
  -DEDIT3_FILE=step
  "-DEDIT3_FROM=set paper scene             = overlap.prm"
  "-DEDIT3_TO=set paper scene ="
  -DEDIT4_FILE=step
  "-DEDIT4_FROM=set friction coefficients   = 0, 0.3"
  "-DEDIT4_TO=set friction coefficients = scene"
  -DEDIT5_FILE=step
  "-DEDIT5_FROM=set outputs                 = slave.ux, slave.uy, master1.ux, master1.uy, master2.ux, master2.uy, Fn, Ft"
  "-DEDIT5_TO=set outputs = lower.Fn, lower.Ft, upper.Fn, upper.Ft, upper.max_pressure, upper.contact_length, P3.node(0.1, 0.016).uy"
  "-DMESSAGE=Case three-beams \\(plane stress\\), P1.tip 35714.3 N along \\(0, -1\\), P3.press 14285.7 N along \\(0, -1\\). resultant force \\(0, -50000\\) N, mu = lower 0, upper 0.5"
  -DJSON_CHECKS=${CMAKE_CURRENT_SOURCE_DIR}/check_step-3_three_beams.cmake)

# Each case edits one line of prm/step-3.prm (step) or prm/overlap.prm
# (scene).
set(step3_bad_inputs
  "faces_cannot_touch|scene|set master face          = top|set master face = bottom|Contact interface: the slave face \\(P1 bottom\\) and the master face \\(P2 bottom\\) cannot touch"
  "faces_apart|scene|set lower left corner  = 0.1, -0.008|set lower left corner  = 0.25, -0.008|Contact interface: no node of the slave face \\(P1 bottom\\) lies opposite the master face \\(P2 top\\)"
  "negative_friction_in_step|step|set friction coefficients   = 0, 0.3|set friction coefficients = 0, -0.3|friction coefficients: each value must not be negative, got -0.3"
  "negative_friction_in_scene|scene|set friction coefficient = 0.3|set friction coefficient = -0.3|Contact interface: friction coefficient must not be negative"
  "sliding_angle_limit_out_of_range|step|set penetration tolerance   = 1e-8|set sliding angle limit = 90|sliding angle limit must lie between 0 and 90 degrees, got 90"
  "initial_penetration|scene|set initial gap          = auto|set initial gap = -1e-3|Contact interface: initial penetration of 0.001 m at the slave node"
  "transition_points_out_of_order|step|set gap points      = 1e-3, 5e-3, 1e-2|set gap points = 5e-3, 1e-3, 1e-2|FL2C: gap points / force points: the input transition points must satisfy 0 < p1 < p2 < p3, got 0.005, 0.001, 0.01"
  "malformed_friction_list|step|set friction coefficients   = 0, 0.3|set friction coefficients = 0, x|friction coefficients: <x> is not a number"
  "unknown_output|step|set outputs                 = slave.ux|set outputs = slave.uz|outputs: <slave.uz>: not an output"
  "output_of_no_component|step|set outputs                 = slave.ux|set outputs = P5.node(0, 0).ux|outputs: <P5.node.0, 0..ux>: the scene has no component <P5> .its components: P1, P2.")
fuzzycontact_bad_input_tests(step-3 overlap "${step3_bad_inputs}"
  -DEXTRA_FILES=${CMAKE_SOURCE_DIR}/prm/stacked.prm)

# FL2C with the paper's transition points and without its coarse correction
# (the paper's regulators alone) oscillates on this scene: its row must say
# so, and the run go on (the other solvers' rows, results.json; exit 0).
fuzzycontact_program_test(step-3.diagnostic_solver_fails
  step-3 overlap
  -DEXPECT=success
  -DEXTRA_FILES=${CMAKE_SOURCE_DIR}/prm/stacked.prm
  ${step3_coarse}
  -DEDIT_FILE=step
  "-DEDIT_FROM=set calibration     = automatic"
  "-DEDIT_TO=set calibration = prm"
  -DEDIT2_FILE=step
  "-DEDIT2_FROM=set coarse correction = active set"
  "-DEDIT2_TO=set coarse correction = none"
  "-DMESSAGE= fl2c_modes +failed: fl2c_modes: the fuzzy regulators did not converge in 20000 iterations \\(key 'FL2C/max iterations'; load step 1\\); complementarity residual.*\n reduced_exact_modes +[-0-9]")

# A body held by contact alone (prm/step-3-slope.prm: a block on a slope):
# every solver carries statics' N = F cos 20 and T = F sin 20, and the
# report gives the block's rigid-body motion. With too little friction the
# block slides: no static equilibrium, refused before anything is written.
fuzzycontact_program_test(step-3.slope step-3 slope
  -DEXPECT=success
  -DPRM=${CMAKE_SOURCE_DIR}/prm/step-3-slope.prm
  -DOUTPUT=step-3-slope-output
  -DEXTRA_FILES=${CMAKE_SOURCE_DIR}/prm/meshes
  "-DMESSAGE= full_order +9.39693e\\+03 +3.42020e\\+03.*\n reduced_exact +9.39693e\\+03 +3.42020e\\+03.*\n fl2c_corrected +9.39693e\\+03 +3.42020e\\+03.* held by contact alone.* Block: rotation about")
fuzzycontact_program_test(step-3.bad_input.block_slides step-3 slope
  -DEXPECT=failure
  -DPRM=${CMAKE_SOURCE_DIR}/prm/step-3-slope.prm
  -DOUTPUT=step-3-slope-output
  -DEXTRA_FILES=${CMAKE_SOURCE_DIR}/prm/meshes
  -DEDIT_FILE=scene
  "-DEDIT_FROM=set friction coefficient = 0.5"
  "-DEDIT_TO=set friction coefficient = 0.3"
  "-DMESSAGE=step-3-slope.prm: full-order contact solver: no static equilibrium \\(load step 1\\): the bodies held by contact alone cannot be held.*Block: translation along \\(1, 0\\).*the body slides: it needs friction coefficients 1.213.* times the present ones \\(the largest, 0.3, would be 0.36397")

# The block on the slope under its own weight (prm/slope-weight.prm,
# through prm/step-3-slope.prm): every solver carries statics' N = W cos 20
# = 364.126 N and T = W sin 20 = 132.531 N (W = rho g A t), and the case
# line says the loading is gravity. A force cannot scale a weight: 'load =
# <force>' is refused on a scene with gravity.
set(step3_slope_weight
  -DPRM=${CMAKE_SOURCE_DIR}/prm/step-3-slope.prm
  -DOUTPUT=step-3-slope-output
  -DEXTRA_FILES=${CMAKE_SOURCE_DIR}/prm/meshes
  -DEDIT_FILE=step
  "-DEDIT_FROM=set scenes                  = slope.prm"
  "-DEDIT_TO=set scenes = slope-weight.prm")
fuzzycontact_program_test(step-3.slope_weight step-3 slope-weight
  -DEXPECT=success
  ${step3_slope_weight}
  "-DMESSAGE=gravity \\(0, -9.81\\) m/s\\^2.*\n full_order +3.64126e\\+02 +1.32531e\\+02.*\n reduced_exact +3.64126e\\+02 +1.32531e\\+02.*\n fl2c_corrected +3.64126e\\+02 +1.32531e\\+02")
fuzzycontact_program_test(step-3.bad_input.force_scales_weight step-3 slope-weight
  -DEXPECT=failure
  ${step3_slope_weight}
  -DEDIT2_FILE=step
  "-DEDIT2_FROM=set load                    = scene"
  "-DEDIT2_TO=set load = 50000"
  "-DMESSAGE=load = 50000.*: scene slope-weight has gravity \\(the weight of every component\\), which a force cannot scale; set load = scene")
fuzzycontact_program_test(step-3.bad_input.gravity_out_of_range step-3 slope-weight
  -DEXPECT=failure
  ${step3_slope_weight}
  -DEDIT2_FILE=scene
  "-DEDIT2_FROM=set gravity       = 0, -9.81"
  "-DEDIT2_TO=set gravity = 0, -9.81e5"
  "-DMESSAGE=Scene file <[^>]*slope-weight.prm>: Scene: gravity \\(its magnitude\\) must lie between 0 and 10000")

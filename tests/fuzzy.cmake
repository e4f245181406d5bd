## Tests of the fuzzy study: the machinery (fuzzy numbers, fuzzy parameters,
## interval methods, the fuzzy contact model) and step-4 runs. Included from
## tests/CMakeLists.txt.
fuzzycontact_gtest(fuzzy)

# A quick step-4: coarse meshes (1510 DoFs per component), 3 alpha levels,
# 3 Extension Principle points per parameter and level.
set(step4_quick
  "-DEDIT_FILE=step"
  "-DEDIT_FROM=set mesh refinements       = 2"
  "-DEDIT_TO=set mesh refinements       = 0"
  "-DEDIT2_FILE=step"
  "-DEDIT2_FROM=set number of alpha levels = 11"
  "-DEDIT2_TO=set number of alpha levels = 3"
  "-DEDIT3_FILE=step"
  "-DEDIT3_FROM=set points per dimension = 4"
  "-DEDIT3_TO=set points per dimension = 3")

# With 20 spot checks (the line 'accept unproven = false' replaced: it is
# the default): the reduced model within the proofs' tolerance of the
# exact one at 20 of the optimisation's points.
set(step4_spot_checks
  "-DEDIT7_FILE=step"
  "-DEDIT7_FROM=set accept unproven   = false"
  "-DEDIT7_TO=set spot checks       = 20")
fuzzycontact_program_test(step-4.quick_run step-4 overlap
  ${step4_quick} ${step4_spot_checks}
  -DEXPECT=success
  -DJSON_CHECKS=${CMAKE_CURRENT_SOURCE_DIR}/check_step-4.cmake)

# The proofs feed back: a deliberately poor model (modes only, three of
# them) is made richer by the exact solutions at the unproven bounds'
# arguments until every bound is proven (exit 0); with no rounds allowed
# the run writes its results, warns per unproven bound, flags them in
# results.json and exits with status 3; its spot checks find the poor
# model beyond the tolerance away from the bounds too.
set(step4_poor_model
  "-DEDIT4_FILE=step"
  "-DEDIT4_FROM=set static correction = true"
  "-DEDIT4_TO=set static correction = false"
  "-DEDIT5_FILE=step"
  "-DEDIT5_FROM=set number of modes  = 9"
  "-DEDIT5_TO=set number of modes  = 3")
fuzzycontact_program_test(step-4.proofs_correct_a_poor_model step-4 overlap
  ${step4_quick} ${step4_poor_model}
  -DEXPECT=success
  -DJSON_CHECKS=${CMAKE_CURRENT_SOURCE_DIR}/check_step-4_corrected.cmake)
fuzzycontact_program_test(step-4.unproven_bounds_exit_status step-4 overlap
  ${step4_quick} ${step4_poor_model} ${step4_spot_checks}
  "-DEDIT6_FILE=step"
  "-DEDIT6_FROM=set max rounds        = 3"
  "-DEDIT6_TO=set max rounds        = 0"
  -DEXPECT=success
  -DEXPECT_STATUS=3
  "-DMESSAGE=bound\\(s\\) not proven within 0.0001"
  -DJSON_CHECKS=${CMAKE_CURRENT_SOURCE_DIR}/check_step-4_unproven.cmake)

# step4_study_test(<name> <study prm> <scene prm> <output folder> <check
# script> [run_program.cmake arguments...]): step-4 on prm/<study prm> in a
# folder of its own, with the edits and extra files given, and its
# results.json checked by tests/<check script>.
function(step4_study_test name study scene output checks)
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND}
      -DPROGRAM=$<TARGET_FILE:step-4>
      -DPRM=${CMAKE_SOURCE_DIR}/prm/${study}
      -DSCENE=${CMAKE_SOURCE_DIR}/prm/${scene}
      -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/work/${name}
      -DOUTPUT=${output}
      ${ARGN}
      -DEXPECT=success
      -DJSON_CHECKS=${CMAKE_CURRENT_SOURCE_DIR}/${checks}
      -P ${CMAKE_CURRENT_SOURCE_DIR}/run_program.cmake)
endfunction()

# Two contact pairs of different friction, a fuzzy modulus and a fuzzy load
# on the upper beam (beside the middle beam's load), per-pair outputs: the
# exact reference keeps each pair's friction coefficient.
step4_study_test(step-4.three_beams step-4-three-beams.prm three-beams.prm
  step-4-three-beams-output check_step-4_three_beams.cmake
  "-DEDIT_FILE=step"
  "-DEDIT_FROM=set mesh refinements       = 2"
  "-DEDIT_TO=set mesh refinements       = 0"
  "-DEDIT2_FILE=step"
  "-DEDIT2_FROM=set number of alpha levels = 6"
  "-DEDIT2_TO=set number of alpha levels = 3"
  "-DEDIT3_FILE=step"
  "-DEDIT3_FROM=set points per dimension = 4"
  "-DEDIT3_TO=set points per dimension = 3")

# step-4 on the user's own meshes: prm/step-4-hertz.prm (Gmsh geometries,
# curved contact, prescribed displacement), 6 alpha levels (the largest
# pressure's upper bound at alpha = 0.8 lies on a kink the search must
# find), 3 points per parameter in the Extension Principle.
step4_study_test(step-4.hertz step-4-hertz.prm hertz.prm
  step-4-hertz-output check_step-4_hertz.cmake
  -DEXTRA_FILES=${CMAKE_SOURCE_DIR}/prm/meshes
  "-DEDIT_FILE=step"
  "-DEDIT_FROM=set number of alpha levels = 11"
  "-DEDIT_TO=set number of alpha levels = 6"
  "-DEDIT2_FILE=step"
  "-DEDIT2_FROM=set points per dimension = 4"
  "-DEDIT2_TO=set points per dimension = 3")

# step-4 on a load history: prm/step-4-cattaneo-mindlin.prm (two stages,
# partial slip; every model solves stage by stage), 3 alpha levels, 3
# points per parameter in the Extension Principle.
step4_study_test(step-4.load_stages step-4-cattaneo-mindlin.prm cattaneo-mindlin.prm
  step-4-cattaneo-mindlin-output check_step-4_cattaneo_mindlin.cmake
  -DEXTRA_FILES=${CMAKE_SOURCE_DIR}/prm/meshes
  "-DEDIT_FILE=step"
  "-DEDIT_FROM=set number of alpha levels = 11"
  "-DEDIT_TO=set number of alpha levels = 3"
  "-DEDIT2_FILE=step"
  "-DEDIT2_FROM=set points per dimension = 4"
  "-DEDIT2_TO=set points per dimension = 3")

# Kinked responses (prm/step-4-kinked.prm on coarse meshes): friction that
# reverses inside the range of the load and a gap that opens the contact,
# against a dense Extension Principle (20 points per parameter, 6 levels,
# reused factorisations: exact for a body's modulus, loads and gaps).
step4_study_test(step-4.kinked step-4-kinked.prm kinked.prm
  step-4-kinked-output check_step-4_kinked.cmake
  "-DEDIT_FILE=step"
  "-DEDIT_FROM=set mesh refinements       = 2"
  "-DEDIT_TO=set mesh refinements       = 0"
  "-DEDIT2_FILE=step"
  "-DEDIT2_FROM=set points per dimension = 4"
  "-DEDIT2_TO=set points per dimension = 20"
  "-DEDIT3_FILE=step"
  "-DEDIT3_FROM=set reuse factorisations = false"
  "-DEDIT3_TO=set reuse factorisations = true"
  "-DEDIT4_FILE=step"
  "-DEDIT4_FROM=set number of alpha levels = 11"
  "-DEDIT4_TO=set number of alpha levels = 6")

# step-4 on two MPI ranks against one process (compare_mpi_runs.cmake):
# the same results to round-off. Arguments: the test's
# name, the step file and the scene under prm/, the output folder, then
# further -D arguments: edits of the files, extra files, and which
# components each rank assembles and factorises (RANK_ASSEMBLED,
# RANK_FACTORISED: "<rank 0>|<rank 1>").
function(step4_mpi_test name prm scene output)
  add_test(NAME ${name}
    COMMAND ${CMAKE_COMMAND}
      -DPROGRAM=$<TARGET_FILE:step-4>
      -DPRM=${CMAKE_SOURCE_DIR}/prm/${prm}
      -DSCENE=${CMAKE_SOURCE_DIR}/prm/${scene}
      -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/work/${name}
      -DSTUDY_TESTS=$<TARGET_FILE:study>
      -DOUTPUT=${output}
      ${ARGN}
      "-DMPI_LAUNCHER=${DEAL_II_MPIEXEC}|${DEAL_II_MPIEXEC_NUMPROC_FLAG}|2"
      -P ${CMAKE_CURRENT_SOURCE_DIR}/compare_mpi_runs.cmake)
  set_tests_properties(${name} PROPERTIES
    ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"
    PROCESSORS 2)
endfunction()

# Two MPI processes give the same bounds as one.
step4_mpi_test(step-4.mpi_np2_same_as_np1 step-4.prm overlap.prm step-4-output
  ${step4_quick}
  "-DRANK_ASSEMBLED=P1|P2"
  "-DRANK_FACTORISED=P1|P2")

# The same on the zone study: the re-analysed component P1 is built on the
# first rank, which alone solves the reduced model; P2 on the second, which
# assembles and factorises P1 too for its share of the proofs (each at new
# zone moduli of P1), but the first never touches P2. With 12 spot checks:
# the first rank's evaluations gathered, the exact solves dealt to both.
step4_mpi_test(step-4.zones_mpi_np2_same_as_np1 step-4-zones.prm overlap-zones.prm step-4-zones-output
  ${step4_quick}
  "-DEDIT7_FILE=step"
  "-DEDIT7_FROM=set accept unproven   = false"
  "-DEDIT7_TO=set spot checks       = 12"
  -DJSON_CHECKS=${CMAKE_CURRENT_SOURCE_DIR}/check_spot_checks.cmake
  "-DRANK_ASSEMBLED=P1|P1,P2"
  "-DRANK_FACTORISED=P1|P1,P2")

# A prescribed displacement (the roller of prm/hertz.prm, curved meshes):
# its loads come from the stiffness, and the rank that does not build the
# roller receives them instead of assembling it.
step4_mpi_test(step-4.hertz_mpi_np2_same_as_np1 step-4-hertz.prm hertz.prm step-4-hertz-output
  -DEXTRA_FILES=${CMAKE_SOURCE_DIR}/prm/meshes
  "-DEDIT_FILE=step"
  "-DEDIT_FROM=set number of alpha levels = 11"
  "-DEDIT_TO=set number of alpha levels = 2"
  "-DEDIT2_FILE=step"
  "-DEDIT2_FROM=set points per dimension = 4"
  "-DEDIT2_TO=set points per dimension = 3"
  "-DRANK_ASSEMBLED=Roller|Block"
  "-DRANK_FACTORISED=Roller|Block")

# Three components on two ranks (components 0 and 2 on rank 0); its
# reference is made of independent analyses, for which every rank assembles
# every component.
step4_mpi_test(step-4.three_beams_mpi_np2_same_as_np1 step-4-three-beams.prm three-beams.prm step-4-three-beams-output
  "-DEDIT_FILE=step"
  "-DEDIT_FROM=set mesh refinements       = 2"
  "-DEDIT_TO=set mesh refinements       = 0"
  "-DEDIT2_FILE=step"
  "-DEDIT2_FROM=set number of alpha levels = 6"
  "-DEDIT2_TO=set number of alpha levels = 3"
  "-DEDIT3_FILE=step"
  "-DEDIT3_FROM=set points per dimension = 4"
  "-DEDIT3_TO=set points per dimension = 3"
  "-DRANK_FACTORISED=P1,P3|P2")

# Bad input: each edits one line of prm/step-4.prm.
set(step4_bad_inputs
  "reversed_interval|step|set values   = 0.95, 1, 1.05|set values = 1.05, 1, 0.95|Fuzzy parameter P1.E: the values must not decrease"
  "empty_interval|step|set values = 10e3, 50e3, 100e3|set values = 50e3, 50e3, 50e3|Fuzzy parameter P1.tip.force: the support .* is empty"
  "no_values|step|set values = 10e3, 50e3, 100e3|set values =|Fuzzy parameter P1.tip.force: a triangular fuzzy number needs 3 values, got 0"
  "nan_value|step|set values = 10e3, 50e3, 100e3|set values = 10e3, nan, 100e3|Fuzzy parameter P1.tip.force: values: <nan> is not a finite number"
  "one_alpha_level|step|set number of alpha levels = 11|set number of alpha levels = 1|number of alpha levels must be an integer from 2 to 101"
  "listed_parameter_without_subsection|step|P1.E, P2.E, P1.tip.force|P1.E, P2.E, P1.tip.force, P2.rho|a mandatory key is not set: <values> in subsection <Fuzzy parameter P2.rho>"
  "unknown_key|step|set vertex method          = true|set vertex methods = true|No entry with name <vertex methods>"
  "negative_modulus_support|step|set values   = 0.95, 1, 1.05|set values = -0.95, 1, 1.05|P1.E must lie between 1000 and 1e\\+13"
  "noisy_sensitivities|step|set finite difference step = 1e-4|set finite difference step = 1e-7|the finite difference step must be well above the response tolerance"
  "unknown_output|step|set outputs                = slave.ux, slave.uy, Fn, Ft|set outputs = slave.ux, P1.sigma|outputs: <P1.sigma>: not an output"
  "output_outside|step|set outputs                = slave.ux, slave.uy, Fn, Ft|set outputs = P2.node(0.05, 0).uy|lies outside component P2"
  "output_of_no_pair|step|set outputs                = slave.ux, slave.uy, Fn, Ft|set outputs = contact.Fn|the scene has no contact pair <contact> .its contact pairs: interface.")
# Two fuzzy parameters that set the same modulus.
fuzzycontact_program_test(step-4.bad_input.overlapping_parameters step-4 overlap
  -DEXPECT=failure
  -DEDIT_FILE=step
  "-DEDIT_FROM=P1.E, P2.E, P1.tip.force"
  "-DEDIT_TO=P1.E, P2.E, P1.body.E, P1.tip.force"
  -DEDIT2_FILE=step
  "-DEDIT2_FROM=subsection Fuzzy parameter P2.E"
  "-DEDIT2_TO=subsection Fuzzy parameter P1.body.E\n  set values = 2e11, 2.1e11, 2.2e11\nend\nsubsection Fuzzy parameter P2.E"
  "-DMESSAGE=fuzzy parameters: <P1.E> and <P1.body.E> set the same value of the scene")
fuzzycontact_program_test(step-4.bad_input.unknown_parameter step-4 overlap
  -DEXPECT=failure
  -DEDIT_FILE=step
  "-DEDIT_FROM=P1.E, P2.E, P1.tip.force"
  "-DEDIT_TO=P1.E, P3.E, P1.tip.force"
  -DEDIT2_FILE=step
  "-DEDIT2_FROM=subsection Fuzzy parameter P2.E"
  "-DEDIT2_TO=subsection Fuzzy parameter P3.E"
  "-DMESSAGE=Scene quantity <P3.E>: the scene has no component <P3>")
fuzzycontact_bad_input_tests(step-4 overlap "${step4_bad_inputs}")

# step-4 under gravity (prm/step-4-column.prm: a column on a footing under
# their own weights; the column's density is fuzzy and scales its weight),
# 3 alpha levels, 3 points per parameter.
set(step4_column_quick
  "-DEDIT_FILE=step"
  "-DEDIT_FROM=set number of alpha levels = 11"
  "-DEDIT_TO=set number of alpha levels = 3"
  "-DEDIT2_FILE=step"
  "-DEDIT2_FROM=set points per dimension = 4"
  "-DEDIT2_TO=set points per dimension = 3")
step4_study_test(step-4.gravity step-4-column.prm column.prm
  step-4-column-output check_step-4_column.cmake ${step4_column_quick})

# The same on two MPI ranks: the bodies' weights travel with their reduced
# blocks (the zone responses), and each rank assembles and factorises its
# own body only.
step4_mpi_test(step-4.gravity_mpi_np2_same_as_np1 step-4-column.prm column.prm step-4-column-output
  ${step4_column_quick}
  "-DRANK_ASSEMBLED=Column|Footing"
  "-DRANK_FACTORISED=Column|Footing")

# Under gravity the weight is no quantity of its own, and a zone's modulus
# cannot vary (the weight's exact response would need new factorisations).
set(step4_column_refused
  -DEXPECT=failure
  -DPRM=${CMAKE_SOURCE_DIR}/prm/step-4-column.prm
  -DOUTPUT=step-4-column-output)
fuzzycontact_program_test(step-4.bad_input.weight_force step-4 column
  ${step4_column_refused}
  -DEDIT_FILE=step
  "-DEDIT_FROM=Column.rho, Footing.E, Column.E"
  "-DEDIT_TO=Column.weight.force, Footing.E, Column.E"
  -DEDIT2_FILE=step
  "-DEDIT2_FROM=subsection Fuzzy parameter Column.rho"
  "-DEDIT2_TO=subsection Fuzzy parameter Column.weight.force"
  "-DMESSAGE=Scene quantity <Column.weight.force>: the weight of component Column is not a quantity of its own: vary Column.rho")
fuzzycontact_program_test(step-4.bad_input.zone_modulus_with_gravity step-4 column
  ${step4_column_refused}
  -DEDIT_FILE=step
  "-DEDIT_FROM=Column.rho, Footing.E, Column.E"
  "-DEDIT_TO=Column.rho, Footing.body.E, Column.E"
  -DEDIT2_FILE=step
  "-DEDIT2_FROM=subsection Fuzzy parameter Footing.E"
  "-DEDIT2_TO=subsection Fuzzy parameter Footing.body.E"
  "-DMESSAGE=Scene quantity <Footing.body.E>: the scene has gravity.*Vary the modulus of the whole body \\(Footing.E\\)")

# Sliding inside the fuzzy range (prm/step-4-slope.prm: a block on a slope
# held by friction alone, mu around statics' critical tan 20 deg), 5 alpha
# levels, 3 points per parameter in the Extension Principle: the study goes
# on where there is no static equilibrium, says from which alpha sliding is
# possible and where it starts, and bounds the outputs over the rest.
step4_study_test(step-4.sliding step-4-slope.prm slope.prm
  step-4-slope-output check_step-4_slope.cmake
  -DEXTRA_FILES=${CMAKE_SOURCE_DIR}/prm/meshes
  "-DEDIT_FILE=step"
  "-DEDIT_FROM=set number of alpha levels = 11"
  "-DEDIT_TO=set number of alpha levels = 5"
  "-DEDIT2_FILE=step"
  "-DEDIT2_FROM=set points per dimension = 4"
  "-DEDIT2_TO=set points per dimension = 3")

## Tests of the modal reanalysis (issue 3): one GoogleTest unit, the default
## run of step-2 with its acceptance checks, and bad input to step-2.
## Included by tests/CMakeLists.txt.

fuzzycontact_gtest(reanalysis)

# The default run, on the unrefined meshes (1530 DoFs) to keep it short.
# step-2's cases use a second scene.
set(step2_extra_files -DEXTRA_FILES=${CMAKE_SOURCE_DIR}/prm/close-modes.prm)

fuzzycontact_program_test(step-2.default_run step-2 cantilever-zones
  ${step2_extra_files}
  -DEXPECT=success
  -DEDIT_FILE=step
  "-DEDIT_FROM=set mesh refinements = 2"
  "-DEDIT_TO=set mesh refinements = 0"
  -DJSON_CHECKS=${CMAKE_CURRENT_SOURCE_DIR}/check_step-2.cmake)

# Each case edits one line of prm/step-2.prm; all are found while the input
# is read, before anything is computed or written.
# (No ';' in these strings: they are CMake lists.)
set(step2_bad_inputs
  "unknown_key|step|set changes in percent = 5, -10, 8|set change in percent = 5, -10, 8|No entry with name <change in percent>"
  "missing_zone|step|set parameters         = beam.root.E|set parameters = beam.middle.E|Case b: Scene quantity <beam.middle.E>: component beam has no zone called <middle> .its zones: root, tip.. A reanalysis parameter of component beam is beam.E, beam.rho, beam.<zone>.E or beam.<zone>.rho"
  "other_component|step|set parameters         = beam.E|set parameters = P1.E|Case a: Scene quantity <P1.E>: the scene has no component <P1> .nor a contact pair of that name. its components: beam.. A reanalysis parameter of component beam is beam.E"
  "non_positive_modulus|step|set changes in percent = 5, -10, 8|set changes in percent = 5, -110, 8|Case c, sample 1: reanalysis parameter beam.tip.E: the change of -110 % makes the Young's modulus of zone tip of component beam non-positive"
  "non_positive_density|step|set changes in percent = 5, -10, 8|set changes in percent = 5, -10, -100|Case c, sample 1: reanalysis parameter beam.tip.rho: the change of -100 % makes the density of zone tip of component beam non-positive"
  "nan_change|step|set changes in percent = 5, -10, 8|set changes in percent = 5, nan, 8|Case c, sample 1 of 'changes in percent': <nan> is not a finite number"
  "wrong_number_of_changes|step|set changes in percent = 5, -10, 8|set changes in percent = 5, -10|Case c, sample 1 of 'changes in percent': 2 changes given for 3 parameters"
  "order_zero|step|set maximum order        = 3|set maximum order = 0|entry value 0 for the entry named maximum order does not match the given pattern"
  "order_four|step|set maximum order        = 3|set maximum order = 4|entry value 4 for the entry named maximum order does not match the given pattern"
  "duplicate_parameter|step|set parameters         = beam.root.E, beam.tip.E, beam.tip.rho|set parameters = beam.root.E, beam.tip.E, beam.root.E|Case c: reanalysis parameters <beam.root.E> and <beam.root.E> change the same property of the same zones"
  "not_a_material|step|set parameters         = beam.E|set parameters = beam.mu|Case a: Scene quantity <beam.mu>: .*A reanalysis parameter of component beam is"
  "cutoff_frequency|step|set cutoff frequency = 0|set cutoff frequency = 20000|step-2 reanalyses a fixed number of modes")
fuzzycontact_bad_input_tests(step-2 cantilever-zones "${step2_bad_inputs}"
  ${step2_extra_files})

# Runs a step program as a user would and checks what happened.
#
#   cmake -DPROGRAM=<exe> -DPRM=<step .prm> -DSCENE=<scene .prm>
#         -DWORKDIR=<folder> -DOUTPUT=<output folder name>
#         [-DEDIT_FILE=step|scene -DEDIT_FROM=<text> -DEDIT_TO=<text>]
#         [-DEDIT2_...] ... [-DEDIT8_...]  (the same, up to eight)
#         [-DEXTRA_FILES=<file>,<file>...]
#         [-DLAUNCHER=<command>|<arg>|...]   (e.g. /usr/bin/mpiexec|-n|2)
#         -DEXPECT=success|failure [-DMESSAGE=<regex>]
#         [-DEXPECT_STATUS=<n>]  (success with this exit status, e.g. 3)
#         [-DJSON_CHECKS=<check script>]
#         -P run_program.cmake
#
# The step file and its scene are copied into WORKDIR (optionally with up
# to eight text replacements, to make a bad input out of a good one or a
# quick run out of a long one), and so are EXTRA_FILES (unedited) for step
# files that name more than one scene; the program runs there, behind
# LAUNCHER if given. For
# EXPECT=failure the program must exit non-zero, print a message matching
# MESSAGE on stderr and leave no output folder (EXPECT=success: MESSAGE, if
# given, must match its standard output; with EXPECT_STATUS, the exit
# status must be that one, and MESSAGE must match stderr instead). For
# EXPECT=success it must exit 0 and write OUTPUT/results.json; JSON_CHECKS
# then names a CMake script that inspects the variable RESULTS_JSON (and may
# look at the other files in WORKDIR/OUTPUT).

file(REMOVE_RECURSE "${WORKDIR}")
file(MAKE_DIRECTORY "${WORKDIR}")
get_filename_component(prm_name "${PRM}" NAME)
get_filename_component(scene_name "${SCENE}" NAME)
file(READ "${PRM}" prm_text)
file(READ "${SCENE}" scene_text)
foreach(edit EDIT EDIT2 EDIT3 EDIT4 EDIT5 EDIT6 EDIT7 EDIT8)
  if(DEFINED ${edit}_FILE)
    if(${edit}_FILE STREQUAL "step")
      set(edited "${prm_text}")
    else()
      set(edited "${scene_text}")
    endif()
    string(FIND "${edited}" "${${edit}_FROM}" position)
    if(position EQUAL -1)
      message(FATAL_ERROR "test setup: <${${edit}_FROM}> not found in the ${${edit}_FILE} file")
    endif()
    string(REPLACE "${${edit}_FROM}" "${${edit}_TO}" edited "${edited}")
    if(${edit}_FILE STREQUAL "step")
      set(prm_text "${edited}")
    else()
      set(scene_text "${edited}")
    endif()
  endif()
endforeach()

file(WRITE "${WORKDIR}/${prm_name}" "${prm_text}")
file(WRITE "${WORKDIR}/${scene_name}" "${scene_text}")
if(DEFINED EXTRA_FILES)
  string(REPLACE "," ";" extra_files "${EXTRA_FILES}")
  foreach(extra ${extra_files})
    file(COPY "${extra}" DESTINATION "${WORKDIR}")
  endforeach()
endif()

string(REPLACE "|" ";" launcher "${LAUNCHER}")
execute_process(COMMAND ${launcher} "${PROGRAM}" "${prm_name}"
  WORKING_DIRECTORY "${WORKDIR}"
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)

if(EXPECT STREQUAL "failure")
  if(status EQUAL 0)
    message(FATAL_ERROR "expected a non-zero exit status, got 0.\n${out}\n${err}")
  endif()
  if(NOT err MATCHES "${MESSAGE}")
    message(FATAL_ERROR "stderr does not match <${MESSAGE}>:\n${err}")
  endif()
  if(EXISTS "${WORKDIR}/${OUTPUT}")
    message(FATAL_ERROR "bad input must not write output, but ${OUTPUT}/ exists")
  endif()
  message(STATUS "refused as expected (status ${status}): ${err}")
else()
  set(expected_status 0)
  if(DEFINED EXPECT_STATUS)
    set(expected_status ${EXPECT_STATUS})
  endif()
  if(NOT status EQUAL expected_status)
    message(FATAL_ERROR "exit status ${status}, expected ${expected_status}\n${out}\n${err}")
  endif()
  if(NOT EXISTS "${WORKDIR}/${OUTPUT}/results.json")
    message(FATAL_ERROR "no ${OUTPUT}/results.json was written")
  endif()
  file(READ "${WORKDIR}/${OUTPUT}/results.json" RESULTS_JSON)
  file(GLOB leftovers "${WORKDIR}/${OUTPUT}/*.tmp-*")
  if(leftovers)
    message(FATAL_ERROR "temporary files left behind: ${leftovers}")
  endif()
  if(DEFINED JSON_CHECKS)
    include("${JSON_CHECKS}")
  endif()
  if(DEFINED EXPECT_STATUS)
    if(DEFINED MESSAGE AND NOT err MATCHES "${MESSAGE}")
      message(FATAL_ERROR "stderr does not match <${MESSAGE}>:\n${err}")
    endif()
  elseif(DEFINED MESSAGE AND NOT out MATCHES "${MESSAGE}")
    message(FATAL_ERROR "stdout does not match <${MESSAGE}>:\n${out}")
  endif()
  message(STATUS "${out}")
endif()

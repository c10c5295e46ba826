# A data folder that cannot be one: XDG_DATA_HOME names a regular file. The game says so when it
# starts (naming the path and why) and when a level is won, still plays (exit 0), and its exit
# summary claims no new best and says the run was not saved.
#   cmake -DGAME=tire-game -DLEVEL=levels/01-first-roll.json -DWORK=dir -P progress_unsaved_check.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(WRITE "${WORK}/not-a-folder" "a file where the data folder should be\n")
set(ENV{XDG_DATA_HOME} "${WORK}/not-a-folder")

execute_process(COMMAND "${GAME}" "${LEVEL}" --frames 900 --press right:0-899
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 100)
if(NOT code STREQUAL "0")
  message(FATAL_ERROR "tire-game exited with ${code}\nstdout:\n${out}\nstderr:\n${err}")
endif()
message(STATUS "stdout: ${out}\nstderr: ${err}")
if(NOT err MATCHES "progress and best runs cannot be kept in [^\n]*not-a-folder/soft-tire: [^\n]*not-a-folder is not a folder; nothing will be saved")
  message(FATAL_ERROR "no warning at the start naming the data folder and why:\n${err}")
endif()
if(NOT err MATCHES "cannot save the progress to [^\n]*not-a-folder/soft-tire/progress.json: [^\n]*; this best time is not kept")
  message(FATAL_ERROR "no warning when the win could not be saved:\n${err}")
endif()
string(STRIP "${out}" out)
foreach(check "won;finished;status" "OFF;progress;run;new_best" "OFF;progress;run;saved" "OFF;progress;won")
  list(POP_FRONT check want)
  string(JSON got ERROR_VARIABLE e GET "${out}" ${check})
  if(NOT got STREQUAL want)
    message(FATAL_ERROR "${check}: got '${got}' (${e}), expected '${want}'\n${out}")
  endif()
endforeach()
if(EXISTS "${WORK}/not-a-folder/soft-tire" OR NOT IS_DIRECTORY "${WORK}" OR IS_DIRECTORY "${WORK}/not-a-folder")
  message(FATAL_ERROR "the file standing for the data folder was changed")
endif()

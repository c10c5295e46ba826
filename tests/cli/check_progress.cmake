# tirectl's progress line (tools/common/progress.h): on stderr when it is a terminal, never in a
# pipe or a file, never with --no-progress. The terminal is a pseudo-terminal from script(1).
#   cmake -DTIRECTL=tirectl -DLEVEL=levels/01-first-roll.json -DREPLAY=replay.json -P check_progress.cmake
cmake_policy(SET CMP0054 NEW)  # if() takes quoted text as text
find_program(SCRIPT script)
if(NOT SCRIPT)
  message("SKIPPED: no script(1) to give tirectl a terminal")
  return()
endif()
execute_process(COMMAND "${SCRIPT}" -qec "true" /dev/null RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET)
if(NOT code STREQUAL "0")
  message("SKIPPED: script(1) cannot open a pseudo-terminal here")
  return()
endif()

# Runs the shell command `command` on a terminal; everything it wrote (stdout and stderr) in `out`.
function(on_terminal command)
  execute_process(COMMAND "${SCRIPT}" -qec "${command}" /dev/null TIMEOUT 120
    RESULT_VARIABLE code OUTPUT_VARIABLE text ERROR_VARIABLE text)
  if(NOT code STREQUAL "0")
    message(FATAL_ERROR "${command}: exit ${code}\n${text}")
  endif()
  set(out "${text}" PARENT_SCOPE)
endfunction()

# The line shows from the start (then every 2 s of wall time) and is erased at the end.
on_terminal("'${TIRECTL}' run '${LEVEL}' --ticks 30")
if(NOT out MATCHES "\rrun: 0% \\(0 / 30 ticks\\)" OR NOT out MATCHES "ticks[^\r]*\\)\r +\r{")
  message(FATAL_ERROR "no progress line, shown and then erased, for tirectl run on a terminal:\n${out}")
endif()
if(NOT out MATCHES "\"ticks\": 30,")
  message(FATAL_ERROR "no summary after the progress line:\n${out}")
endif()
on_terminal("'${TIRECTL}' replay '${REPLAY}'")
if(NOT out MATCHES "\rreplay [^\r]*01-first-roll-goal.json: 0% \\(0 / 600 ticks\\)" OR
   NOT out MATCHES "ticks[^\r]*\\)\r +\r[^\r]*01-first-roll-goal.json: ok")
  message(FATAL_ERROR "no progress line for tirectl replay on a terminal:\n${out}")
endif()
foreach(command "'${TIRECTL}' run '${LEVEL}' --ticks 30 --no-progress"
                "'${TIRECTL}' replay --no-progress '${REPLAY}'")
  on_terminal("${command}")
  if(out MATCHES "ticks\\)")
    message(FATAL_ERROR "${command}: a progress line despite --no-progress:\n${out}")
  endif()
endforeach()

# Not a terminal: stderr stays empty.
foreach(args "run;${LEVEL};--ticks;30" "replay;${REPLAY}")
  execute_process(COMMAND "${TIRECTL}" ${args} TIMEOUT 120 RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT code STREQUAL "0" OR NOT err STREQUAL "")
    message(FATAL_ERROR "tirectl ${args} in a pipe: exit ${code}, stderr:\n${err}")
  endif()
endforeach()

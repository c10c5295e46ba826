# Paths with a newline in them, echoed by tirectl with the newline escaped (tire::printable), so that
# a name such as "x<newline>levels/01.json: ok" cannot forge a line of the output. In a folder of the
# test's own, with names relative to it:
#   cmake -DTIRECTL=tirectl -DLEVEL=levels/01-first-roll.json -DWORK=<dir> -P check_printable.cmake
cmake_policy(SET CMP0054 NEW)  # if() takes quoted text as text
set(nl "\n")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}" "${WORK}/r${nl}d")
file(COPY_FILE "${LEVEL}" "${WORK}/a${nl}b.json")
file(WRITE "${WORK}/bad${nl}.json" "{\"name\": 3, \"tires\": 1}")

# Runs tirectl with ARGN in WORK and checks the exit code and both outputs exactly.
function(expect code stdout stderr)
  execute_process(COMMAND "${TIRECTL}" ${ARGN} WORKING_DIRECTORY "${WORK}" TIMEOUT 60
    RESULT_VARIABLE got_code OUTPUT_VARIABLE got_out ERROR_VARIABLE got_err)
  if(NOT got_code STREQUAL "${code}")
    message(FATAL_ERROR "tirectl ${ARGN}: exit ${got_code}, expected ${code}\nstdout:\n${got_out}\nstderr:\n${got_err}")
  endif()
  if(NOT stdout STREQUAL "*" AND NOT got_out STREQUAL stdout)
    message(FATAL_ERROR "tirectl ${ARGN}: stdout is\n[${got_out}]\nexpected\n[${stdout}]")
  endif()
  if(NOT got_err STREQUAL stderr)
    message(FATAL_ERROR "tirectl ${ARGN}: stderr is\n[${got_err}]\nexpected\n[${stderr}]")
  endif()
endfunction()

# validate: the ok line and the error lines.
expect(0 "a\\nb.json: ok\n" "" validate "a${nl}b.json")
expect(2 "" "x\\nlevels/01.json: ok: no such file\n" validate "x${nl}levels/01.json: ok")
expect(2 "" "bad\\n.json: /name: must be a string of at most 200 characters, got 3\nbad\\n.json: /tires: must be an array, got 1\n"
  validate "bad${nl}.json")
# run: the file errors and its own messages.
expect(2 "" "tirectl: --record a\\nb.json is the level being run (a\\nb.json); refusing to write the replay over it\n"
  run "a${nl}b.json" --ticks 1 --record "a${nl}b.json")
expect(2 "" "x\\ny.json: no such file\n" run "x${nl}y.json")
# replay: a missing file, then one recorded into a folder with a newline in its name, which names
# its level (with a newline too) relative to itself.
expect(2 "" "x\\ny.json: no such file\n" replay "x${nl}y.json")
expect(0 "*" "" run "a${nl}b.json" --ticks 30 --record "r${nl}d/r.json")
expect(0 "r\\nd/r.json: ok (30 ticks, running)\n" "" replay "r${nl}d/r.json")

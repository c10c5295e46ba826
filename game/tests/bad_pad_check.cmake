# Bad --pad specs: a message naming the spec, exit 2, no crash.
#   cmake -DGAME=tire-game -DLEVEL=... -P bad_pad_check.cmake
foreach(spec "connect:soon" "leftx:0-10" "leftx=2:0-10" "leftx=nan:3" "nosuch:3" "a:10-5" "a" "=1:3" "a:-3" "leftx=1:x")
  execute_process(COMMAND "${GAME}" "${LEVEL}" --no-progress --frames 5 --pad "${spec}"
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 30)
  if(NOT code STREQUAL "2" OR NOT err MATCHES "--pad")
    message(FATAL_ERROR "--pad ${spec}: exit ${code}, expected 2 with a message\nstdout: ${out}\nstderr: ${err}")
  endif()
  string(STRIP "${err}" err)
  message(STATUS "--pad ${spec}: ${err}")
endforeach()

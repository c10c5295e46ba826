# A session played in the window (offscreen here) is recorded, and tirectl replays it bit for bit.
#   cmake -DGAME=... -DTIRECTL=... -DLEVEL=... -DOUT=... -P window_replay_check.cmake
execute_process(COMMAND ${GAME} ${LEVEL} --frames 420 --press right:0-250 --press space:120
                        --press left:300-399 --press r:330 --record ${OUT}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "tire-game exited ${code}:\n${out}\n${err}")
endif()
file(READ ${OUT} replay)
foreach(needle "\"restart\": true" "\"jump\": true" "\"steer\": -1.0" "\"hash\"")
  string(FIND "${replay}" "${needle}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the recorded replay lacks ${needle}:\n${replay}")
  endif()
endforeach()
execute_process(COMMAND ${TIRECTL} replay ${OUT} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES ": ok \\(420 ticks")
  message(FATAL_ERROR "tirectl replay did not reproduce the window's session (exit ${code}):\n${out}\n${err}")
endif()
message(STATUS "${out}")

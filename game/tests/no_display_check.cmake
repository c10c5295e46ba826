# Without a display the game must exit 1 with a clear message, never crash:
#   cmake -DGAME=tire-game -DLEVEL=levels/01-first-roll.json -P no_display_check.cmake
# (run with DISPLAY and WAYLAND_DISPLAY unset and SDL_VIDEODRIVER=x11, so that SDL finds nothing.)
execute_process(COMMAND "${GAME}" "${LEVEL}" --frames 10
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 30)
if(NOT code STREQUAL "1")
  message(FATAL_ERROR "exit code ${code}, expected 1\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(NOT err MATCHES "tire-game: cannot open a window: .*Set DISPLAY or run headless with SDL_VIDEODRIVER=offscreen, or use build/bin/tirectl")
  message(FATAL_ERROR "stderr does not explain the missing display:\n${err}")
endif()
message(STATUS "${err}")

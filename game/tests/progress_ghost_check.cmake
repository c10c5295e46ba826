# Progress and the ghost, headless, on a copy of level 01 and a data folder of its own
# (XDG_DATA_HOME; the user's own files are never touched):
#  - win it (steering from frame 60), then faster (from frame 0): progress.json holds the better
#    time, the exit summary reports the menu's note with it, and a slower win after it is no best;
#  - the next run shows the ghost: loaded, and, played with the very inputs of the best run, exactly
#    where the player is (replays are bit-exact); a run starting later has the ghost ahead of it;
#  - the level file changed: the ghost is dropped with a message, the best time is shown as the
#    earlier version's, and a slower win on the new version is its best;
#  - a truncated or mistyped progress.json is reported, set aside, and the game starts (exit 0).
#   cmake -DGAME=tire-game -DLEVEL=levels/01-first-roll.json -DWORK=dir [-DSHOT=ghost.bmp] -P progress_ghost_check.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/levels" "${WORK}/data")
file(COPY "${LEVEL}" DESTINATION "${WORK}/levels")
get_filename_component(level_name "${LEVEL}" NAME)
set(level "${WORK}/levels/${level_name}")
set(progress "${WORK}/data/soft-tire/progress.json")
set(ENV{XDG_DATA_HOME} "${WORK}/data")

function(play out_var err_var)
  execute_process(COMMAND "${GAME}" "${level}" --levels-dir "${WORK}/levels" ${ARGN}
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 100)
  if(NOT code STREQUAL "0")
    message(FATAL_ERROR "tire-game ${ARGN} exited with ${code}\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  string(STRIP "${out}" out)
  message(STATUS "${ARGN}:\n  ${out}\n  stderr: ${err}")
  set(${out_var} "${out}" PARENT_SCOPE)
  set(${err_var} "${err}" PARENT_SCOPE)
endfunction()
function(expect json want)
  string(JSON got ERROR_VARIABLE e GET "${json}" ${ARGN})
  if(NOT got STREQUAL want)
    message(FATAL_ERROR "${ARGN}: got '${got}' (${e}), expected '${want}'\n${json}")
  endif()
endfunction()

# 1. A slow win, then a faster one.
play(slow err --frames 900 --press right:60-899)
expect("${slow}" won finished status)
expect("${slow}" ON progress run new_best)
string(JSON slow_time GET "${slow}" finished time)
play(fast err --frames 900 --press right:0-899)
expect("${fast}" won finished status)
expect("${fast}" ON progress run new_best)
expect("${fast}" ON progress ghost loaded)  # the slow run's ghost raced this one
string(JSON fast_time GET "${fast}" finished time)
if(NOT fast_time LESS slow_time)
  message(FATAL_ERROR "the second run (${fast_time} s) is not faster than the first (${slow_time} s)")
endif()
file(READ "${progress}" saved)
string(JSON best GET "${saved}" levels ${level_name} best_time)
string(JSON won GET "${saved}" levels ${level_name} won)
if(NOT best EQUAL fast_time OR NOT won STREQUAL "ON")
  message(FATAL_ERROR "progress.json holds ${best} s (won ${won}), expected the better time ${fast_time} s:\n${saved}")
endif()
expect("${fast}" "${best}" progress best_time)
# Level 01's medals are gold 7 s, silver 10 s: the slow win (7.27 s) earned silver, the fast one
# (6.50 s) gold, and the record keeps the best medal with the best time.
string(JSON medal GET "${saved}" levels ${level_name} medal)
if(NOT medal STREQUAL "gold")
  message(FATAL_ERROR "progress.json keeps the medal '${medal}', expected gold:\n${saved}")
endif()
string(JSON menu GET "${fast}" progress menu)
if(NOT menu MATCHES "^best [0-9]+\\.[0-9][0-9] s, gold$")
  message(FATAL_ERROR "the menu's note for the level is '${menu}', expected 'best N.NN s, gold'")
endif()
message(STATUS "progress.json: best ${best} s (first win ${slow_time} s); the menu shows '${menu}'")
if(NOT EXISTS "${WORK}/data/soft-tire/ghosts/01-first-roll.json")
  message(FATAL_ERROR "no ghost file next to progress.json")
endif()

# 2. A slower win is no new best and leaves the record alone.
play(slower err --frames 900 --press right:60-899)
expect("${slower}" OFF progress run new_best)
expect("${slower}" "${best}" progress best_time)

# 3. The ghost: played with the best run's inputs, it is exactly where the player is.
play(same err --frames 300 --press right:0-299)
expect("${same}" ON progress ghost loaded)
expect("${same}" 300 progress ghost tick)
foreach(i 0 1)
  string(JSON p GET "${same}" player ${i})
  string(JSON g GET "${same}" progress ghost position ${i})
  if(NOT p STREQUAL g)
    message(FATAL_ERROR "the ghost replaying the same inputs is at ${g}, the player at ${p} (coordinate ${i})")
  endif()
endforeach()
# A player who starts late: the ghost is ahead. G hides it (and the summary says so).
set(shot_args "")
if(SHOT)
  set(shot_args --screenshot "${SHOT}")
endif()
play(late err --frames 150 --press right:40-149 ${shot_args})
string(JSON px GET "${late}" player 0)
string(JSON gx GET "${late}" progress ghost position 0)
if(NOT gx GREATER px)
  message(FATAL_ERROR "the ghost (x ${gx}) is not ahead of a player who started late (x ${px})")
endif()
expect("${late}" ON progress ghost visible)
play(hidden err --frames 10 --press g:2)
expect("${hidden}" OFF progress ghost visible)

# 4. The level changed since the ghost was recorded: dropped, with a message.
file(READ "${level}" text)
string(REPLACE "\"description\": \"" "\"description\": \"Changed. " text "${text}")
file(WRITE "${level}" "${text}")
play(changed err --frames 10)
expect("${changed}" OFF progress ghost loaded)
if(NOT err MATCHES "ghost dropped: the level changed")
  message(FATAL_ERROR "no message about the dropped ghost:\n${err}")
endif()
# Its best time is of the earlier version: the menu says so, and a slower win is the new best.
expect("${changed}" OFF progress of_this_version)
string(JSON menu GET "${changed}" progress menu)
if(NOT menu MATCHES "^best [0-9]+\\.[0-9][0-9] s, gold on an earlier version$")
  message(FATAL_ERROR "the menu's note for the changed level is '${menu}', expected 'best N.NN s, gold on an earlier version'")
endif()
play(rewon err --frames 900 --press right:60-899)
expect("${rewon}" ON progress run new_best)
expect("${rewon}" ON progress of_this_version)
expect("${rewon}" "${slow_time}" progress best_time)
string(JSON menu GET "${rewon}" progress menu)
if(NOT menu MATCHES "^best [0-9]+\\.[0-9][0-9] s, silver$")
  message(FATAL_ERROR "after a win on the changed level the menu shows '${menu}', expected 'best N.NN s, silver'")
endif()

# 5. A damaged progress.json: reported (naming the file and what is wrong), set aside, the game starts.
foreach(damage "{\"format\": \"soft-tire-progress/1\", \"levels\": {\"01-first-ro"
               "{\"format\": \"soft-tire-progress/1\", \"levels\": {\"01-first-roll.json\": {\"won\": \"yes\"}}}"
               "[1, 2, 3]")
  file(REMOVE "${progress}.damaged")
  file(WRITE "${progress}" "${damage}")
  play(damaged err --frames 10)
  if(NOT err MATCHES "progress file .*progress.json is damaged: .*set aside as .*progress.json.damaged")
    message(FATAL_ERROR "a damaged progress.json (${damage}) was not reported:\n${err}")
  endif()
  if(NOT EXISTS "${progress}.damaged" OR EXISTS "${progress}")
    message(FATAL_ERROR "the damaged progress.json was not set aside")
  endif()
  expect("${damaged}" OFF progress won)
endforeach()

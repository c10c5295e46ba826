# The replay suite: each replay in tests/replays is its own test, labelled `replay`, so that
# `ctest -L replay` runs the suite alone. Damaged replays must be refused with exit code 2 (or 1
# for one whose level changed or whose state diverged), never crash.
file(GLOB replays ${CMAKE_CURRENT_SOURCE_DIR}/replays/*.json)
foreach(replay ${replays})
  get_filename_component(name ${replay} NAME_WE)
  add_test(NAME "replay ${name}" COMMAND tirectl replay ${replay})
  set_tests_properties("replay ${name}" PROPERTIES LABELS replay)
endforeach()
# Level 08's replay steps its pile of 301 tires for 20 s: long, as the Debug suite counts it
# (tests/CMakeLists.txt).
set_tests_properties("replay 08-three-hundred-goal" PROPERTIES LABELS "replay;long")

set(BAD_REPLAYS ${CMAKE_CURRENT_SOURCE_DIR}/replays-bad)
tirectl_test("replay refuses a truncated file" 2 ARGS replay ${BAD_REPLAYS}/truncated.json
  STDERR "truncated.json: invalid JSON: parse error at line 1")
tirectl_test("replay names every wrong type" 2 ARGS replay ${BAD_REPLAYS}/wrong-types.json
  STDERR "/ticks: must be an integer.*/inputs/0/steer: must be a number in \\[-1, 1\\], got \"left\".*/expect/status: must be one of")
tirectl_test("replay refuses keys given twice" 2 ARGS replay ${BAD_REPLAYS}/duplicate-keys.json
  STDERR "duplicate-keys.json: /inputs/1/steer: key given twice \\(first at line 4\\).*duplicate-keys.json: /ticks: key given twice \\(first at line 2\\)")
tirectl_test("replay refuses inputs out of order" 2 ARGS replay ${BAD_REPLAYS}/out-of-order.json
  STDERR "/inputs/1/tick: inputs must be in tick order: 10 comes after 50")
tirectl_test("replay refuses ticks past the end" 2 ARGS replay ${BAD_REPLAYS}/past-the-end.json
  STDERR "/inputs/1/tick: must be at most 99 .*/expect/checkpoints/0/tick: must be at most 100")
# A mass scale of 0 made each particle's inverse mass infinite: the tire diverged every tick (issue 12).
tirectl_test("replay refuses a mass scale of 0" 2 ARGS replay ${BAD_REPLAYS}/mass-scale-zero.json
  STDERR "mass-scale-zero.json: /inputs/0/set/value: must be a number in \\[0.01, 10\\] \\(times the tire's spawn mass\\), got 0")
tirectl_test("replay refuses an unknown format" 2 ARGS replay ${BAD_REPLAYS}/wrong-format.json
  STDERR "/format: must be \"tire-replay/1\", got \"tire-replay/9\"")
tirectl_test("replay refuses a level whose content changed" 1 ARGS replay ${BAD_REPLAYS}/level-changed.json
  STDERR "has changed since this replay was recorded.*--allow-level-change")
tirectl_test("replay runs a changed level when allowed" 0 ARGS replay --allow-level-change ${BAD_REPLAYS}/level-changed.json
  STDOUT "level-changed.json: ok")
# Inputs sharing a tick all act in file order: a second steer on one would silently replace the first.
tirectl_test("replay refuses two steers on one tick" 2 ARGS replay ${BAD_REPLAYS}/same-tick-steer.json
  STDERR "same-tick-steer.json: /inputs/2/steer: a second steer on tick 50 \\(the first is /inputs/1/steer\\): only the last would act; give one steer per tick")
# A replay's level is read as a level before anything is said of it: a file that is not one gets the
# loader's error and neither its digest nor its bytes.
tirectl_test("replay refuses a level that is not a level, printing no digest" 2
  ARGS replay ${BAD_REPLAYS}/level-not-a-level.json
  STDERR "level-not-a-level.json: /level: [^\n]*README.md is not a valid level: invalid JSON: parse error at line 1"
  REFUSE_STDERR "SHA-256|[0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f][0-9a-f]|last read|Soft tire")
tirectl_test("replay refuses an absolute level path" 2 ARGS replay ${BAD_REPLAYS}/level-absolute.json
  STDERR "level-absolute.json: /level: must be the level file's path relative to the replay file's folder"
  REFUSE_STDERR "root:")
tirectl_test("replay names the first divergent tick" 1 ARGS replay ${BAD_REPLAYS}/diverged.json
  STDOUT "FAILED, first divergent tick 30.*state diverged at tick 30")

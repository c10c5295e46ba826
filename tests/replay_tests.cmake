# The replay suite: each replay in tests/replays is its own test, labelled `replay`, so that
# `ctest -L replay` runs the suite alone. Damaged replays must be refused with exit code 2 (or 1
# for one whose level changed or whose state diverged), never crash.
file(GLOB replays ${CMAKE_CURRENT_SOURCE_DIR}/replays/*.json)
foreach(replay ${replays})
  get_filename_component(name ${replay} NAME_WE)
  add_test(NAME "replay ${name}" COMMAND tirectl replay ${replay})
  set_tests_properties("replay ${name}" PROPERTIES LABELS replay)
endforeach()

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
tirectl_test("replay names the first divergent tick" 1 ARGS replay ${BAD_REPLAYS}/diverged.json
  STDOUT "FAILED, first divergent tick 30.*state diverged at tick 30")

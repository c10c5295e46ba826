# tirectl as a user runs it: exit codes 0 / 2 and the messages they read.
set(EXPECT ${CMAKE_CURRENT_SOURCE_DIR}/cli/expect.cmake)
set(LEVELS ${PROJECT_SOURCE_DIR}/levels)
set(BAD ${CMAKE_CURRENT_SOURCE_DIR}/levels)

function(tirectl_test name code)
  cmake_parse_arguments(T "LONG" "STDOUT;STDERR;REFUSE_STDERR" "ARGS" ${ARGN})
  set(defs -DEXPECT_CODE=${code})
  if(DEFINED T_STDOUT)
    list(APPEND defs "-DEXPECT_STDOUT=${T_STDOUT}")
  endif()
  if(DEFINED T_STDERR)
    list(APPEND defs "-DEXPECT_STDERR=${T_STDERR}")
  endif()
  if(DEFINED T_REFUSE_STDERR)
    list(APPEND defs "-DREFUSE_STDERR=${T_REFUSE_STDERR}")
  endif()
  string(REPLACE ";" "|" cmd "$<TARGET_FILE:tirectl>;${T_ARGS}")
  add_test(NAME "tirectl ${name}" COMMAND ${CMAKE_COMMAND} "-DCMD=${cmd}" ${defs} -P ${EXPECT})
  set(labels unit)
  if(T_LONG)  # a big scene stepped for long: left out of the Debug suite (tests/CMakeLists.txt)
    list(APPEND labels long)
  endif()
  set_tests_properties("tirectl ${name}" PROPERTIES LABELS "${labels}")
endfunction()

tirectl_test("validate accepts the default level" 0 ARGS validate ${LEVELS}/01-first-roll.json
  STDOUT "01-first-roll.json: ok")
tirectl_test("validate names file, path and expectation" 2 ARGS validate ${BAD}/bad-segments.json
  STDERR "bad-segments.json: /tires/0/segments: must be an integer in \\[6, 256\\], got 2")
tirectl_test("validate reports truncated JSON" 2 ARGS validate ${BAD}/bad-truncated.json
  STDERR "bad-truncated.json: invalid JSON: parse error at line 1")
tirectl_test("validate reports a missing file" 2 ARGS validate ${BAD}/no-such-level.json
  STDERR "no-such-level.json: no such file")
tirectl_test("run prints the final state" 0 ARGS run ${LEVELS}/01-first-roll.json --ticks 120 --steer 1
  STDOUT "\"ticks\": 120,.*\"status\": \"running\".*\"centroid\".*\"area_ratio\".*\"grounded\": [a-z]+,[ \n]*\"asleep\": false.*\"hash\": \"[0-9a-f]+\"")
# The substeps the ticks took (SolverConfig::refine_turn): a tire driven along level 01 (global 2 × 1)
# keeps the level's; the global method refines while a 1000 kg box crushes a soft tire flat.
tirectl_test("run reports the substeps the ticks took" 0 ARGS run ${LEVELS}/01-first-roll.json --ticks 60 --steer 1
  STDOUT "\"substeps\": {[ \n]*\"level\": 2,[ \n]*\"most\": 2,[ \n]*\"refined_ticks\": 0[ \n]*}")
tirectl_test("run reports the substeps the global method's refinement added" 0 ARGS run ${BAD}/global-crush.json --ticks 60
  STDOUT "\"substeps\": {[ \n]*\"level\": 2,[ \n]*\"most\": (4|8|16),[ \n]*\"refined_ticks\": [1-9][0-9]*[ \n]*}")
tirectl_test("validate refuses a solver.sleep that is not a boolean" 2 ARGS validate ${BAD}/bad-sleep.json
  STDERR "bad-sleep.json: /solver/sleep: must be true or false, got \"no\"")
tirectl_test("run refuses a solver.sleep that is not a boolean" 2 ARGS run ${BAD}/bad-sleep.json --ticks 10
  STDERR "bad-sleep.json: /solver/sleep: must be true or false, got \"no\"")
tirectl_test("run refuses an invalid level" 2 ARGS run ${BAD}/bad-segments.json --ticks 10
  STDERR "/tires/0/segments")
tirectl_test("run applies --set and validates it" 2 ARGS run ${LEVELS}/01-first-roll.json --set solver.substeps=0
  STDERR "/solver/substeps: must be an integer in \\[1, 256\\], got 0")
tirectl_test("run refuses a steer outside [-1, 1]" 2 ARGS run ${LEVELS}/01-first-roll.json --steer 3)
# Options that would be silently ignored are refused together: a replay given with --input drives
# the player (--steer, --jump-at); --steps fixes bench's count, which --seconds would otherwise set;
# the global method's own sweep needs the global method swept.
set(GOAL_REPLAY ${CMAKE_CURRENT_SOURCE_DIR}/replays/01-first-roll-goal.json)
tirectl_test("run refuses --steer with --input" 2 ARGS run ${LEVELS}/01-first-roll.json --input ${GOAL_REPLAY} --steer 1
  STDERR "--(steer|input) excludes --(input|steer)")
tirectl_test("run refuses --jump-at with --input" 2 ARGS run ${LEVELS}/01-first-roll.json --jump-at 10 --input ${GOAL_REPLAY}
  STDERR "--(jump-at|input) excludes --(input|jump-at)")
tirectl_test("run takes its inputs from --input alone" 0 ARGS run ${LEVELS}/01-first-roll.json --input ${GOAL_REPLAY} --ticks 600
  STDOUT "\"status\": \"won\"")
tirectl_test("bench refuses --steps with --seconds" 2 ARGS bench --scene prototype --steps 5 --seconds 1
  STDERR "--(steps|seconds) excludes --(seconds|steps)")
tirectl_test("tradeoff refuses --global-substeps without the global method" 2
  ARGS tradeoff --methods gauss-seidel --global-substeps 2 --out ${CMAKE_CURRENT_BINARY_DIR}/tradeoff-test-bad
  STDERR "--global-substeps and --global-iterations apply to the global method, which --methods leaves out")
# A key with an empty part is not the key without it: solver.dt. was once taken as solver.dt.
tirectl_test("run refuses a --set key with an empty part" 2 ARGS run ${LEVELS}/01-first-roll.json --set solver.dt.=0.01
  STDERR "01-first-roll.json: --set solver.dt.=0.01: the key \"solver.dt.\" has an empty part \\(a leading, trailing or doubled dot\\)")
tirectl_test("run refuses a --set key with a doubled dot" 2 ARGS run ${LEVELS}/01-first-roll.json --set solver..dt=0.01
  STDERR "--set solver..dt=0.01: the key \"solver..dt\" has an empty part")
# A path with a newline is echoed with it escaped: "x\nlevels/01.json: ok" cannot forge an ok line.
add_test(NAME "tirectl escapes control characters in the paths it prints"
  COMMAND ${CMAKE_COMMAND} -DTIRECTL=$<TARGET_FILE:tirectl> -DLEVEL=${LEVELS}/01-first-roll.json
    -DWORK=${CMAKE_CURRENT_BINARY_DIR}/printable-test -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/check_printable.cmake)
set_tests_properties("tirectl escapes control characters in the paths it prints" PROPERTIES LABELS unit)
# Progress on stderr only on a terminal (a pseudo-terminal from script(1) here), never in a pipe.
add_test(NAME "tirectl shows progress on a terminal only, and not with --no-progress"
  COMMAND ${CMAKE_COMMAND} -DTIRECTL=$<TARGET_FILE:tirectl> -DLEVEL=${LEVELS}/01-first-roll.json
    -DREPLAY=${GOAL_REPLAY} -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/check_progress.cmake)
set_tests_properties("tirectl shows progress on a terminal only, and not with --no-progress" PROPERTIES
  LABELS unit SKIP_REGULAR_EXPRESSION "SKIPPED:")
tirectl_test("unknown subcommand is a usage error" 2 ARGS fly)
# levels/schema.json is generated from the parameter table (engine/tire/include/tire/tire/parameters.h):
# regenerated here and compared with the committed file. On a difference tirectl names the first
# differing line and says how to regenerate: tirectl schema --write levels/schema.json
tirectl_test("schema: levels/schema.json is what the parameter table generates" 0 ARGS schema --check ${LEVELS}/schema.json
  STDOUT "schema.json: up to date with the parameter table")
# Numbers a user types are finite and in range: NaN fails every comparison, so a range check alone
# lets it through (issue 18). The message names the option and what was typed.
tirectl_test("run refuses --steer nan" 2 ARGS run ${LEVELS}/01-first-roll.json --ticks 5 --steer nan
  STDERR "--steer: must be a number in \\[-1, 1\\], got nan")
tirectl_test("run refuses --steer inf" 2 ARGS run ${LEVELS}/01-first-roll.json --ticks 5 --steer inf
  STDERR "--steer: must be a number in \\[-1, 1\\], got inf")
tirectl_test("run refuses --ticks 1e300" 2 ARGS run ${LEVELS}/01-first-roll.json --ticks 1e300
  STDERR "--ticks: must be an integer in \\[0, 1e\\+08\\], got 1e300")
tirectl_test("run takes --ticks 1e2 as 100" 0 ARGS run ${LEVELS}/01-first-roll.json --ticks 1e2 STDOUT "\"ticks\": 100,")
tirectl_test("run refuses --set solver.substeps=nan" 2 ARGS run ${LEVELS}/01-first-roll.json --set solver.substeps=nan
  STDERR "--set solver.substeps=nan: value must be a finite number, got nan")
tirectl_test("run refuses --set tires.0.mass=inf" 2 ARGS run ${LEVELS}/01-first-roll.json --set tires.0.mass=inf
  STDERR "--set tires.0.mass=inf: value must be a finite number, got inf")
tirectl_test("bench refuses --seconds nan" 2 ARGS bench --seconds nan --scene prototype
  STDERR "--seconds: must be a number in \\[0, 3600\\], got nan")
tirectl_test("bench refuses --threads nan" 2 ARGS bench --threads nan --scene prototype
  STDERR "--threads: must be an integer in \\[1, 256\\], got nan")
tirectl_test("tradeoff refuses --game-error nan" 2 ARGS tradeoff --game-error nan
  STDERR "--game-error: must be a number in \\(0, inf\\), got nan")
tirectl_test("tradeoff refuses a nan inside a list" 2 ARGS tradeoff --tunnel-clamp 1,nan
  STDERR "--tunnel-clamp: must be a number in \\[0.1, 1000\\], got nan")
# A key written twice: every repeat, with its JSON path and the first one's line.
tirectl_test("validate refuses keys given twice" 2 ARGS validate ${BAD}/bad-duplicate-keys.json
  STDERR "bad-duplicate-keys.json: /name: key given twice \\(first at line 1\\).*bad-duplicate-keys.json: /solver: key given twice \\(first at line 3\\).*bad-duplicate-keys.json: /tires/0/mass: key given twice \\(first at line 5\\)")
tirectl_test("bench prints CSV" 0 ARGS bench --scene prototype --steps 50
  STDOUT "^scene,tires,particles,contacts,tire_pairs,threads,segments,substeps,iterations,steps,median_ms,p99_ms,mean_ms,us_per_tire,peak_rss_mib,speedup_vs_prototype,asleep,simd\nprototype,1,56,[1-9][0-9]*,0,1,28,1,22,50,[^\n]*,[0-9]+,(avx2|sse2|scalar)\n")
tirectl_test("bench counts the contacts and tire pairs of a pile" 0 ARGS bench --scene pile-100 --threads 2 --steps 3 --warmup 10
  STDOUT "\npile-100,100,5600,[1-9][0-9]*,[1-9][0-9]*,2,28,8,1,3,")
# The big scenes, built and stepped once, so that ctest stays quick (a full run takes minutes): the
# settled pile settles for 2 ticks only; the crowd's 9 900 shelf tires each touch their shelf with
# the two particles of their bottom segment from the first tick, the 100 falling ones touch nothing.
tirectl_test("bench settles pile-1000-settled for at most --settle ticks" 0
  ARGS bench --scene pile-1000-settled --settle 2 --warmup 0 --steps 1
  STDOUT "\npile-1000-settled,1000,56000,[0-9]+,[0-9]+,[0-9]+,28,8,1,1,[^\n]*,0,(avx2|sse2|scalar)\n"
  STDERR "pile-1000-settled: settled for 2 ticks, 0 of 1000 tires asleep")
# The car: its level text loads (a scene the reader refused would end the run), its two wheels
# are the scene's tires and touch the ground.
tirectl_test("bench builds car-global-2x1" 0 ARGS bench --scene car-global-2x1 --warmup 30 --steps 3
  STDOUT "\ncar-global-2x1,2,112,[1-9][0-9]*,0,[0-9]+,28,2,1,3,")
tirectl_test("bench builds island-pile-60-settled-awake" 0
  ARGS bench --scene island-pile-60-settled-awake --settle 30 --warmup 0 --steps 1
  STDOUT "island-pile-60-settled-awake,60,")
tirectl_test("bench builds crowd-100" 0 ARGS bench --scene crowd-100 --warmup 0 --steps 1
  STDOUT "\ncrowd-100,100,5600,0,[0-9]+,[0-9]+,28,8,1,1,[^\n]*,0,(avx2|sse2|scalar)\n")
tirectl_test("bench builds crowd-10000: 9900 tires resting on shelves" 0 ARGS bench --scene crowd-10000 --warmup 0 --steps 1
  STDOUT "\ncrowd-10000,10000,560000,19800,[0-9]+,[0-9]+,28,8,1,1,[^\n]*,0,(avx2|sse2|scalar)\n")
tirectl_test("bench builds global-crowd-10000: the crowd on the default method" 0
  ARGS bench --scene global-crowd-100 --scene global-crowd-10000 --warmup 0 --steps 1
  STDOUT "\nglobal-crowd-100,100,5600,0,[0-9]+,[0-9]+,28,2,1,1,[^\n]*,0,(avx2|sse2|scalar)\nglobal-crowd-10000,10000,560000,19800,[0-9]+,[0-9]+,28,2,1,1,[^\n]*,0,(avx2|sse2|scalar)\n")
# The scenes of costs bounded by what is near (docs/bounded-and-safe.md), each built and stepped once:
# the tire on either chain; the 1953 tires of 256 segments on a grid (no pairs), on one spot and
# heaped, where each tire keeps at most 32 pairs (solver.tire_neighbours): at most 31 248 of the
# 1 906 128 candidates, so the count has at most five digits.
tirectl_test("bench drives a tire along chains of 1000 and 100 000 points" 0
  ARGS bench --scene chain-1000 --scene chain-100000 --warmup 0 --steps 1
  STDOUT "\nchain-1000,1,56,[0-9]+,0,1,28,2,1,1,[^\n]*\nchain-100000,1,56,[0-9]+,0,1,28,2,1,1,")
tirectl_test("bench steps 1953 tires of 256 segments on a grid, on one spot and heaped" 0
  ARGS bench --scene spot-grid-1953 --scene spot-pile-1953 --scene spot-heap-1953 --warmup 0 --steps 1
  STDOUT "\nspot-grid-1953,1953,999936,[0-9]+,0,[0-9]+,256,2,1,1,[^\n]*\nspot-pile-1953,1953,999936,[0-9]+,[1-9][0-9]?[0-9]?[0-9]?[0-9]?,[0-9]+,256,2,1,1,[^\n]*\nspot-heap-1953,1953,999936,[0-9]+,[1-9][0-9]?[0-9]?[0-9]?[0-9]?,[0-9]+,256,2,1,1,")
tirectl_test("bench times a tire rolling on flat ground by either method" 0
  ARGS bench --scene rolling-gauss-seidel-8x1 --scene rolling-global-2x1 --warmup 10 --steps 3
  STDOUT "\nrolling-gauss-seidel-8x1,1,56,[0-9]+,0,[0-9]+,28,8,1,3,[^\n]*\nrolling-global-2x1,1,56,[0-9]+,0,[0-9]+,28,2,1,3,")
# The bare tire (the tire solver alone) at the default settings, as the flat level is: global 2 x 1.
tirectl_test("bench steps the bare tire and the flat level at the default settings" 0
  ARGS bench --scene bare-tire --scene flat-level --warmup 10 --steps 3
  STDOUT "\nbare-tire,1,56,[0-9]+,0,1,28,2,1,3,[^\n]*\nflat-level,1,56,[0-9]+,0,[0-9]+,28,2,1,3,")
tirectl_test("bench refuses an unknown scene" 2 ARGS bench --scene pile-7 STDERR "unknown scene \"pile-7\"")
tirectl_test("bench steps with the plain schedule when asked" 0 ARGS bench --scene pile-10 --schedule plain --steps 3 --warmup 2
  STDOUT "\npile-10,10,560,")
tirectl_test("bench refuses an unknown schedule" 2 ARGS bench --scene pile-10 --schedule odd STDERR "--schedule: odd not in \\{fused,plain\\}")

# Every shipped level validates, and can be completed: tirectl plays it with fixed inputs until the
# script says won. (Levels that need steering choreography are completed by replays instead.)
file(GLOB shipped_levels ${LEVELS}/*.json)
list(FILTER shipped_levels EXCLUDE REGEX "schema\\.json$")
foreach(level ${shipped_levels})
  get_filename_component(name ${level} NAME_WE)
  tirectl_test("level ${name} validates" 0 ARGS validate ${level} STDOUT ": ok")
endforeach()
tirectl_test("level 01-first-roll is won by rolling right" 0
  ARGS run ${LEVELS}/01-first-roll.json --ticks 900 --steer 1 STDOUT "\"status\": \"won\"")
tirectl_test("level 02-jumps is won by jumping the blocks and the pit" 0
  ARGS run ${LEVELS}/02-jumps.json --ticks 640 --steer 1 --jump-at 103 --jump-at 180 --jump-at 330 --jump-at 398
  STDOUT "\"status\": \"won\"")
tirectl_test("level 03-hills is won by rolling over the hills and jumping the crack" 0
  ARGS run ${LEVELS}/03-hills.json --ticks 3600 --steer 1 --jump-at 480 STDOUT "\"status\": \"won\"")
tirectl_test("level 04-crates is won by pushing the crate into the pit and hopping the kerb" 0
  ARGS run ${LEVELS}/04-crates.json --ticks 2400 --steer 0.9 --jump-at 350 STDOUT "\"status\": \"won\"")
tirectl_test("level 06-tire-rain is won once the gate opens, by a jump onto the ledge" 0
  ARGS run ${LEVELS}/06-tire-rain.json --ticks 2400 --steer 1 --jump-at 440 STDOUT "\"status\": \"won\"")
tirectl_test("level 07-sandbox is won by rolling the ball into the pit" 0
  ARGS run ${LEVELS}/07-sandbox.json --ticks 1800 --steer 1 STDOUT "\"status\": \"won\"")
tirectl_test("level 08-three-hundred is won through the gate the 300th tire opens" 0
  LONG ARGS run ${LEVELS}/08-three-hundred.json --ticks 1200 --steer -1 STDOUT "\"status\": \"won\"")

# Hardening (docs/testing.md, "Hardening"): hostile files get one clear line per problem naming the file, the
# JSON path and what was expected, and exit code 2; never a crash, a stack trace or "terminate
# called" (expect.cmake fails on those). Every fuzz regression input goes through tirectl too.
set(HOSTILE ${CMAKE_CURRENT_SOURCE_DIR}/fuzz-regressions)
tirectl_test("hostile: a nesting bomb is refused with its path" 2 ARGS validate ${HOSTILE}/level/deep-nesting.invalid.json
  STDERR "deep-nesting.invalid.json: (/0)+: nesting deeper than 64 levels; arrays and objects may nest at most 64 deep\n$")
tirectl_test("hostile: 1e308 is judged by each key's range" 2 ARGS validate ${HOSTILE}/level/huge-numbers.invalid.json
  STDERR "huge-numbers.invalid.json: /gravity: must be \\[x, y\\] with each in \\[-1000, 1000\\] m/s\\^2, got \\[1e\\+308,-1e\\+308\\].*/tires/0/segments: must be an integer in \\[6, 256\\], got 1e\\+308")
tirectl_test("hostile: 1e400 is invalid JSON" 2 ARGS validate ${HOSTILE}/level/number-overflow.invalid.json
  STDERR "number-overflow.invalid.json: invalid JSON: number overflow parsing '1e400'")
tirectl_test("hostile: 5 million particles are refused before building" 2 ARGS run ${HOSTILE}/level/too-many-particles.invalid.json --ticks 1
  STDERR "too-many-particles.invalid.json: /tires/1953: the particles of the level's tires .* may add up to at most 1000000, got 5120000")
tirectl_test("hostile: a 1 MiB key is refused and cut short" 2 ARGS validate ${HOSTILE}/level/long-unknown-key.invalid.json
  STDERR "long-unknown-key.invalid.json: /tires/0/k+\\.\\.\\.\\(1048576 bytes\\): a key may be at most 4096 bytes long, got one of 1048576\n$")
tirectl_test("hostile: a script spawning 1.5 million particles is refused" 2 ARGS validate ${HOSTILE}/level/script-spawn-flood.invalid.json
  STDERR "script-spawn-flood.invalid.json: /triggers/1/do/953: the particles")
tirectl_test("hostile: an empty file is invalid JSON" 2 ARGS validate ${HOSTILE}/level/empty.invalid.json
  STDERR "empty.invalid.json: invalid JSON: parse error at line 1, column 1: .*unexpected end of input")
tirectl_test("hostile: binary garbage is invalid JSON" 2 ARGS validate ${HOSTILE}/level/binary.invalid.json
  STDERR "binary.invalid.json: invalid JSON: parse error at line 1, column 1")
tirectl_test("hostile: a device is not a level" 2 ARGS validate /dev/zero STDERR "^/dev/zero: not a regular file\n$")
tirectl_test("hostile: a directory is not a level" 2 ARGS validate ${HOSTILE} STDERR "fuzz-regressions: not a regular file")
tirectl_test("hostile: --set 1e308 is judged like the file" 2 ARGS run ${LEVELS}/01-first-roll.json --set tires.0.segments=1e308
  STDERR "01-first-roll.json: /tires/0/segments: must be an integer in \\[6, 256\\], got 1e\\+308")
tirectl_test("hostile: a replay of 10^8 ticks is refused" 2 ARGS replay ${HOSTILE}/replay/ticks-1e8.invalid.json
  STDERR "ticks-1e8.invalid.json: /ticks: must be an integer in \\[0, 5.184e\\+06\\], got 100000000")
tirectl_test("hostile: a replay tuning 10^9 substeps is refused" 2 ARGS replay ${HOSTILE}/replay/set-substeps-1e9.invalid.json
  STDERR "/inputs/0/set/value: must be an integer in \\[1, 256\\], got 1000000000.0.*/inputs/1/set/value: must be a number in \\[0.001, 1e\\+06\\] kg, got 0")
tirectl_test("hostile: a replay naming its level by an absolute path is refused" 2
  ARGS replay ${HOSTILE}/replay/level-is-dev-zero.invalid.json
  STDERR "level-is-dev-zero.invalid.json: /level: must be the level file's path relative to the replay file's folder \\(as \"../levels/01-first-roll.json\"\\), got \"/dev/zero\"")
tirectl_test("hostile: a replay whose level is a device is refused" 2
  ARGS replay ${HOSTILE}/replay/level-is-dev-zero-relative.invalid.json
  STDERR "level-is-dev-zero-relative.invalid.json: /level: cannot read [^\n]*/dev/zero: not a regular file")
tirectl_test("hostile: run --input with a hostile replay is refused" 2
  ARGS run ${LEVELS}/01-first-roll.json --ticks 10 --input ${HOSTILE}/replay/spawn-flood.invalid.json
  STDERR "spawn-flood.invalid.json: /inputs/10000/spawn: a replay may spawn at most 10000 tires; this is one more")
file(GLOB fuzz_regression_files ${HOSTILE}/level/*.json ${HOSTILE}/simulate/*.json ${HOSTILE}/replay/*.json
  ${HOSTILE}/session/*.json)
foreach(file ${fuzz_regression_files})
  get_filename_component(name ${file} NAME)
  get_filename_component(dir ${file} DIRECTORY)
  get_filename_component(target ${dir} NAME)
  set(command validate)
  set(options)
  if(target STREQUAL "replay")
    set(command replay)
  elseif(target STREQUAL "session")
    # Played as fuzz_session plays it, for 600 ticks within the budgets it lowers (fuzz_session.h).
    set(command run)
    set(options --ticks 600 --steer 1 --set budgets.tires=6 --set budgets.particles=336 --set budgets.props=48
      --set budgets.spawns_per_tick=4)
  endif()
  if(name MATCHES "\\.invalid\\.json$")
    tirectl_test("fuzz regression ${target}/${name}" 2 ARGS ${command} ${file} ${options} STDERR "${name}: ")
  else()
    tirectl_test("fuzz regression ${target}/${name}" 0 ARGS ${command} ${file} ${options})
  endif()
endforeach()

# tirectl tradeoff: a tiny sweep runs and writes its CSV and plot, for both solver methods (the
# default) or the one asked for; bad arguments are usage errors.
set(TRADEOFF_OUT ${CMAKE_CURRENT_BINARY_DIR}/tradeoff-test)
tirectl_test("tradeoff runs a tiny sweep" 0
  ARGS tradeoff --scenarios rest --substeps 1,4 --iterations 1 --segments 12 --repeats 1 --ref-substeps 128
       --out ${TRADEOFF_OUT}
  STDOUT "tradeoff.csv")
add_test(NAME "tirectl tradeoff writes the CSV columns and the SVG"
  COMMAND ${CMAKE_COMMAND} -DDIR=${TRADEOFF_OUT} "-DMETHODS=gauss-seidel|global"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/check_tradeoff.cmake)
set_tests_properties("tirectl tradeoff writes the CSV columns and the SVG" PROPERTIES LABELS unit
  DEPENDS "tirectl tradeoff runs a tiny sweep")
tirectl_test("tradeoff sweeps only the methods asked for" 0
  ARGS tradeoff --methods global --scenarios rest --substeps 1,4 --iterations 1 --segments 12 --repeats 1
       --ref-substeps 128 --out ${TRADEOFF_OUT}-global
  STDOUT "tradeoff.csv")
add_test(NAME "tirectl tradeoff --methods global writes global rows only"
  COMMAND ${CMAKE_COMMAND} -DDIR=${TRADEOFF_OUT}-global -DMETHODS=global
          -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/check_tradeoff.cmake)
set_tests_properties("tirectl tradeoff --methods global writes global rows only" PROPERTIES LABELS unit
  DEPENDS "tirectl tradeoff sweeps only the methods asked for")
tirectl_test("tradeoff refuses an unknown method" 2 ARGS tradeoff --methods global,newton --out ${TRADEOFF_OUT}-bad
  STDERR "--methods: must be one of gauss-seidel, global, got \"newton\"")
tirectl_test("tradeoff refuses zero substeps" 2 ARGS tradeoff --substeps 0 --out ${TRADEOFF_OUT}-bad
  STDERR "--substeps")
tirectl_test("tradeoff refuses an unknown scenario" 2 ARGS tradeoff --scenarios nowhere --out ${TRADEOFF_OUT}-bad
  STDERR "unknown scenario \"nowhere\"")

# Outputs written safely (docs/testing.md, "Hardening"): never over the level being run or the replay read,
# never onto a FIFO, device or directory, through a symbolic link to its file, the mode kept; a
# write that fails is exit 2 naming the file. Each case in a folder of its own under the build.
foreach(check "onto-level/run --record onto the level being run is refused before the run, the level unchanged"
              "onto-input/run --record onto the --input replay is refused, the replay unchanged"
              "fifo/run --record onto a FIFO or a directory is refused, the FIFO stays a FIFO"
              "link-mode/run --record through a symbolic link writes its file and keeps the link and a 0600 mode"
              "missing-dir/run --record into a missing folder fails with exit 2 naming the file")
  string(FIND "${check}" "/" slash)
  string(SUBSTRING "${check}" 0 ${slash} case)
  math(EXPR slash "${slash} + 1")
  string(SUBSTRING "${check}" ${slash} -1 what)
  add_test(NAME "tirectl ${what}"
    COMMAND ${CMAKE_COMMAND} -DTIRECTL=$<TARGET_FILE:tirectl> -DLEVEL=${LEVELS}/01-first-roll.json
      -DWORK=${CMAKE_CURRENT_BINARY_DIR}/outputs-${case} -DCASE=${case}
      -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/check_outputs.cmake)
  set_tests_properties("tirectl ${what}" PROPERTIES LABELS unit TIMEOUT 120)
endforeach()

# Run-time budgets (issue 34): a level that spawns a tire every tick for ever is held to its live
# tires, the budget reported once on stderr and in the output.
tirectl_test("run holds a spawn flood to budgets.tires and reports it once" 0
  ARGS run ${BAD}/spawn-flood.json --ticks 600 --set budgets.tires=50
  STDOUT "\"budgets_reached\": .[ \n]*{[ \n]*\"budget\": \"budgets.tires\",[ \n]*\"limit\": 50,[ \n]*\"first_tick\": 49,[ \n]*\"dropped\": 552"
  STDERR "^tirectl: warning: budgets.tires \\(50\\) reached at tick 49: what would pass it is dropped\n$")
# The island solve's work (docs/at-rest.md): three tires stacked, their contacts one problem.
tirectl_test("run reports the island solve's work" 0
  ARGS run ${BAD}/island-stack.json --ticks 120
  STDOUT "\"islands\": {[ \n]*\"solved\": [1-9][0-9]*,[ \n]*\"rows\": [1-9][0-9]*,.*\"overflows\": 0,[ \n]*\"failures\": 0")
# How far tires are inside each other at the end (tire/world/overlap.h): the stack's middle tire,
# carrying the top one, is pressed a little into one of its neighbours.
tirectl_test("run reports the deepest overlap between tires" 0
  ARGS run ${BAD}/island-stack.json --ticks 120
  STDOUT "\"overlap\": {[ \n]*\"deepest\": [0-9][.0-9e-]*,[ \n]*\"tire\": 1,[ \n]*\"inside\": [02][ \n]*}")
add_test(NAME "tire-soak holds a level's spawn flood to the tires it was given"
  COMMAND tire-soak --level ${BAD}/spawn-flood.json --minutes 0.2 --max-tires 20 --warmup 0)
set_tests_properties("tire-soak holds a level's spawn flood to the tires it was given" PROPERTIES LABELS unit
  PASS_REGULAR_EXPRESSION "tire-soak: ok: .*tires at end 21 \\(max 21\\).*ticks past budgets.tires 0")
# A level's bounds (levels/README.md "bounds"). A level that names none has them computed from its
# geometry: a tire driven off a 5 m shelf into nothing is lost once it has fallen 10 m below it,
# in under 200 ticks, and the run says why and when; in a level with checkpoints it is put back.
tirectl_test("run loses a tire driven off a ledge, by the computed bounds" 0
  ARGS run ${BAD}/ledge.json --ticks 200 --steer 1
  STDOUT "\"status\": \"lost\",[ \n]*\"end\": {[ \n]*\"tick\": 1[0-9][0-9],[ \n]*\"time\": [0-9.]+,[ \n]*\"reason\": \"out_of_bounds\"[ \n]*},[ \n]*\"medal\": null,[ \n]*\"bounds\": {[ \n]*\"min\": \\[[ \n]*-15.0,[ \n]*-11.0[ \n]*\\],[ \n]*\"max\": \\[[ \n]*15.0,[ \n]*null[ \n]*\\]")
tirectl_test("run keeps a tire that stays on the ledge" 0
  ARGS run ${BAD}/ledge.json --ticks 200
  STDOUT "\"status\": \"running\",[ \n]*\"end\": null,")
tirectl_test("run puts a tire that leaves the bounds back at the checkpoint" 0
  ARGS run ${BAD}/ledge-checkpoint.json --ticks 400 --steer 1
  STDOUT "\"status\": \"running\",[ \n]*\"end\": null,.*\"respawns\": [1-9]")
tirectl_test("validate names a bounds corner the player starts outside" 2 ARGS validate ${BAD}/bad-bounds.json
  STDERR "bad-bounds.json: /bounds/min: must be below and left of the player's start \\[0,0.5\\] \\(/tires/0/position\\), got \\[2,-5\\]")

# Medals: a won run prints the medal it earned; the course check finds a level that holding one
# direction wins.
tirectl_test("run prints the medal a win earns" 0 ARGS run ${BAD}/course/held-right.json --ticks 600 --steer 1
  STDOUT "\"status\": \"won\".*\"medal\": \"gold\"")
tirectl_test("run prints no medal for a run still going" 0 ARGS run ${BAD}/course/held-right.json --ticks 10
  STDOUT "\"medal\": null")
tirectl_test("course finds a level won by holding one direction" 1 ARGS course ${BAD}/course --max-held-share 0.25
  STDOUT "\"won_holding\": \\[[ \n]*\"right\"[ \n]*\\]"
  STDERR "1 of 1 levels are won by holding one input")
tirectl_test("course names a level with no shipped replay that wins it" 1 ARGS course ${BAD}/course
  --replays ${CMAKE_CURRENT_SOURCE_DIR}/replays --max-held-share 1 STDOUT "no shipped replay wins it")
# The game's course (levels/): every level has a goal, a time limit, medals and a shipped replay
# that wins it, and at most a quarter are won by holding one direction or nothing. Label `course`:
# not in the Debug run (tools/test), which would step the same bits ten times slower.
add_test(NAME "tirectl course: levels/ is a course" COMMAND tirectl course ${LEVELS}
  --replays ${CMAKE_CURRENT_SOURCE_DIR}/replays)
set_tests_properties("tirectl course: levels/ is a course" PROPERTIES LABELS course TIMEOUT 1200)

# Vehicles (levels/README.md, "Vehicles"): a player vehicle driven by --steer, --lean and --brake,
# its chassis in --trace and in the report; a vehicle level's errors from validate.
tirectl_test("run drives a player vehicle and traces its chassis" 0
  ARGS run ${BAD}/vehicle-car.json --ticks 120 --steer 1 --lean 0.2 --trace 60
  STDERR "t= +1[.]00 s +chassis \\( *[1-9][0-9.]*, *0[.][0-9]+\\) m +speed \\( *[1-9][0-9.]*,.*lean +0[.]20"
  STDOUT "\"vehicles\": .[ \n]*{[ \n]*\"index\": 0,[ \n]*\"player\": true,[ \n]*\"position\"")
tirectl_test("run holds a player vehicle's brakes" 0 ARGS run ${BAD}/vehicle-car.json --ticks 60 --brake --trace 60
  STDERR "braking")
tirectl_test("run refuses a lean outside [-1, 1]" 2 ARGS run ${BAD}/vehicle-car.json --lean 2
  STDERR "--lean: must be a number in \\[-1, 1\\], got 2")
tirectl_test("run refuses --brake with --input" 2 ARGS run ${BAD}/vehicle-car.json --input ${GOAL_REPLAY} --brake
  STDERR "--(brake|input) excludes --(input|brake)")
tirectl_test("validate accepts a vehicle level" 0 ARGS validate ${BAD}/vehicle-car.json STDOUT "vehicle-car.json: ok")
tirectl_test("validate refuses one wheel and the gauss-seidel method" 2 ARGS validate ${BAD}/bad-vehicle.json
  STDERR "bad-vehicle.json: /vehicles/0/wheels: must be an array of 2 to 8 wheels, got 1.*bad-vehicle.json: /vehicles: a level with vehicles needs the global solver method")

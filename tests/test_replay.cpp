// Replays: read strictly, written atomically, played back bit for bit.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>

#include "tire/io/file_io.h"
#include "tire/replay/replay.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

TEST_CASE("SHA-256 is the standard one", "[unit][replay]") {
  CHECK(sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST_CASE("a recorded run replays to the same hashes, and a changed input is caught",
          "[unit][replay][determinism]") {
  const Level level = default_level();
  ReplayRecorder recorder("level.json", std::string(64, '0'), 10);
  auto session = make_session(level);
  TickInput held;
  for (std::uint64_t tick = 0; tick < 240; ++tick) {
    held.jump = false;
    ReplayInput in;
    in.tick = tick;
    if (tick == 0) in.steer = 1.0;
    if (tick == 30) in.inflate = -1.0;  // deflate for a second, then inflate
    if (tick == 90) in.jump = true, in.inflate = 1.0;
    if (tick == 150) in.spawn = Vec2{3, 4};
    if (tick == 160) in.set_key = "tires.pressure", in.set_value = 1.3;
    if (in.steer || in.jump || in.inflate || in.spawn || in.set_key) {
      recorder.input(in);
      apply_input(in, *session, level, held);
    }
    session->step(held);
    recorder.after_step(session->state_hash());
  }
  Replay replay = recorder.finish(session->status(), session->state_hash());
  REQUIRE(replay.expect.checkpoints.size() == 24);
  // Through JSON and back, then played: every expectation holds.
  const ReplayLoad again = load_replay_text(replay_to_json(replay), "r.json");
  REQUIRE(again.replay);
  const ReplayOutcome ok = run_replay(*again.replay, level);
  INFO((ok.failures.empty() ? std::string() : ok.failures.front()));
  CHECK(ok.failures.empty());
  CHECK(ok.hash == *replay.expect.hash);
  // The same replay with the jump one tick later diverges, and the report says where.
  Replay changed = *again.replay;
  changed.inputs[2].tick = 91;  // the jump (and the inflate with it)
  const ReplayOutcome bad = run_replay(changed, level);
  REQUIRE(bad.first_divergent_tick);
  CHECK(*bad.first_divergent_tick == 100);  // the first checkpoint after tick 91
  CHECK(*bad.last_matching_tick == 90);
}

TEST_CASE("box tolerances check a tire's centroid instead of an exact hash", "[unit][replay]") {
  Replay replay;
  replay.ticks = 60;
  replay.expect.boxes = {{60, 0, {-0.1, 0.3}, {0.1, 0.6}}, {60, 0, {5, 5}, {6, 6}}, {60, 3, {0, 0}, {1, 1}}};
  const ReplayOutcome out = run_replay(replay, default_level());
  REQUIRE(out.failures.size() == 2);
  CHECK(out.failures[0].find("outside its box") != std::string::npos);
  CHECK(out.failures[1].find("no tire 3") != std::string::npos);
}

TEST_CASE("only known keys can be tuned by a replay", "[unit][replay]") {
  CHECK(is_tunable_key("tires.compliance.spoke"));
  CHECK(is_tunable_key("player.jump_speed"));
  CHECK(is_tunable_key("solver.substeps"));
  CHECK_FALSE(is_tunable_key("solver.dt"));
  CHECK_FALSE(is_tunable_key("tires.colour"));
  const auto errors = load_replay_text(R"({"format": "tire-replay/1", "level": "l", "level_sha256": ")" +
                                           std::string(64, 'a') + R"(", "ticks": 5,
      "inputs": [ {"tick": 1, "set": {"key": "solver.dt", "value": 1}}, {"tick": 2} ]})",
                                       "r.json")
                          .errors;
  REQUIRE(errors.size() == 2);
  CHECK(errors[0] ==
        "r.json: /inputs/0/set/key: must be a tunable key such as \"tires.pressure\" or \"solver.substeps\", "
        "got \"solver.dt\"");
  CHECK(errors[1] == "r.json: /inputs/1: has a tick but no input (steer, jump, spawn, ...)");
}

TEST_CASE("a file written atomically survives the writer being killed mid-write", "[unit][replay][files]") {
  const auto dir = std::filesystem::temp_directory_path() / ("tire-atomic-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "replay.json";
  std::string error;
  REQUIRE(write_file_atomically(file, "old and whole", error));
  // A child rewrites it with 64 MiB, over and over; we kill it at a random moment.
  for (int attempt = 0; attempt < 5; ++attempt) {
    const pid_t child = ::fork();
    if (child == 0) {
      const std::string big(64 << 20, 'x');
      std::string e;
      for (;;) write_file_atomically(file, big, e);
    }
    ::usleep(static_cast<useconds_t>(20000 + 15000 * attempt));
    ::kill(child, SIGKILL);
    ::waitpid(child, nullptr, 0);
    const auto contents = read_file(file, 1ull << 30, error);
    REQUIRE(contents);
    const bool whole =
        *contents == "old and whole" || (contents->size() == (64u << 20) && contents->back() == 'x');
    CHECK(whole);
  }
  std::filesystem::remove_all(dir);
}

namespace {
const std::string kHead = R"({"format": "tire-replay/1", "level": "l.json", "level_sha256": ")" +
                          std::string(64, 'a') + R"(", "ticks": 100, "inputs": )";
std::vector<std::string> replay_errors(const std::string& inputs) {
  return load_replay_text(kHead + inputs + "}", "r.json").errors;
}
}  // namespace

TEST_CASE("inputs sharing a tick all act, so a tick holds one steer and one jump", "[unit][replay]") {
  // Different inputs on one tick, each acting in file order, as the game records them (the
  // friction slider sets two keys at once; a restart, then the steer held through it).
  CHECK(replay_errors(R"([{"tick": 5, "restart": true}, {"tick": 5, "steer": 1}, {"tick": 5, "jump": true},
      {"tick": 5, "set": {"key": "tires.friction", "value": 0.5}},
      {"tick": 5, "set": {"key": "tires.kinetic_friction", "value": 0.5}}, {"tick": 5, "spawn": [0, 3]},
      {"tick": 5, "spawn": [1, 3]}, {"tick": 6, "steer": 0}, {"tick": 7, "restart": true, "steer": 1}])")
            .empty());
  // A second steer on a tick would silently replace the first: refused, naming both.
  CHECK(replay_errors(R"([{"tick": 3, "steer": 1}, {"tick": 7, "steer": 1}, {"tick": 7, "steer": -1}])") ==
        std::vector<std::string>{
            "r.json: /inputs/2/steer: a second steer on tick 7 (the first is /inputs/1/steer): "
            "only the last would act; give one steer per tick"});
  CHECK(replay_errors(R"([{"tick": 7, "jump": true, "steer": 1}, {"tick": 7, "jump": true}])") ==
        std::vector<std::string>{"r.json: /inputs/1/jump: a second jump on tick 7 (the first is "
                                 "/inputs/0/jump): give one jump per tick"});
  // A restart drops the steer given before it on its tick (a level starts unsteered).
  CHECK(replay_errors(R"([{"tick": 9, "steer": 1}, {"tick": 9, "restart": true}])") ==
        std::vector<std::string>{
            "r.json: /inputs/1/restart: restarts the level after the steer of /inputs/0 on "
            "the same tick 9, which the restart drops (a level starts unsteered); give the "
            "steer after the restart"});
}

TEST_CASE("a replay names its level by a path relative to its own folder", "[unit][replay]") {
  const auto with_level = [](const std::string& level) {
    return load_replay_text(R"({"format": "tire-replay/1", "level": )" + level + R"(, "level_sha256": ")" +
                                std::string(64, 'a') + R"(", "ticks": 1, "inputs": []})",
                            "r.json")
        .errors;
  };
  CHECK(with_level(R"("../../levels/01-first-roll.json")").empty());
  const std::string expected =
      "r.json: /level: must be the level file's path relative to the replay file's folder (as "
      "\"../levels/01-first-roll.json\"), got ";
  CHECK(with_level(R"("/etc/passwd")") == std::vector<std::string>{expected + "\"/etc/passwd\""});
  CHECK(with_level(R"("")") == std::vector<std::string>{expected + "\"\""});
  CHECK(with_level(R"("l.json\u0000x")") == std::vector<std::string>{expected + "\"l.json\\u0000x\""});
}

TEST_CASE("a replay's level is read as a level before its digest is taken", "[unit][replay]") {
  const auto dir =
      std::filesystem::temp_directory_path() / ("tire-replay-level-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir / "replays");
  const auto put = [&](const std::string& name, const std::string& text) {
    std::string error;
    REQUIRE(write_file_atomically(dir / name, text, error));
  };
  const std::string level_text = R"({"name": "n", "tires": [{"position": [0, 1]}]})";
  put("level.json", level_text);
  put("secret.txt", "root:x:0:0:root:/root:/bin/bash\n");
  put("other.json", R"({"token": "hunter2"})");
  Replay replay;
  replay.level = "../level.json";
  const ReplayLevel good = load_replay_level(dir / "replays" / "r.json", replay);
  CHECK(good.errors.empty());
  REQUIRE(good.level);
  CHECK(good.sha256 == sha256_hex(level_text));
  CHECK(good.path == dir / "replays" / "../level.json");

  // Not a level: the loader's error under the replay's /level, nothing of the bytes, no digest.
  replay.level = "../secret.txt";
  const ReplayLevel secret = load_replay_level(dir / "replays" / "r.json", replay);
  CHECK_FALSE(secret.level);
  CHECK(secret.sha256.empty());
  REQUIRE(secret.errors.size() == 1);
  const std::string where = (dir / "replays" / "r.json").string() + ": /level: ";
  const std::string shown = (dir / "replays" / "../secret.txt").string();
  CHECK(secret.errors[0].rfind(where + shown + " is not a valid level: invalid JSON: parse error at line 1",
                               0) == 0);
  CHECK(secret.errors[0].find("last read") == std::string::npos);
  CHECK(secret.errors[0].find("root:") == std::string::npos);
  CHECK(secret.errors[0].find(sha256_hex("root:x:0:0:root:/root:/bin/bash\n").substr(0, 12)) ==
        std::string::npos);

  replay.level = "../other.json";
  const ReplayLevel other = load_replay_level(dir / "replays" / "r.json", replay);
  CHECK_FALSE(other.level);
  REQUIRE_FALSE(other.errors.empty());
  for (const std::string& e : other.errors)
    CHECK(e.rfind(where + (dir / "replays" / "../other.json").string() + " is not a valid level: /", 0) == 0);

  replay.level = "../missing.json";
  CHECK(load_replay_level(dir / "replays" / "r.json", replay).errors ==
        std::vector<std::string>{where + "cannot read " + (dir / "replays" / "../missing.json").string() +
                                 ": no such file"});
  std::filesystem::remove_all(dir);
}

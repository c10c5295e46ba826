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
  double steer = 0.0;
  for (std::uint64_t tick = 0; tick < 240; ++tick) {
    bool jump = false;
    ReplayInput in;
    in.tick = tick;
    if (tick == 0) in.steer = 1.0;
    if (tick == 90) in.jump = true;
    if (tick == 150) in.spawn = Vec2{3, 4};
    if (tick == 160) in.set_key = "tires.pressure", in.set_value = 1.3;
    if (in.steer || in.jump || in.spawn || in.set_key) {
      recorder.input(in);
      apply_input(in, *session, level, steer, jump);
    }
    session->step({steer, jump});
    recorder.after_step(*session);
  }
  Replay replay = recorder.finish(*session);
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
  changed.inputs[1].tick = 91;
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

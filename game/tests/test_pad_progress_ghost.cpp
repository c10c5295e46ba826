// The gamepad's pure parts (the --pad parser, the stick's dead zone), the progress file (parsing,
// damage, best times, keys) and the ghost (a cut recording, lockstep replay) without a window.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <fstream>

#include "input/gamepad.h"
#include "input/pad_script.h"
#include "internals.h"
#include "play/session_recorder.h"
#include "progress/best_runs.h"
#include "progress/ghost.h"
#include "progress/progress.h"
#include "tire/math/state_hash.h"
#include "tire/replay/replay.h"

using namespace game;

TEST_CASE("pad specs (--pad) parse into axis or button and frames", "[unit][game]") {
  std::string error;
  const auto axis = parse_pad_press("leftx=-0.5:10-20", error);
  REQUIRE(axis);
  CHECK(axis->is_axis);
  CHECK(axis->axis == SDL_CONTROLLER_AXIS_LEFTX);
  CHECK(axis->value == -0.5);
  CHECK(axis->first == 10);
  CHECK(axis->last == 20);
  const auto button = parse_pad_press("a:140", error);
  REQUIRE(button);
  CHECK_FALSE(button->is_axis);
  CHECK(button->button == SDL_CONTROLLER_BUTTON_A);
  CHECK(button->first == 140);
  CHECK(button->last == 140);
  for (const char* bad : {"leftx:3", "leftx=1.5:3", "leftx=x:3", "zz:3", "a:5-4", "a", "a:", "start=1:3",
                          "connect:x", "connect:-1"}) {
    error.clear();
    CHECK_FALSE(parse_pad_press(bad, error));
    CHECK(error.find(std::string("--pad ") + bad) == 0);
  }
  CHECK(axis_raw(1.0) == 32767);
  CHECK(axis_raw(-1.0) == -32767);
  CHECK(axis_raw(0.0) == 0);
}

TEST_CASE("the stick steers nothing inside its dead zone and exactly 1 at full tilt", "[unit][game]") {
  CHECK(stick_steer(0) == 0.0);
  CHECK(stick_steer(static_cast<Sint16>(kStickDeadZone * 32767 * 0.9)) == 0.0);
  CHECK(stick_steer(32767) == 1.0);
  CHECK(stick_steer(-32768) == -1.0);
  CHECK(stick_steer(-32767) == -1.0);
  const double half = stick_steer(axis_raw(0.6));
  CHECK(half > 0.4);
  CHECK(half < 0.6);
}

namespace {
const std::string kShaA(64, 'a'), kShaB(64, 'b');
}  // namespace

TEST_CASE("a faster win is a new best time and a slower one is not", "[unit][game]") {
  Progress p;
  CHECK_FALSE(p.record("a.json", kShaA, false, 3.0, 180));
  REQUIRE(p.find("a.json"));
  CHECK(format_record(p.find("a.json")) == "not won yet");
  CHECK(p.record("a.json", kShaA, true, 10.0, 600));
  CHECK(p.record("a.json", kShaA, true, 9.5, 570));
  CHECK_FALSE(p.record("a.json", kShaA, true, 9.9, 594));
  CHECK(p.find("a.json")->best_ticks == 570);
  CHECK(format_record(p.find("a.json")) == "best 9.50 s");
  CHECK(format_record(nullptr).empty());
  std::string error;
  const auto back = Progress::parse(p.to_json(), error);
  REQUIRE(back);
  CHECK(back->at("a.json").best_time == 9.5);
  CHECK(back->at("a.json").won);
}

TEST_CASE("the best medal won is kept with the best time", "[unit][game]") {
  Progress p;
  CHECK(p.record("a.json", kShaA, true, 20.0, 1200, tire::Medal::bronze));
  CHECK(format_record(p.find("a.json")) == "best 20.00 s, bronze");
  CHECK(p.record("a.json", kShaA, true, 9.5, 570, tire::Medal::gold));
  // Slower, and with no medal: the gold won stays.
  CHECK_FALSE(p.record("a.json", kShaA, true, 12.0, 720, tire::Medal::none));
  CHECK(p.find("a.json")->medal == tire::Medal::gold);
  CHECK(format_record(p.find("a.json")) == "best 9.50 s, gold");
  std::string error;
  const auto back = Progress::parse(p.to_json(), error);
  REQUIRE(back);
  CHECK(back->at("a.json").medal == tire::Medal::gold);
  // A record from before medals has none.
  const auto old = Progress::parse(
      R"({"format": "soft-tire-progress/1", "levels": {"a.json": {"won": true, "best_time": 9, "best_ticks": 540}}})",
      error);
  REQUIRE(old);
  CHECK(old->at("a.json").medal == tire::Medal::none);
}

TEST_CASE("a level that changed since its record shows it as an earlier version's and starts a new one",
          "[unit][game]") {
  Progress p;
  CHECK(p.record("a.json", kShaA, true, 6.88, 413, tire::Medal::gold));
  const LevelRecord* r = p.find("a.json");
  REQUIRE(r);
  CHECK(of_version(*r, kShaA));
  CHECK_FALSE(of_version(*r, kShaB));
  CHECK(format_record(r, true) == "best 6.88 s, gold on an earlier version");
  std::string error;
  const auto back = Progress::parse(p.to_json(), error);
  REQUIRE(back);
  CHECK(back->at("a.json").level_sha256 == kShaA);
  // The file changed: a slower win on it is its first, with the medal it earns there.
  CHECK(p.record("a.json", kShaB, true, 10.0, 600, tire::Medal::silver));
  CHECK(p.find("a.json")->best_time == 10.0);
  CHECK(p.find("a.json")->medal == tire::Medal::silver);
  CHECK(of_version(*p.find("a.json"), kShaB));
  // A loss on a changed level: not won on it yet.
  CHECK_FALSE(p.record("a.json", kShaA, false, 3.0, 180));
  CHECK_FALSE(p.find("a.json")->won);
  CHECK(format_record(p.find("a.json"), true) == "not won since it changed");
  // A record from before levels' hashes were kept is of no known version.
  const auto old = Progress::parse(
      R"({"format": "soft-tire-progress/1", "levels": {"a.json": {"won": true, "best_time": 9, "best_ticks": 540}}})",
      error);
  REQUIRE(old);
  CHECK_FALSE(of_version(old->at("a.json"), kShaA));
}

TEST_CASE("a damaged progress file is an error naming what is wrong", "[unit][game]") {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"format": "soft-tire-progress/1", "levels": {"a.js)", "not valid JSON"},
      {R"([])", "/: must be an object"},
      {R"({"levels": {}})", "/format"},
      {R"({"format": "soft-tire-progress/1", "levels": []})", "/levels"},
      {R"({"format": "soft-tire-progress/1", "levels": {"a.json": 3}})", "/levels/a.json"},
      {R"({"format": "soft-tire-progress/1", "levels": {"a.json": {"won": "yes"}}})", "/levels/a.json/won"},
      {R"({"format": "soft-tire-progress/1", "levels": {"a.json": {"won": true, "best_time": "9"}}})",
       "/levels/a.json/best_time"},
      {R"({"format": "soft-tire-progress/1", "levels": {"a.json": {"won": true, "best_time": 9, "best_ticks": -1}}})",
       "/levels/a.json/best_ticks"},
      {R"({"format": "soft-tire-progress/1", "levels": {"a.json": {"won": true, "best_time": 9, "best_ticks": 540, "medal": "platinum"}}})",
       "/levels/a.json/medal"},
      {R"({"format": "soft-tire-progress/1", "levels": {"a.json": {"won": false, "level_sha256": "ABC"}}})",
       "/levels/a.json/level_sha256: must be 64 lowercase hex digits"},
  };
  for (const auto& [text, what] : cases) {
    std::string error;
    CHECK_FALSE(Progress::parse(text, error));
    INFO(text);
    CHECK(error.find(what) != std::string::npos);
  }
}

TEST_CASE("progress keys levels by their path in the levels folder and names ghost files safely",
          "[unit][game]") {
  const std::filesystem::path dir = TIRE_LEVELS_DIR;
  CHECK(level_key(dir, dir / "01-first-roll.json") == "01-first-roll.json");
  CHECK(level_key(dir, dir / "sub" / ".." / "02-jumps.json") == "02-jumps.json");
  const std::string outside = level_key(dir, dir / ".." / "README.md");
  CHECK(std::filesystem::path(outside).is_absolute());
  Progress p;
  CHECK(p.ghost_file("01-first-roll.json").filename() == "01-first-roll.json");
  CHECK(p.ghost_file("/a b/c.json").filename() == "_a_b_c.json");
}

namespace {
std::shared_ptr<const tire::Level> level_01() {
  const tire::LevelLoad load =
      tire::load_level_file(std::filesystem::path(TIRE_LEVELS_DIR) / "01-first-roll.json");
  REQUIRE(load.level);
  return std::make_shared<const tire::Level>(*load.level);
}
}  // namespace

TEST_CASE("a win is a new best only once saved, and a data folder that cannot be made is reported",
          "[unit][game]") {
  const auto dir = std::filesystem::temp_directory_path() / ("tire-best-runs-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "file") << "a file where the data folder should be\n";
  const std::string level_path = std::string(TIRE_LEVELS_DIR) + "/01-first-roll.json";
  const auto level = level_01();
  SessionRecorder recorder;
  recorder.begin(level_path, level->gravity);
  const auto session = std::make_unique<tire::Simulation>(level);
  const auto win = [&](const std::filesystem::path& data, std::vector<std::string>& messages) {
    BestRuns runs;
    messages = runs.open(data, TIRE_LEVELS_DIR);
    runs.level_started(level_path, level, messages);
    const RunResult r = runs.finished(true, 9.5, 570, true, recorder, *session, messages);
    return std::make_pair(r, runs.summary(level_path));
  };

  std::vector<std::string> messages;
  const auto [saved, saved_summary] = win(dir / "data", messages);
  CHECK(messages.empty());
  CHECK(saved.new_best);
  CHECK(saved.saved);
  CHECK(saved.note == "New best time!");
  CHECK(saved_summary["run"]["new_best"] == true);
  CHECK(saved_summary["best_time"] == 9.5);

  // XDG_DATA_HOME naming a file: said when the progress opens, and the win is not claimed as a best.
  const auto [unsaved, unsaved_summary] = win(dir / "file" / "soft-tire", messages);
  INFO(messages.size() << " messages: " << (messages.empty() ? "" : messages.front()));
  REQUIRE(messages.size() == 2);
  CHECK(messages[0] == "progress and best runs cannot be kept in " + (dir / "file" / "soft-tire").string() +
                           ": " + (dir / "file").string() + " is not a folder; nothing will be saved");
  CHECK(messages[1].rfind(
            "cannot save the progress to " + (dir / "file" / "soft-tire" / "progress.json").string() + ": ",
            0) == 0);
  CHECK(messages[1].ends_with("; this best time is not kept"));
  CHECK(unsaved.won);
  CHECK_FALSE(unsaved.new_best);
  CHECK_FALSE(unsaved.saved);
  CHECK(unsaved.note == "best time not saved: the progress file cannot be written");
  CHECK(unsaved_summary["run"]["new_best"] == false);
  CHECK(unsaved_summary["run"]["saved"] == false);
  CHECK(unsaved_summary["won"] == false);  // what the (missing) file holds
  CHECK(unsaved_summary["menu"] == "");
  std::filesystem::remove_all(dir);
}

TEST_CASE("the last run of a recording replays on its own to the recorded end", "[unit][game][replay]") {
  const auto level = level_01();
  tire::ReplayRecorder recorder("01-first-roll.json", "sha");
  std::unique_ptr<tire::LevelSession> session = tire::make_session(*level);
  tire::TickInput held;
  const auto play = [&](const tire::ReplayInput& in) {
    recorder.input(in);
    tire::apply_input(in, *session, *level, held);
  };
  tire::ReplayInput left;
  left.steer = -1.0;
  play(left);
  for (int i = 0; i < 50; ++i) session->step(held), recorder.after_step(session->state_hash());
  tire::ReplayInput restart;
  restart.tick = 50;
  restart.restart = true;
  play(restart);
  tire::ReplayInput right;
  right.tick = 50;
  right.steer = 1.0;
  play(right);
  for (int i = 0; i < 100; ++i) session->step(held), recorder.after_step(session->state_hash());
  const tire::Replay whole = recorder.finish(session->status(), session->state_hash());
  const tire::Replay run = last_attempt(whole);
  CHECK(run.ticks == 100);
  REQUIRE(run.inputs.size() == 1);
  CHECK(run.inputs[0].tick == 0);
  CHECK(run.expect.checkpoints.front().tick == 10);  // recorded at 60, 50 ticks before the restart
  const tire::ReplayOutcome outcome = tire::run_replay(run, *level);
  CHECK(outcome.failures.empty());
}

TEST_CASE("the ghost steps in lockstep from its replay and ends where the run ended",
          "[unit][game][replay]") {
  const auto level = level_01();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tire-ghost-test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path level_file = std::filesystem::path(TIRE_LEVELS_DIR) / "01-first-roll.json";
  SessionRecorder recorder;
  recorder.begin(level_file, level->gravity);
  std::unique_ptr<tire::Simulation> session = std::make_unique<tire::Simulation>(level);
  for (std::uint64_t t = 0; t < 120; ++t) {
    const tire::TickInput in{t < 80 ? 1.0 : 0.0, t == 40};
    recorder.on_step(t, in);
    session->step(in);
    recorder.on_stepped(*session);
  }
  const std::filesystem::path file = dir / "ghost.json";
  REQUIRE(recorder.save(*session, file, true).empty());
  Ghost ghost;
  const std::string sha = level_file_sha256(level_file);
  REQUIRE(ghost.load(file, level, sha).empty());
  REQUIRE(ghost.loaded());
  ghost.sync(60);
  CHECK(ghost.tick() == 60);
  ghost.sync(500);  // past its end it holds still
  CHECK(ghost.tick() == 120);
  REQUIRE(ghost.player());
  CHECK(ghost.player()->centroid.x == world_of(*session).player()->centroid().x);
  CHECK(ghost.player()->centroid.y == world_of(*session).player()->centroid().y);
  ghost.sync(0);  // the player restarted
  CHECK(ghost.tick() == 0);
  // Another version of the level: dropped.
  CHECK(ghost.load(file, level, std::string(64, '0')).find("ghost dropped") != std::string::npos);
  CHECK_FALSE(ghost.loaded());
  // A missing ghost is no ghost and no message; a broken one is a message.
  CHECK(ghost.load(dir / "none.json", level, sha).empty());
  std::ofstream(dir / "broken.json") << "{\"format\": \"tire-rep";
  CHECK(ghost.load(dir / "broken.json", level, sha).find("cannot read the ghost") != std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST_CASE("the ghost of a vehicle level is its player vehicle, in lockstep, drawn between ticks",
          "[unit][game][replay]") {
  const std::filesystem::path level_file =
      std::filesystem::path(TIRE_LEVELS_DIR) / ".." / "tests" / "levels" / "vehicle-car.json";
  const tire::LevelLoad load = tire::load_level_file(level_file);
  REQUIRE(load.level);
  const auto level = std::make_shared<const tire::Level>(*load.level);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("tire-vehicle-ghost-test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  SessionRecorder recorder;
  recorder.begin(level_file, level->gravity);
  auto session = std::make_unique<tire::Simulation>(level);
  for (std::uint64_t t = 0; t < 120; ++t) {
    const tire::TickInput in{1.0, false, 0.0, t > 60 && t < 80 ? 1.0 : 0.0, t >= 100};
    recorder.on_step(t, in);
    session->step(in);
    recorder.on_stepped(*session);
  }
  const std::filesystem::path file = dir / "ghost.json";
  REQUIRE(recorder.save(*session, file, true).empty());
  Ghost ghost;
  REQUIRE(ghost.load(file, level, level_file_sha256(level_file)).empty());
  ghost.sync(120);
  CHECK_FALSE(ghost.player());  // no player tire: the player is the vehicle
  const std::optional<tire::VehicleView> v = ghost.vehicle();
  REQUIRE(v);
  const tire::VehicleView mine = *session->vehicle_at(0);
  CHECK(v->center == mine.center);  // the same run, to the bit
  CHECK(ghost.position() == mine.center);
  REQUIRE(ghost.chassis());
  CHECK(ghost.chassis()->vertices.size() == 4);
  // Drawn at alpha 1 it is where it is now; at 0 where it was a tick before.
  CHECK(ghost.interpolated_chassis(1.0).position == v->pose.position);
  CHECK(ghost.interpolated_chassis(0.0).position.x < v->pose.position.x);
  std::vector<tire::Vec2> wheel;
  for (std::size_t w = 0; w < v->wheel_count; ++w) {
    ghost.interpolated_wheel(w, 1.0, wheel);
    const std::optional<tire::TireView> t = session->tire(mine.wheel_ids[w]);
    REQUIRE(wheel.size() == t->positions.size());
    CHECK(wheel.front() == t->positions.front());
    ghost.interpolated_wheel(w, 0.0, wheel);
    CHECK(wheel.front() != t->positions.front());
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("F5's saves never reuse a name: a second save in the same second is <name>-2.json",
          "[unit][game][replay]") {
  const auto level = level_01();
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("tire-f5-test-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const std::filesystem::path level_file = std::filesystem::path(TIRE_LEVELS_DIR) / "01-first-roll.json";
  SessionRecorder recorder;
  recorder.begin(level_file, level->gravity);
  std::unique_ptr<tire::Simulation> session = std::make_unique<tire::Simulation>(level);
  std::vector<std::filesystem::path> saved;
  for (int save = 0; save < 3; ++save) {
    for (int t = 0; t < 10; ++t) {
      recorder.on_step(session->tick(), {1.0, false});
      session->step({1.0, false});
      recorder.on_stepped(*session);
    }
    // The same name each time, as default_file gives within one second.
    std::string error;
    const auto file =
        recorder.save_new(*session, dir / "replays" / "01-first-roll-20240101-120000.json", error);
    INFO(error);
    REQUIRE(file);
    saved.push_back(*file);
  }
  CHECK(saved[0].filename() == "01-first-roll-20240101-120000.json");
  CHECK(saved[1].filename() == "01-first-roll-20240101-120000-2.json");
  CHECK(saved[2].filename() == "01-first-roll-20240101-120000-3.json");
  // Each holds its own save, and names the level relative to itself.
  for (std::size_t i = 0; i < saved.size(); ++i) {
    const tire::ReplayLoad load = tire::load_replay_file(saved[i]);
    REQUIRE(load.replay);
    CHECK(load.replay->ticks == 10 * (i + 1));
    CHECK(std::filesystem::equivalent(saved[i].parent_path() / load.replay->level, level_file));
  }
  std::filesystem::remove_all(dir);
}

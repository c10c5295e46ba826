// The game's logic that needs no window: the --press parser, tuning changes (and the waking they
// do), the session's event routing and interpolation, hot reload, the level list, the camera, the
// frame-time statistics, the HUD's sleep line, the sleeping shade and the picture small tires are
// drawn with.
#define CATCH_CONFIG_MAIN
#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <fstream>
#include <thread>

#include "app/frame_stats.h"
#include "app/hot_reload.h"
#include "app/level_list.h"
#include "app/menus.h"
#include "input/key_script.h"
#include "internals.h"
#include "play/game_session.h"
#include "play/tuning.h"
#include "render/camera.h"
#include "render/draw.h"
#include "render/hud.h"
#include "render/renderer.h"
#include "tire/tire/parameters.h"

using namespace game;

namespace {

std::shared_ptr<const tire::Level> flat_level() {
  const tire::LevelLoad load = tire::load_level_text(
      R"({"name": "Flat", "tires": [{"position": [0, 0.5]}], "obstacles": [{"min": [-20, -1], "max": [20, 0]}]})",
      "flat.json");
  REQUIRE(load.level);
  return std::make_shared<const tire::Level>(*load.level);
}

struct Recorder : SessionObserver {
  std::vector<std::pair<std::uint64_t, std::size_t>> batches;  // tick, event count
  std::vector<std::uint64_t> steps;
  void on_events(std::uint64_t tick, const std::vector<SessionEvent>& events) override {
    batches.emplace_back(tick, events.size());
  }
  void on_step(std::uint64_t tick, const tire::TickInput&) override { steps.push_back(tick); }
  void on_stepped(const tire::Simulation&) override {}
};

// Steps the session, no key held, until every tire has come to rest and fallen asleep.
void put_to_sleep(GameSession& session) {
  const std::size_t tires = world_of(session).tires().size();
  for (int i = 0; i < 900 && world_of(session).asleep_count() < tires; ++i) session.step({});
  for (const tire::Tire& t : world_of(session).tires())
    UNSCOPED_INFO("tire " << t.id << " at " << t.centroid().x << ", " << t.centroid().y << " moving "
                          << tire::length(t.velocity()) << " m/s, still " << t.still_time << " s");
  REQUIRE(world_of(session).asleep_count() == tires);
}

}  // namespace

TEST_CASE("press specs (--press KEY:FRAMES) parse into key and frames", "[unit][game]") {
  std::string error;
  const auto range = parse_key_press("right:0-300", error);
  REQUIRE(range);
  CHECK(range->key == SDL_SCANCODE_RIGHT);
  CHECK(range->first == 0);
  CHECK(range->last == 300);
  const auto single = parse_key_press("Space:120", error);
  REQUIRE(single);
  CHECK(single->key == SDL_SCANCODE_SPACE);
  CHECK(single->first == 120);
  CHECK(single->last == 120);
  CHECK(parse_key_press("period:3", error)->key == SDL_SCANCODE_PERIOD);
  CHECK(parse_key_press("esc:3", error)->key == SDL_SCANCODE_ESCAPE);
  CHECK(parse_key_press("f2:3", error)->key == SDL_SCANCODE_F2);

  CHECK_FALSE(parse_key_press("right", error));
  CHECK_THAT(error, Catch::Contains("KEY:FRAME"));
  CHECK_FALSE(parse_key_press("nosuchkey:1", error));
  CHECK_THAT(error, Catch::Contains("unknown key"));
  CHECK_FALSE(parse_key_press("right:9-3", error));
  CHECK_FALSE(parse_key_press("right:-3", error));
  CHECK_FALSE(parse_key_press("right:x", error));
}

TEST_CASE("a key script presses and releases on the right frames", "[unit][game]") {
  KeyScript script;
  std::string error;
  script.add(*parse_key_press("right:0-2", error));
  script.add(*parse_key_press("space:1", error));
  CHECK(script.events_at(0).size() == 1);
  CHECK(script.events_at(0)[0].down);
  const auto frame1 = script.events_at(1);
  REQUIRE(frame1.size() == 1);
  CHECK(frame1[0].key == SDL_SCANCODE_SPACE);
  const auto frame2 = script.events_at(2);  // space goes up
  REQUIRE(frame2.size() == 1);
  CHECK_FALSE(frame2[0].down);
  const auto frame3 = script.events_at(3);  // right goes up
  REQUIRE(frame3.size() == 1);
  CHECK(frame3[0].key == SDL_SCANCODE_RIGHT);
  CHECK_FALSE(frame3[0].down);
  CHECK(script.events_at(4).empty());
}

TEST_CASE("tuning changes are key = value pairs that reach every tire", "[unit][game]") {
  GameSession session;
  session.start("flat.json", flat_level());
  session.queue(SpawnTireEvent{{3, 2}});
  session.flush();
  REQUIRE(world_of(session).tires().size() == 2);

  Tuning wanted = session.tuning();
  REQUIRE(wanted.set("tires.pressure", 1.5));
  REQUIRE(wanted.set("tires.mass_scale", 2.0));
  REQUIRE(wanted.set("tires.friction", 0.3));
  REQUIRE(wanted.set("gravity.y", -3.0));
  REQUIRE(wanted.set("solver.substeps", 12));
  REQUIRE(wanted.set("tires.compliance.spoke", 1e-4));
  const std::vector<TuneEvent> changes = tuning_changes(session.tuning(), wanted);
  CHECK(changes.size() == 6);
  for (const TuneEvent& e : changes) session.queue(e);
  session.flush();

  for (const tire::Tire& t : world_of(session).tires()) {
    CHECK(t.spec.pressure == 1.5);
    CHECK(t.spec.mass == Approx(20.0));  // default spec mass 10 kg, times 2
    CHECK(t.spec.friction == 0.3);
    CHECK(t.spec.kinetic_friction == 0.3);
    CHECK(t.spec.compliance.spoke == 1e-4);
  }
  CHECK(world_of(session).gravity().y == -3.0);
  CHECK(world_of(session).config().substeps == 12);
  CHECK(tuning_value(session.tuning(), "tires.mass_scale") == 2.0);

  // Scaling again multiplies the spawn mass, not the current one.
  session.queue(TuneEvent{"tires.mass_scale", 0.5});
  session.flush();
  CHECK(world_of(session).tires()[0].spec.mass == Approx(5.0));
  // An unknown key changes nothing.
  session.queue(TuneEvent{"tires.nonsense", 1.0});
  session.flush();
  CHECK(tuning_value(session.tuning(), "tires.mass_scale") == 0.5);
  // Nor does a value outside the parameter table's range (a mass scale of 0 would divide by it).
  session.queue(TuneEvent{"tires.mass_scale", 0.0});
  session.flush();
  CHECK(tuning_value(session.tuning(), "tires.mass_scale") == 0.5);
  CHECK(world_of(session).tires()[0].spec.mass == Approx(5.0));
}

TEST_CASE("the tuning panel's keys are the parameter table's, its sliders inside the table's ranges",
          "[unit][game]") {
  // Every key is a row of the table that the panel may set, and every such row is a key.
  std::vector<std::string> expected;
  for (const tire::Parameter& p : tire::parameters())
    if (p.may(tire::by_panel)) expected.emplace_back(p.key);
  CHECK(tuning_keys() == expected);
  // A fresh Tuning holds the table's defaults.
  const Tuning defaults;
  for (const tire::TunableParameter* p : tuning_parameters())
    CHECK(tuning_value(defaults, p->key) == p->default_value);
  for (const tire::TunableParameter* p : tuning_parameters()) {
    INFO(p->key);
    // Each has a slider of its own, in one of the panel's sections, that never leaves the range.
    const SliderSpec* spec = slider_spec(p->key);
    REQUIRE(spec != nullptr);
    CHECK(std::find_if(slider_sections().begin(), slider_sections().end(), [&](const char* s) {
            return std::string_view(s) == spec->section;
          }) != slider_sections().end());
    CHECK(p->range.contains(spec->min));
    CHECK(p->range.contains(spec->max));
    const SliderRange range = slider_range(*p);
    CHECK(range.min == spec->min);
    CHECK(range.max == spec->max);
    CHECK(spec->min < spec->max);
    CHECK(spec->scale == (p->integer ? SliderScale::integer : spec->scale));
    if (spec->scale == SliderScale::exponent) CHECK(spec->min > 0.0);
  }
  // The table's range, not the slider's, is what a change must keep to.
  GameSession session;
  session.start("flat.json", flat_level());
  for (const tire::TunableParameter* p : tuning_parameters()) {
    INFO(p->key);
    CHECK_FALSE(apply_tuning(session.simulation(), p->key, p->range.max + 1.0));
  }
}

TEST_CASE("every input reaches the world through the session, between ticks", "[unit][game]") {
  GameSession session;
  Recorder recorder;
  session.set_observer(&recorder);
  session.start("flat.json", flat_level());
  const std::uint64_t first_generation = session.generation();

  session.queue(SpawnTireEvent{{2, 3}});
  session.queue(GrabEvent{{0, 0.5}, 0.3});
  session.queue(MoveGrabEvent{{0, 1.0}});
  session.queue(MoveGrabEvent{{0, 2.0}});  // collapses into the previous move
  session.step({1.0, false});
  REQUIRE(recorder.batches.size() == 1);
  CHECK(recorder.batches[0] == std::make_pair(std::uint64_t{0}, std::size_t{3}));
  CHECK(recorder.steps == std::vector<std::uint64_t>{0});
  CHECK(world_of(session).tires().size() == 2);
  CHECK(world_of(session).tires()[0].grabbed);
  CHECK(world_of(session).tires()[0].grab_target == tire::Vec2{0, 2.0});

  session.queue(ReleaseGrabEvent{});
  session.step({});
  CHECK_FALSE(world_of(session).tires()[0].grabbed);

  // A level load starts a fresh world.
  session.queue(LoadLevelEvent{"flat.json", session.level_ptr()});
  session.flush();
  CHECK(session.generation() == first_generation + 1);
  CHECK(world_of(session).tick() == 0);
  CHECK(world_of(session).tires().size() == 1);
}

TEST_CASE("a run the tuning panel changed is marked tuned until the level restarts", "[unit][game]") {
  // The app does not record a tuned run's time as a best time (App::level_finished).
  GameSession session;
  session.start("flat.json", flat_level());
  session.step({});
  CHECK_FALSE(session.tuned());
  session.queue(TuneEvent{"solver.substeps", 1e9});  // refused by the table: changes nothing
  session.step({});
  CHECK_FALSE(session.tuned());
  session.queue(TuneEvent{"gravity.y", -3.0});
  session.step({});
  CHECK(session.tuned());
  session.queue(LoadLevelEvent{"flat.json", session.level_ptr()});  // R: the level as written again
  session.flush();
  CHECK_FALSE(session.tuned());
}

TEST_CASE("drawing interpolates between the last two ticks", "[unit][game]") {
  GameSession session;
  session.start("flat.json", flat_level());
  const tire::TireView t = *session.simulation().tire_at(0);
  std::vector<tire::Vec2> out;
  session.interpolated_positions(t, 0.5, out);  // no previous tick yet: as it is
  CHECK(std::ranges::equal(out, t.positions));
  for (int i = 0; i < 30; ++i) session.step({1.0, false});
  const tire::TireView moved = *session.simulation().tire_at(0);
  const std::vector<tire::Vec2> now(moved.positions.begin(), moved.positions.end());
  session.interpolated_positions(moved, 1.0, out);
  CHECK(out == now);
  session.interpolated_positions(moved, 0.0, out);
  CHECK(out != now);
  const tire::Vec2 half = session.interpolated_centroid(moved, 0.5);
  const tire::Vec2 before = session.interpolated_centroid(moved, 0.0);
  const tire::Vec2 after = moved.centroid;
  CHECK(half.x == Approx(0.5 * (before.x + after.x)));
}

TEST_CASE("hot reload notices a changed file once", "[unit][game]") {
  const auto file = std::filesystem::temp_directory_path() / "tire-game-hot-reload-test.json";
  { std::ofstream(file) << "{}"; }
  HotReload watcher(1.0);
  watcher.watch(file);
  CHECK_FALSE(watcher.poll(0.0));
  { std::ofstream(file) << "{\"changed\": true}"; }  // a different size, whatever the clock's resolution
  CHECK_FALSE(watcher.poll(0.5));                    // not yet time to look
  CHECK(watcher.poll(1.0));
  CHECK_FALSE(watcher.poll(2.0));
  std::filesystem::remove(file);
  CHECK_FALSE(watcher.poll(3.0));  // a vanished file is not a change
}

TEST_CASE("the level list is sorted by file name and names each level", "[unit][game]") {
  const auto dir = std::filesystem::temp_directory_path() / "tire-game-level-list-test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  { std::ofstream(dir / "02-b.json") << R"({"name": "Bee"})"; }
  { std::ofstream(dir / "01-a.json") << R"({"name": "Ay"})"; }
  { std::ofstream(dir / "03-broken.json") << R"({"name": )"; }
  { std::ofstream(dir / "notes.txt") << "not a level"; }
  const std::vector<LevelEntry> levels = scan_levels(dir);
  REQUIRE(levels.size() == 3);
  CHECK(levels[0].name == "Ay");
  CHECK(levels[1].name == "Bee");
  CHECK_FALSE(levels[2].valid);
  CHECK(levels[2].name == "03-broken.json");
  CHECK(find_level(levels, dir / "02-b.json") == std::optional<std::size_t>{1});
  CHECK_FALSE(find_level(levels, dir / "nope.json"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("the camera scales with the window and stays inside the level", "[unit][game]") {
  Camera camera;
  camera.resize(1280, 720);
  CHECK(camera.scale() == Approx(720 / Camera::kViewHeight));
  camera.resize(640, 720);  // narrow: the width decides
  CHECK(camera.scale() == Approx(640 / Camera::kViewWidth));
  camera.resize(1280, 720);
  const tire::Aabb bounds{{-50, -2}, {50, 4}};  // lower than the view: rests on its bottom
  camera.snap({-49, 0}, bounds);
  CHECK(camera.view().min.x == Approx(-50));
  CHECK(camera.view().min.y == Approx(-2));
  // A point maps to the screen and back.
  const ScreenPoint p = camera.to_screen({-45, 1});
  const tire::Vec2 back = camera.to_world(p.x, p.y);
  CHECK(back.x == Approx(-45).margin(1e-4));
  CHECK(back.y == Approx(1).margin(1e-4));
  CHECK(p.y < camera.to_screen({-45, 0}).y);  // y up in the world is up on the screen
}

TEST_CASE("the 300-tire level is all on one screen at the game's zoom", "[unit][game]") {
  const tire::LevelLoad load =
      tire::load_level_file(std::filesystem::path(TIRE_LEVELS_DIR) / "08-three-hundred.json");
  REQUIRE(load.level);
  const tire::Simulation simulation(std::make_shared<const tire::Level>(*load.level));
  const tire::Aabb bounds = level_bounds(simulation);
  const tire::Tire* player = world_of(simulation).player();
  REQUIRE(player);
  // 16:9, 4:3 and a tall window: the walls (x in [-4.5, 4.5]), the floor and the height the pile
  // reaches (about 3.5 m) are in view while the player waits at the gate.
  for (const auto& [w, h] : {std::pair{1280, 720}, std::pair{1024, 768}, std::pair{1920, 1080}}) {
    Camera camera;
    camera.resize(w, h);
    camera.snap(camera.aim(player->centroid(), {}), bounds);
    for (int i = 0; i < 300; ++i) camera.follow(camera.aim(player->centroid(), {}), bounds, 1.0 / 60.0);
    INFO(w << "x" << h);
    CHECK(camera.view().min.x <= -4.5);
    CHECK(camera.view().max.x >= 4.5);
    CHECK(camera.view().min.y <= 0.0);
    CHECK(camera.view().max.y >= 4.5);
  }
}

TEST_CASE("frame times: median and p99 by nearest rank, in a buffer reserved up front", "[unit][game]") {
  std::vector<double> values;
  for (int i = 100; i >= 1; --i) values.push_back(i);
  CHECK(percentile(values, 0.5) == 50);
  CHECK(percentile(values, 0.99) == 99);
  CHECK(percentile(values, 1.0) == 100);
  std::vector<double> none;
  CHECK(percentile(none, 0.5) == 0);

  FrameStats stats;
  stats.add({1, 1, 1, 1});  // never reserved: kept nowhere, and nothing allocated
  CHECK(stats.size() == 0);
  stats.reserve(4);
  const std::size_t capacity = stats.capacity();
  for (float ms : {4.0f, 1.0f, 3.0f, 2.0f}) stats.add({ms, 2 * ms, 0.5f * ms, 3 * ms});
  CHECK(stats.sim().median == 2);
  CHECK(stats.sim().p99 == 4);
  CHECK(stats.render().median == 4);
  CHECK(stats.present().max == 2);
  CHECK(stats.frame().max == 12);
  // Full: the oldest frame (4 ms) makes room for the newest.
  stats.add({10, 20, 5, 30});
  CHECK(stats.size() == 4);
  CHECK(stats.capacity() == capacity);
  CHECK(stats.sim().max == 10);
  CHECK(stats.sim().median == 2);
  // The last frames, newest first across the ring's wrap: 10 then 2, then 3.
  CHECK(stats.sim_last(1).max == 10);
  CHECK(stats.sim_last(2).median == 2);
  CHECK(stats.sim_last(3).max == 10);
  CHECK(stats.sim_last(3).median == 3);
  CHECK(stats.sim_last(99).median == stats.sim().median);
  stats.clear();
  CHECK(stats.sim().median == 0);
}

TEST_CASE("the picture of a small tire: hub cap, rim with spokes, sidewall, tread blocks", "[unit][game]") {
  TireLook look;
  look.inner_ratio = 0.6;
  look.radius_pixels = 32;
  const auto same = [](SDL_Color a, SDL_Color b) {
    return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
  };
  const SDL_Color cap = tire_texel(0, 0, look);
  const SDL_Color rim = tire_texel(0.3, 0.3, look);       // r = 0.42, between the spokes
  const SDL_Color spoke = tire_texel(0.45, 0.0, look);    // on the spoke along x
  const SDL_Color sidewall = tire_texel(0.0, 0.7, look);  // between the rim and the tread band
  CHECK(same(rim, look.rim));
  CHECK_FALSE(same(spoke, rim));
  CHECK_FALSE(same(cap, rim));
  CHECK_FALSE(same(sidewall, rim));
  // Round the tread the blocks alternate.
  int changes = 0;
  const auto at = [&](int degree) {
    const double a = (degree + 0.5) * 3.14159265358979 / 180.0;  // never on a block's edge
    return tire_texel(0.95 * std::cos(a), 0.95 * std::sin(a), look);
  };
  SDL_Color last = at(359);
  for (int i = 0; i < 360; ++i) {
    const SDL_Color c = at(i);
    if (!same(c, last)) ++changes;
    last = c;
  }
  CHECK(changes == look.tread_blocks);
  // The image is opaque everywhere, so the tires can be drawn without blending.
  std::vector<std::uint32_t> pixels;
  tire_image(look, 32, pixels);
  REQUIRE(pixels.size() == 32u * 32u);
  for (std::uint32_t p : pixels) CHECK(reinterpret_cast<const std::uint8_t*>(&p)[3] == 255);
}

TEST_CASE("every tuning change the session applies wakes the sleeping tires, and a refused one does not",
          "[unit][game]") {
  const auto two_tires = [](GameSession& session) {
    session.start("flat.json", flat_level());
    session.queue(SpawnTireEvent{{3, 2}});
    session.flush();
    REQUIRE(world_of(session).tires().size() == 2);
  };
  // A key of each kind: a tire's, the one friction slider (two keys), the solver's, the gravity,
  // the sleep checkbox. Each on a session of its own (a sideways gravity rolls the tires away).
  for (const TuneEvent& change :
       {TuneEvent{"tires.pressure", 1.2}, TuneEvent{"tires.friction", 0.4}, TuneEvent{"solver.substeps", 9},
        TuneEvent{"gravity.x", 1.0}, TuneEvent{std::string(kSleepKey), 0.0},
        TuneEvent{std::string(kSleepKey), 1.0}, TuneEvent{std::string(kRollingHoldKey), 1.0}}) {
    INFO(change.key << " = " << change.value);
    GameSession session;
    two_tires(session);
    put_to_sleep(session);
    session.queue(change);
    session.flush();
    CHECK(tuning_value(session.tuning(), change.key) == change.value);
    CHECK(world_of(session).asleep_count() == 0);
    for (const tire::Tire& t : world_of(session).tires()) CHECK_FALSE(t.asleep);
  }
  // Changes the world refuses change nothing, and wake nothing.
  GameSession session;
  two_tires(session);
  put_to_sleep(session);
  for (const TuneEvent& refused :
       {TuneEvent{"tires.nonsense", 1.0}, TuneEvent{"tires.mass_scale", 0.0},
        TuneEvent{std::string(kSleepKey), 0.5}, TuneEvent{std::string(kRollingHoldKey), 0.5}}) {
    session.queue(refused);
    session.flush();
  }
  CHECK(world_of(session).asleep_count() == 2);
  CHECK(world_of(session).config().sleep);
}

TEST_CASE("the sleep and rolling hold checkboxes are SolverConfig's flags, carried as key = 1 or 0",
          "[unit][game]") {
  struct Checkbox {
    std::string_view key;
    bool Tuning::*tuned;
    bool tire::SolverConfig::*config;
  };
  for (const Checkbox box :
       {Checkbox{kSleepKey, &Tuning::sleep, &tire::SolverConfig::sleep},
        Checkbox{kRollingHoldKey, &Tuning::rolling_hold, &tire::SolverConfig::rolling_hold}}) {
    INFO(box.key);
    GameSession session;
    session.start("flat.json", flat_level());
    const bool engine_default = tire::SolverConfig{}.*box.config;
    REQUIRE(world_of(session).config().*box.config == engine_default);
    const Tuning level = session.tuning();
    CHECK(level.*box.tuned == engine_default);
    CHECK(Tuning().*box.tuned == engine_default);
    CHECK(tuning_value(level, box.key) == (engine_default ? 1.0 : 0.0));

    Tuning flipped = session.tuning();
    flipped.*box.tuned = !engine_default;
    const std::vector<TuneEvent> changes = tuning_changes(session.tuning(), flipped);
    REQUIRE(changes.size() == 1);
    CHECK(changes[0].key == box.key);
    CHECK(changes[0].value == (engine_default ? 0.0 : 1.0));
    session.queue(changes[0]);
    session.flush();
    CHECK(world_of(session).config().*box.config == !engine_default);
    CHECK(session.tuning() == flipped);
    // A freshly loaded world's tuning reads the flag from the world.
    CHECK(Tuning::from_simulation(session.simulation()).*box.tuned == !engine_default);

    // "Reset to the level's values" puts it back.
    for (const TuneEvent& e : tuning_changes(session.tuning(), level)) session.queue(e);
    session.flush();
    CHECK(world_of(session).config().*box.config == engine_default);
    CHECK(session.tuning() == level);
  }
}

TEST_CASE("the HUD counts the sleeping tires, when there are tires", "[unit][game]") {
  char line[64] = "untouched";
  CHECK_FALSE(format_asleep_line(line, 0, 0));
  CHECK(std::string_view(line) == "untouched");
  REQUIRE(format_asleep_line(line, 123, 300));
  CHECK(std::string_view(line) == "asleep     123 / 300");
  REQUIRE(format_asleep_line(line, 0, 1));
  CHECK(std::string_view(line) == "asleep       0 / 1");
  // Too small a buffer: cut, still terminated.
  char small[8];
  REQUIRE(format_asleep_line(small, 5, 10));
  CHECK(std::string_view(small) == "asleep ");

  // Fed from the world: tires come to rest and fall asleep.
  GameSession session;
  session.start("flat.json", flat_level());
  session.queue(SpawnTireEvent{{3, 2}});
  session.flush();
  put_to_sleep(session);
  REQUIRE(format_asleep_line(line, world_of(session).asleep_count(), world_of(session).tires().size()));
  CHECK(std::string_view(line) == "asleep       2 / 2");
}

TEST_CASE("the debug view's shade of a sleeping tire is darker in every channel, alpha kept",
          "[unit][game]") {
  for (const SDL_Color c :
       {rgba(255, 255, 255, 220), rgba(0, 200, 255), rgba(176, 182, 194), rgba(38, 38, 42)}) {
    const SDL_Color s = asleep_shade(c);
    CHECK(s.a == c.a);
    CHECK(s.r <= c.r);
    CHECK(s.g <= c.g);
    CHECK(s.b <= c.b);
    // Enough to see: at least a quarter less light.
    CHECK(s.r + s.g + s.b <= 0.75 * (c.r + c.g + c.b));
  }
}

TEST_CASE("the HUD counts a time limit down and the end screen names what ended the level", "[unit][game]") {
  char line[64];
  format_clock_line(line, 12.345, std::nullopt);
  CHECK(std::string_view(line) == "time        12.35 s");
  format_clock_line(line, 12.345, 60.0);
  CHECK(std::string_view(line) == "time left   47.7 s");
  format_clock_line(line, 61.0, 60.0);  // never below zero
  CHECK(std::string_view(line) == "time left    0.0 s");
  CHECK(time_left(60.0, 59.5) == 0.5);
  using tire::EndReason;
  using tire::ScriptStatus;
  CHECK(std::string_view(end_title(ScriptStatus::lost, EndReason::time_limit)) == "Time's up");
  CHECK(std::string_view(end_title(ScriptStatus::lost, EndReason::out_of_bounds)) == "Off the edge");
  CHECK(std::string_view(end_title(ScriptStatus::lost, EndReason::lose_action)) == "You lost");
  CHECK(std::string_view(end_title(ScriptStatus::won, EndReason::goal)) == "Level complete!");
  // And the session says which: level 01, standing still, runs out of time.
  const tire::LevelLoad load =
      tire::load_level_file(std::filesystem::path(TIRE_LEVELS_DIR) / "01-first-roll.json");
  REQUIRE(load.level);
  GameSession session;
  session.start("01.json", std::make_shared<const tire::Level>(*load.level));
  for (int i = 0; i < 4000 && session.simulation().status() == ScriptStatus::running; ++i) session.step({});
  CHECK(session.simulation().end_reason() == EndReason::time_limit);
}

TEST_CASE("a chasm is drawn open to the deep, rock only under the ground", "[unit][game]") {
  // Level 02 drawn into memory: its chasm (x 30 to 34.5) between two stretches of ground whose
  // bottom is y = -1, with a catch floor far down (y -12 to -11).
  const tire::LevelLoad load =
      tire::load_level_file(std::filesystem::path(TIRE_LEVELS_DIR) / "02-jumps.json");
  REQUIRE(load.level);
  GameSession session;
  session.start("02.json", std::make_shared<const tire::Level>(*load.level));
  const Underground ground = underground(session.simulation());
  CHECK(ground.floor == -1.0);
  CHECK(ground.surface == 0.0);
  SDL_Surface* surface = SDL_CreateRGBSurfaceWithFormat(0, 400, 300, 32, SDL_PIXELFORMAT_RGBA32);
  REQUIRE(surface);
  SDL_Renderer* renderer = SDL_CreateSoftwareRenderer(surface);
  REQUIRE(renderer);
  {
    Draw draw(renderer);
    WorldRenderer world_renderer;
    world_renderer.set_underground(ground);
    Camera camera;
    camera.resize(400, 300);
    camera.set_view({32, -6}, 20.0);  // x 22 to 42, y -13.5 to 1.5
    world_renderer.draw(draw, camera, session, 1.0, DebugOptions{});
    draw.flush();
    const auto pixel = [&](tire::Vec2 world) {
      const ScreenPoint p = camera.to_screen(world);
      const auto* row =
          static_cast<const std::uint8_t*>(surface->pixels) + static_cast<int>(p.y) * surface->pitch;
      const std::uint8_t* c = row + 4 * static_cast<int>(p.x);
      return SDL_Color{c[0], c[1], c[2], c[3]};
    };
    const auto brightness = [](SDL_Color c) { return c.r + c.g + c.b; };
    const SDL_Color under_ground = pixel({25, -6}), in_chasm = pixel({32, -6}), chasm_top = pixel({32, -0.5}),
                    under_catch_floor = pixel({32, -12.8});
    INFO("under the ground " << int(under_ground.r) << "," << int(under_ground.g) << ","
                             << int(under_ground.b) << "; in the chasm " << int(in_chasm.r) << ","
                             << int(in_chasm.g) << "," << int(in_chasm.b));
    // Rock under the ground: brown, red above blue.
    CHECK(under_ground.r > under_ground.b + 10);
    // The chasm, 5 m below the floor: the deep, darker than the rock and bluish, not rock.
    CHECK(brightness(in_chasm) < brightness(under_ground));
    CHECK(in_chasm.b > in_chasm.r);
    // At the chasm's lip it is still sky; under the catch floor at its bottom, rock again.
    CHECK(chasm_top.b > 180);
    CHECK(under_catch_floor.r > under_catch_floor.b + 10);
    world_renderer.release();
  }
  SDL_DestroyRenderer(renderer);
  SDL_FreeSurface(surface);
}

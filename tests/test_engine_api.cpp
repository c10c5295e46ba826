// The façade (tire/engine.h), as a program that embeds the engine uses it: only its header.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "tire/engine.h"

using namespace tire;

namespace {
const std::filesystem::path kRoot = TIRE_SOURCE_DIR;
}

TEST_CASE("a level loads into a simulation that plays it as tirectl does", "[unit][api]") {
  SimulationLoad load = Simulation::load(kRoot / "levels/01-first-roll.json");
  REQUIRE(load.errors.empty());
  REQUIRE(load.simulation);
  Simulation& sim = *load.simulation;
  REQUIRE(sim.player());
  const TireView start = *sim.tire(*sim.player());
  CHECK(start.player);
  CHECK(start.positions.size() == 2 * start.segments);
  for (int i = 0; i < 120; ++i) sim.step({.steer = 1.0});
  const TireView end = *sim.tire(*sim.player());
  CHECK(end.centroid.x > start.centroid.x + 5.0);  // rolled right
  CHECK(sim.tick() == 120);
  CHECK(sim.status() == ScriptStatus::running);
  // The hash examples/minimal prints and tools/check-install compares with tirectl's.
  CHECK(sim.state_hash() == 0xc650edb4f9d829eaull);
}

TEST_CASE("a bad level gives its errors and no simulation", "[unit][api]") {
  SimulationLoad load = Simulation::load(kRoot / "tests/levels/bad-segments.json");
  CHECK_FALSE(load.simulation);
  REQUIRE_FALSE(load.errors.empty());
  CHECK(load.errors.front().find("bad-segments.json") != std::string::npos);
  SimulationLoad missing = Simulation::load(kRoot / "levels/no-such-level.json");
  CHECK_FALSE(missing.simulation);
  CHECK_FALSE(missing.errors.empty());
}

TEST_CASE("a world built in code is read through ids and views and driven by commands", "[unit][api]") {
  Simulation sim(SolverConfig{}, {0.0, -9.81});
  sim.add_obstacle({{{-10.0, -1.0}, {10.0, 0.0}}});
  PropSpec crate;
  crate.type = PropType::dynamic_body;
  crate.position = {3.0, 0.5};
  const PropId crate_id = sim.add_prop(crate);
  TireSpec spec;
  spec.position = {0.0, 0.6};
  const TireId a = sim.add_tire(spec);
  spec.position = {-3.0, 0.6};
  const TireId b = sim.add_tire(spec);
  CHECK(sim.tires() == std::vector<TireId>{a, b});
  CHECK(sim.player() == a);  // the first tire
  CHECK_FALSE(sim.tire(999));
  CHECK(sim.prop_count() == 1);
  CHECK_FALSE(sim.prop(1));
  REQUIRE(sim.prop(crate_id));
  CHECK(sim.prop(crate_id)->type == PropType::dynamic_body);

  // Left alone, both settle on the ground and fall asleep.
  for (int i = 0; i < 300; ++i) sim.step();
  CHECK(sim.asleep_count() == 2);
  CHECK(sim.tire(a)->grounded);
  CHECK(sim.tire(a)->asleep);
  CHECK(sim.tire(a)->contacts.ground > 0.0);

  // The energy watch: the tires settled, losing some of what they were brought in with.
  const EnergyView settled = sim.energy();
  CHECK(settled.elastic >= 0.0);
  CHECK(settled.total() < settled.brought_in);

  // A command wakes what it moves: an impulse sends the sleeping tire off, and its energy is booked.
  CHECK(sim.apply_impulse(b, {50.0, 0.0}));
  CHECK(sim.energy().brought_in - settled.brought_in == Approx(sim.energy().total() - settled.total()));
  CHECK_FALSE(sim.tire(b)->asleep);
  for (int i = 0; i < 30; ++i) sim.step();
  CHECK(sim.tire(b)->centroid.x > -2.5);

  // Commands on what is not there are refused and change nothing.
  CHECK_FALSE(sim.apply_impulse(999, {1.0, 0.0}));
  CHECK_FALSE(sim.grab(a, 10'000, {0.0, 2.0}));
  CHECK_FALSE(sim.release(a));  // nothing grabbed
  CHECK(sim.grab(a, 0, {0.0, 2.0}));
  CHECK(sim.move_grab(a, {0.0, 2.5}));
  CHECK(sim.release(a));
  CHECK_FALSE(sim.set_parameter("tires.no_such_key", 1.0));
  CHECK(sim.set_parameter("tires.friction", 0.5));
  CHECK(sim.parameter("tires.friction") == 0.5);
  CHECK(sim.solver_failures() == 0);
  CHECK(sim.take_warnings().empty());
}

TEST_CASE("what a game draws and hears is read through views: tires, props, the script", "[unit][api]") {
  const LevelOpen open = open_level_file(kRoot / "levels/01-first-roll.json");
  REQUIRE(open.level);
  CHECK(open.info.tires == 1);
  CHECK_FALSE(open.info.bounds_min_given);  // computed from its geometry
  CHECK(open.info.bounds.min.y < 0.0);
  Simulation sim(open.level);

  // The tires, walked by index without a list; nullopt past the last.
  REQUIRE(sim.tire_count() == 1);
  const std::optional<TireView> player = sim.tire_at(0);
  REQUIRE(player);
  CHECK_FALSE(sim.tire_at(1));
  CHECK(player->player);
  CHECK(player->outer_radius > player->inner_radius);
  CHECK(player->inner_radius > 0.0);
  CHECK(player->mass > 0.0);
  CHECK_FALSE(player->grab);

  // The script: its regions and goal, and the message its start trigger shows.
  REQUIRE(sim.goal());
  REQUIRE(*sim.goal() < sim.regions().size());
  CHECK(sim.regions()[*sim.goal()].name == "flag");
  REQUIRE(sim.messages().size() == 1);
  CHECK(sim.messages().front().text.starts_with("Hold right"));
  CHECK_FALSE(sim.checkpoint());
  CHECK_FALSE(sim.next_level_requested());
  CHECK((!sim.obstacles().empty() || sim.prop_count() > 0));  // it has ground

  // A tire spawned within the budgets, a grab by a point near its tread, dragged and let go.
  TireSpec spec;
  spec.position = {5.0, 3.0};
  spec.player = false;
  const std::optional<TireId> spawned = sim.spawn_tire(spec);
  REQUIRE(spawned);
  CHECK(sim.tire_count() == 2);
  const std::optional<TireId> grabbed = sim.grab_at({5.0, 3.0 + sim.tire(*spawned)->outer_radius}, 0.3);
  CHECK(grabbed == spawned);
  sim.move_grab({5.0, 4.0});
  REQUIRE(sim.tire(*spawned)->grab);
  CHECK(sim.tire(*spawned)->grab->target == Vec2{5.0, 4.0});
  sim.release_grab();
  CHECK_FALSE(sim.tire(*spawned)->grab);
  CHECK_FALSE(sim.grab_at({-500.0, 500.0}, 0.3));  // nothing there

  // Sleeping off, then on: the setting follows, every tire awake.
  sim.set_sleep(false);
  CHECK_FALSE(sim.config().sleep);
  sim.set_sleep(true);
  CHECK(sim.config().sleep);
  sim.wake_all();
  CHECK(sim.asleep_count() == 0);
}

TEST_CASE("a prop's view holds its shape in its own frame", "[unit][api]") {
  Simulation sim(SolverConfig{}, {0.0, -9.81});
  PropSpec box;
  box.size = {2.0, 1.0};
  box.position = {1.0, 2.0};
  PropSpec wheel;
  wheel.shape = PropShape::circle;
  wheel.radius = 0.25;
  PropSpec ground;
  ground.shape = PropShape::chain;
  ground.points = {{-5.0, 0.0}, {0.0, -1.0}, {5.0, 0.0}};
  ground.thickness = 0.4;
  const std::optional<PropView> b = sim.prop(sim.add_prop(box));
  const std::optional<PropView> w = sim.prop(sim.add_prop(wheel));
  const std::optional<PropView> g = sim.prop(sim.add_prop(ground));
  REQUIRE((b && w && g));
  CHECK(b->vertices.size() == 4);
  CHECK(b->local_bounds.min == Vec2{-1.0, -0.5});
  CHECK(b->state.pose.position == Vec2{1.0, 2.0});
  CHECK(w->shape == PropShape::circle);
  CHECK(w->radius == 0.25);
  CHECK(w->vertices.empty());
  CHECK(g->vertices.size() == 3);
  CHECK(g->normals.size() == 2);
  CHECK(g->thickness == 0.4);
  CHECK_FALSE(g->loop);
  CHECK(g->path.empty());
}

TEST_CASE("a shipped replay checks out, and one whose level changed does not", "[unit][api]") {
  const ReplayCheck ok = check_replay(kRoot / "tests/replays/01-first-roll-goal.json");
  CHECK(ok.passed);
  CHECK(ok.errors.empty());
  CHECK(ok.status == "won");

  const ReplayCheck changed = check_replay(kRoot / "tests/replays-bad/level-changed.json");
  CHECK_FALSE(changed.passed);
  CHECK_FALSE(changed.errors.empty());

  const ReplayCheck missing = check_replay(kRoot / "tests/replays/no-such-replay.json");
  CHECK_FALSE(missing.passed);
  REQUIRE_FALSE(missing.errors.empty());
  CHECK(missing.errors.front().find("no-such-replay.json") != std::string::npos);
}

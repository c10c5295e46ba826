// Vehicles in levels (levels/README.md, "Vehicles"): the reader's errors, a level that drives, its
// replays with lean and brake, the driver's head, the respawn.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>

#include "error_messages.h"
#include "tire/engine.h"
#include "tire/replay/replay.h"
#include "tire/session/level_session.h"
#include "tire_fixtures.h"

using tire_test::has;
using tire_test::joined;

using namespace tire;
using namespace tire::test;
using json = nlohmann::json;

namespace {

// tests/levels/vehicle-car.json: a car, the player, on flat ground.
json car_level() {
  std::ifstream in(source_path("tests/levels/vehicle-car.json"));
  return json::parse(in);
}

std::vector<std::string> errors_of(const json& doc) { return load_level_text(doc.dump(), "v.json").errors; }

Level loaded(const json& doc) {
  const LevelLoad load = load_level_text(doc.dump(), "v.json");
  INFO(joined(load.errors));
  REQUIRE(load.level);
  return *load.level;
}

const VehicleJoints& joints(const LevelSession& s) { return s.world().vehicles(); }

PropState chassis(const LevelSession& s) { return s.world().rigid().prop_state(joints(s).chassis(0)); }

}  // namespace

TEST_CASE("vehicle levels: the car loads, its player is the vehicle, and full throttle drives it right",
          "[unit][vehicle_level]") {
  const SimulationLoad load = Simulation::load(source_path("tests/levels/vehicle-car.json"));
  INFO(joined(load.errors));
  REQUIRE(load.simulation);
  Simulation& sim = *load.simulation;
  const LevelOpen open = open_level_file(source_path("tests/levels/vehicle-car.json"));
  CHECK(open.info.player_vehicle);
  CHECK(open.info.vehicles == 1);
  CHECK(sim.vehicle_count() == 1);
  CHECK(!sim.player());  // no tire is the player
  const VehicleView start = *sim.vehicle_at(0);
  CHECK(start.player);
  CHECK(start.wheels().size() == 2);
  REQUIRE(start.head_center);
  CHECK(start.head_radius == 0.15);
  CHECK(!sim.vehicle_at(1));
  TickInput input;
  input.steer = 1.0;
  for (int i = 0; i < 240; ++i) sim.step(input);
  const VehicleView end = *sim.vehicle_at(0);
  CHECK(end.throttle == 1.0);
  CHECK(end.center.x > start.center.x + 5.0);
  CHECK(end.velocity.x > 2.0);
  CHECK(std::abs(end.pose.angle) < 0.3);
  CHECK(sim.status() == ScriptStatus::running);
  for (const TireId w : end.wheels()) CHECK(sim.tire(w)->centroid.x > 5.0);
}

TEST_CASE("vehicle levels: the reader's errors", "[unit][vehicle_level]") {
  const json level = car_level();
  REQUIRE(errors_of(level).empty());
  CHECK(loaded(level).vehicles.at(0).spec.wheels.at(1).axle.travel == 0.1);  // the sprung wheel's stop
  SECTION("too few wheels") {
    json doc = level;
    doc["vehicles"][0]["wheels"].erase(1);
    CHECK(has(errors_of(doc), "v.json: /vehicles/0/wheels: must be an array of 2 to 8 wheels, got 1"));
  }
  SECTION("too many wheels") {
    json doc = level;
    for (int i = 0; i < 7; ++i) doc["vehicles"][0]["wheels"].push_back(doc["vehicles"][0]["wheels"][0]);
    CHECK(has(errors_of(doc), "v.json: /vehicles/0/wheels: "));
  }
  SECTION("the method") {
    json doc = level;
    doc["solver"] = {{"method", "gauss-seidel"}};
    CHECK(has(errors_of(doc),
              "v.json: /vehicles: a level with vehicles needs the global solver method "
              "(\"solver\": {\"method\": \"global\"}), and this one's is \"gauss-seidel\""));
  }
  SECTION("two players: a tire and a vehicle, two vehicles") {
    json doc = level;
    doc["tires"] = {{{"position", {-5, 0.5}}, {"player", true}}};
    CHECK(has(errors_of(doc),
              "v.json: /vehicles/0/player: only one tire or vehicle may be the player, and "
              "/tires/0 already is"));
    json two = level;
    two["vehicles"].push_back(level["vehicles"][0]);
    two["vehicles"][1]["chassis"]["position"] = {5, 0.7};
    CHECK(has(errors_of(two),
              "v.json: /vehicles/1/player: only one tire or vehicle may be the player, and "
              "/vehicles/0 already is"));
  }
  SECTION("a key a wheel does not have, a key a chassis does not have") {
    json doc = level;
    doc["vehicles"][0]["wheels"][1]["position"] = {0, 0};
    doc["vehicles"][0]["chassis"]["type"] = "static";
    const auto errors = errors_of(doc);
    INFO(joined(errors));
    CHECK(has(errors,
              "v.json: /vehicles/0/wheels/1/position: unknown key; expected one of \"axle\", \"axis\""));
    CHECK(has(errors, "v.json: /vehicles/0/chassis/type: unknown key; expected one of \"shape\""));
  }
  SECTION("a shape key of another shape names the chassis") {
    json doc = level;
    doc["vehicles"][0]["chassis"]["radius"] = 0.5;
    CHECK(has(errors_of(doc),
              "v.json: /vehicles/0/chassis/radius: applies only to circle chassis, and this one "
              "is a box"));
  }
  SECTION("a wheel's tire keys keep their rules; its axis is a unit vector") {
    json doc = level;
    doc["vehicles"][0]["wheels"][0]["segments"] = 2;
    doc["vehicles"][0]["wheels"][0]["inner_radius"] = 0.5;
    doc["vehicles"][0]["wheels"][1]["axis"] = {0, 0};
    const auto errors = errors_of(doc);
    INFO(joined(errors));
    CHECK(has(errors, "v.json: /vehicles/0/wheels/0/segments: must be an integer in [6, 256], got 2"));
    CHECK(has(errors, "v.json: /vehicles/0/wheels/0/inner_radius: must be less than outer_radius"));
    CHECK(has(errors, "v.json: /vehicles/0/wheels/1/axis: must be a unit vector"));
    json nearly = level;
    nearly["vehicles"][0]["wheels"][1]["axis"] = {0.7071, 0.7071};
    const Level l = loaded(nearly);
    CHECK(std::abs(length(l.vehicles[0].spec.wheels[1].axle.axis) - 1.0) < 1e-15);
  }
  SECTION("a chassis is no chain; it needs its shape's key") {
    json doc = level;
    doc["vehicles"][0]["chassis"] = {{"shape", "chain"}, {"points", {{0, 0}, {1, 0}}}};
    CHECK(has(errors_of(doc),
              "v.json: /vehicles/0/chassis/shape: must be one of \"box\", \"circle\", \"polygon\""));
    json no_size = level;
    no_size["vehicles"][0]["chassis"].erase("size");
    CHECK(has(errors_of(no_size), "v.json: /vehicles/0/chassis/size: is required"));
  }
  SECTION("wheels count as tires in the budgets") {
    json doc = level;
    doc["budgets"] = {{"tires", 1}};
    CHECK(has(errors_of(doc),
              "v.json: /vehicles/0/wheels/1: the level's own tires are more than budgets.tires (1)"));
  }
  SECTION("the player vehicle starts inside the bounds") {
    json doc = level;
    doc["bounds"] = {{"min", {1, -5}}, {"max", {50, 50}}};
    CHECK(has(errors_of(doc),
              "v.json: /bounds/min: must be below and left of the player's start [0,0.7] "
              "(/vehicles/0/chassis/position)"));
  }
}

TEST_CASE("vehicle levels: a run with lean and brake records and replays to the same hash",
          "[unit][vehicle_level][replay]") {
  const Level level = loaded(car_level());
  std::vector<ReplayInput> inputs(4);
  inputs[0].steer = 1.0;
  inputs[1].tick = 40;
  inputs[1].lean = 0.5;
  inputs[2].tick = 80;
  inputs[2].brake = true;
  inputs[2].lean = -1.0;
  inputs[3].tick = 100;
  inputs[3].brake = false;
  ReplayRecorder recorder("vehicle-car.json", std::string(64, '0'), 30);
  auto session = make_session(level);
  InputFeed feed(inputs, &recorder);
  TickInput held;
  std::vector<TickInput> seen;
  for (int tick = 0; tick < 120; ++tick) {
    const TickInput& in =
        feed.next_tick([&](const ReplayInput& r, TickInput& h) { apply_input(r, *session, level, h); });
    held = in;
    seen.push_back(in);
    session->step(in);
    recorder.after_step(session->state_hash());
  }
  CHECK(seen[39].lean == 0.0);
  CHECK(seen[40].lean == 0.5);
  CHECK(seen[79].brake == false);
  CHECK(seen[80].brake);
  CHECK(seen[99].brake);
  CHECK(seen[99].lean == -1.0);  // holds
  CHECK(!seen[100].brake);
  const Replay recorded = recorder.finish(session->status(), session->state_hash());
  const std::string text = replay_to_json(recorded);
  CHECK(text.find("\"lean\": 0.5") != std::string::npos);
  CHECK(text.find("\"brake\": true") != std::string::npos);
  CHECK(text.find("\"brake\": false") != std::string::npos);
  const ReplayLoad reread = load_replay_text(text, "r.json");
  INFO(joined(reread.errors));
  REQUIRE(reread.replay);
  CHECK(replay_to_json(*reread.replay) == text);
  const ReplayOutcome outcome = run_replay(*reread.replay, level);
  INFO(joined(outcome.failures));
  CHECK(outcome.failures.empty());
  CHECK(outcome.hash == to_hex(session->state_hash()));

  // One lean and one brake per tick, each in its range.
  json doc = json::parse(text);
  doc["inputs"].push_back({{"tick", 110}, {"lean", 2}});
  doc["inputs"].push_back({{"tick", 111}, {"brake", 1}});
  doc["inputs"].push_back({{"tick", 112}, {"lean", 0.1}});
  doc["inputs"].push_back({{"tick", 112}, {"lean", 0.2}, {"brake", true}});
  doc["inputs"].push_back({{"tick", 112}, {"brake", false}});
  const auto errors = load_replay_text(doc.dump(), "r.json").errors;
  INFO(joined(errors));
  const std::size_t n = doc["inputs"].size();
  const auto at = [&](std::size_t from_end) { return "r.json: /inputs/" + std::to_string(n - from_end); };
  CHECK(has(errors, at(5) + "/lean: must be a number in [-1, 1], got 2"));
  CHECK(has(errors, at(4) + "/brake: must be true or false"));
  CHECK(has(errors, at(2) + "/lean: a second lean on tick 112 (the first is /inputs/" +
                        std::to_string(n - 3) + "/lean): only the last would act; give one lean per tick"));
  CHECK(has(errors, at(1) + "/brake: a second brake on tick 112 (the first is /inputs/" +
                        std::to_string(n - 2) + "/brake): only the last would act; give one brake per tick"));
}

TEST_CASE("vehicle levels: the driver's head touching the ground loses the level", "[unit][vehicle_level]") {
  json doc = car_level();
  // Upside down, half a metre up: it falls on its roof, head first.
  doc["vehicles"][0]["chassis"]["angle"] = 3.14159;
  doc["vehicles"][0]["chassis"]["position"] = {0, 1.2};
  const Level level = loaded(doc);
  auto session = make_session(level);
  int ticks = 0;
  while (session->status() == ScriptStatus::running && ticks < 120) {
    session->step({});
    ++ticks;
  }
  CHECK(session->status() == ScriptStatus::lost);
  CHECK(session->end_reason() == EndReason::head_hit);
  CHECK(std::string(to_string(EndReason::head_hit)) == "head_hit");
  REQUIRE(!session->messages().empty());
  CHECK(session->messages().back().text == "the driver's head hit the ground");
  CHECK(session->end_tick() == static_cast<std::uint64_t>(ticks));
  CHECK(ticks > 5);  // it fell first

  // Upright, it drives on without losing.
  auto upright = make_session(loaded(car_level()));
  run(*upright, 120, TickInput{1.0});
  CHECK(upright->status() == ScriptStatus::running);
}

TEST_CASE("vehicle levels: leaving the bounds respawns the vehicle at the checkpoint, at rest",
          "[unit][vehicle_level]") {
  json doc = car_level();
  doc["bounds"] = {{"min", {-10, -5}}, {"max", {4, 50}}};
  doc["triggers"] = {
      {{"when", {{"type", "start"}}}, {"do", {{{"action", "checkpoint"}, {"position", {-2, 0.8}}}}}}};
  const Level level = loaded(doc);
  auto session = make_session(level);
  int ticks = 0;
  while (session->respawns() == 0 && ticks < 600) {
    session->step(TickInput{1.0});
    ++ticks;
  }
  REQUIRE(session->respawns() == 1);
  CHECK(session->status() == ScriptStatus::running);
  const PropState c = chassis(*session);
  CHECK(c.pose.position.x == Approx(-2.0).margin(1e-5));
  CHECK(c.pose.position.y == Approx(0.8).margin(1e-5));
  CHECK(c.pose.angle == 0.0);
  CHECK(c.velocity.x == 0.0);
  CHECK(c.velocity.y == 0.0);
  CHECK(c.angular_velocity == 0.0);
  for (std::size_t w = 0; w < joints(*session).wheel_count(0); ++w) {
    const Tire& t = session->world().tires()[joints(*session).wheel_tire(0, w)];
    CHECK(length(t.centroid() - c.pose.to_world(joints(*session).axle(0, w).point)) < 1e-5);
    for (const Vec2 v : t.particles.v) CHECK(length(v) == 0.0);
  }
  CHECK(joints(*session).control(0).throttle == 0.0);
  // The player's position is the chassis' centre of mass.
  REQUIRE(session->player_position());
  CHECK(length(*session->player_position() - c.center) == 0.0);
  // It drives off again.
  run(*session, 60, TickInput{1.0});
  CHECK(chassis(*session).center.x > -1.0);
}

TEST_CASE("vehicle levels: the goal is reached by the vehicle's chassis", "[unit][vehicle_level]") {
  json doc = car_level();
  doc["regions"] = {{{"name", "finish"}, {"min", {6, -1}}, {"max", {8, 5}}}};
  doc["goal"] = "finish";
  auto session = make_session(loaded(doc));
  int ticks = 0;
  while (session->status() == ScriptStatus::running && ticks < 600) {
    session->step(TickInput{1.0});
    ++ticks;
  }
  CHECK(session->status() == ScriptStatus::won);
  CHECK(session->end_reason() == EndReason::goal);
  CHECK(chassis(*session).center.x >= 6.0);
}

TEST_CASE("vehicle levels: a script's impulse on a vehicle player moves the whole vehicle",
          "[unit][vehicle_level]") {
  // levels/SCRIPTING.md, "impulse": on a player vehicle, every body of it (the chassis, each wheel)
  // changes velocity by impulse / the vehicle's mass, so that its momentum changes by the impulse
  // and it does not turn; the energy it brings is booked.
  const double added = make_session(loaded(car_level()))->world().energy_in();  // the bodies' own
  json doc = car_level();
  doc["triggers"] = {{{"when", {{"type", "start"}}},
                      {"do", {{{"action", "impulse"}, {"target", "player"}, {"impulse", {120, 300}}}}}}};
  auto session = make_session(loaded(doc));  // the start trigger runs as the session starts
  const World& world = session->world();
  const PropState c = chassis(*session);
  double mass = c.mass;
  Vec2 momentum = c.velocity * c.mass;
  for (std::size_t w = 0; w < joints(*session).wheel_count(0); ++w) {
    const Tire& t = world.tires()[joints(*session).wheel_tire(0, w)];
    mass += t.total_mass();
    const double particle_mass = t.total_mass() / static_cast<double>(t.particles.size());
    for (std::size_t i = 0; i < t.particles.size(); ++i) momentum += t.particles.v[i] * particle_mass;
  }
  CHECK(momentum.x == Approx(120.0).epsilon(1e-6));
  CHECK(momentum.y == Approx(300.0).epsilon(1e-6));
  CHECK(c.velocity.x == Approx(120.0 / mass).epsilon(1e-6));  // Box2D keeps floats
  CHECK(c.velocity.y == Approx(300.0 / mass).epsilon(1e-6));
  CHECK(c.angular_velocity == 0.0);
  CHECK(world.energy_in() - added == Approx(0.5 * (120.0 * 120.0 + 300.0 * 300.0) / mass).epsilon(1e-5));
}

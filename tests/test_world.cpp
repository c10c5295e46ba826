// The world: tires come and go between ticks; the player is well defined.
#include <catch2/catch.hpp>

#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

TEST_CASE("tires can be added and removed while the world steps", "[unit][world]") {
  TireSpec spec;
  spec.position = {0, 0.5};
  World world = flat_world(spec);
  run(world, 30);
  const TireId second = world.add_tire(tire_at({3, 2}));
  run(world, 30);
  CHECK(world.tires().size() == 2);
  CHECK(world.find_tire(second)->centroid().y < 2.0);
  CHECK(world.remove_tire(second));
  CHECK_FALSE(world.remove_tire(second));
  run(world, 30);
  CHECK(world.tires().size() == 1);
  const TireId third = world.add_tire(tire_at({-3, 2}));
  CHECK(third != second);  // ids are never reused
}

TEST_CASE("the first tire is the player unless another says so", "[unit][world]") {
  World world(SolverConfig{}, {0, -9.81});
  world.add_tire(tire_at({0, 1}));
  CHECK(world.player()->id == 0);
  world.add_tire(tire_at({2, 1}, true));
  CHECK(world.player()->id == 1);
  // Steering drives only the player.
  World steer(SolverConfig{}, {0, 0});
  steer.add_tire(tire_at({0, 1}));
  steer.add_tire(tire_at({5, 1}));
  run(steer, 30, {1.0, false});
  CHECK(steer.find_tire(0)->angular_velocity() < -1.0);
  CHECK(steer.find_tire(1)->angular_velocity() == 0.0);
  steer.remove_tire(0);
  CHECK(steer.player() == nullptr);
  steer.step({1.0, false});  // no player: input goes nowhere, nothing breaks
}

TEST_CASE("a grabbed tire follows the mouse and falls when released", "[unit][world][session]") {
  LevelSession session(SolverConfig{}, {0, -9.81});
  session.world() = flat_world(tire_at({0, 0.5}));
  const World& world = session.world();
  REQUIRE_FALSE(session.grab({5, 5}, 0.2));  // nothing there
  REQUIRE(session.grab({0.1, 0.6}, 0.2) == world.tires().front().id);
  for (int i = 1; i <= 60; ++i) {  // dragged over a second, as a mouse does
    session.move_grab(Vec2{0.1, 0.6} + (Vec2{2, 3} - Vec2{0.1, 0.6}) * (i / 60.0));
    session.step({});
  }
  run(session, 180);
  const Tire& t = world.tires().front();
  CHECK(length(t.particles.x[t.grab_particle] - Vec2{2, 3}) < 0.1);  // hanging from the grab point
  session.release_grab();
  run(session, 480);
  CHECK(t.centroid().y < 0.6);  // fell, bounced and settled back on the ground
}

TEST_CASE("a tires. key set while the world runs holds for the tires added after it", "[unit][world]") {
  World world = flat_world(tire_at({0, 0.5}));
  REQUIRE(world.set_parameter("tires.compliance.spoke", 1e-4));
  REQUIRE(world.set_parameter("tires.friction", 0.3));
  REQUIRE(world.set_parameter("tires.mass", 40));
  REQUIRE(world.set_parameter("tires.mass_scale", 0.5));  // after tires.mass: of the spawn mass
  REQUIRE(world.set_parameter("player.jump_speed", 9));   // the player's own: not for others
  TireSpec spec = tire_at({3, 0.5});
  spec.friction = 0.9;
  spec.mass = 8;
  const std::optional<TireId> spawned = world.spawn_tire(spec);
  REQUIRE(spawned);
  const Tire& t = *world.find_tire(*spawned);
  CHECK(t.spec.compliance.spoke == 1e-4);
  CHECK(t.spec.friction == 0.3);
  CHECK(t.particle_mass() * t.particle_count() == Approx(4.0));  // 0.5 × its own 8 kg
  CHECK(t.spec.jump_speed == TireSpec{}.jump_speed);
  // A key set again moves to the end of the order: the mass now wins over the scale.
  REQUIRE(world.set_parameter("tires.mass", 12));
  const Tire& u = *world.find_tire(*world.spawn_tire(tire_at({6, 0.5})));
  CHECK(u.particle_mass() * u.particle_count() == Approx(12.0));
  // The same as the tires that were there: the first tire, set directly, and the spawned one agree
  // (looked up again: spawning u may have moved the tires, t with them).
  CHECK(world.tires().front().spec.compliance.spoke == world.find_tire(*spawned)->spec.compliance.spoke);
}

TEST_CASE("compliance and mass can be tuned live", "[unit][world]") {
  World world = flat_world(tire_at({0, 0.5}));
  run(world, 120);
  const double stiff_sag = 0.5 - world.tires().front().centroid().y;
  REQUIRE(world.set_parameter("tires.compliance.pressure", 1e-3));
  REQUIRE(world.set_parameter("tires.compliance.spoke", 1e-4));
  REQUIRE(world.set_parameter("tires.mass", 20));
  CHECK_FALSE(world.set_parameter("tires.compliance.bogus", 1));
  run(world, 240);
  const Tire& t = world.tires().front();
  CHECK(t.spec.compliance.spoke == 1e-4);
  CHECK(t.particle_mass() * t.particle_count() == Approx(20));
  CHECK(0.5 - t.centroid().y > 2 * stiff_sag);  // softer and heavier: it sags more
}

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

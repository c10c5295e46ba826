// Sleeping (issue 14, world/sleep_islands.h): resting bodies stop costing anything, and wake exactly
// when they must. Work is bounded by counts (tires asleep), never by time.
#include <catch2/catch.hpp>
#include <cmath>

#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {

constexpr double kRestY = 0.49;  // a default tire's hub resting on y = 0

// Steps until every tire sleeps or `ticks` pass; the ticks it took, or −1.
int sleep_within(World& world, int ticks) {
  for (int i = 0; i < ticks; ++i) {
    if (world.asleep_count() == world.tires().size()) return i;
    world.step({});
  }
  return world.asleep_count() == world.tires().size() ? ticks : -1;
}

// A row of `count` tires side by side on a shelf (a static box prop, so that it can be removed)
// 3 m above the ground.
World shelf_world(int count, const SolverConfig& config = {}) {
  World world(config, {0, -9.81});
  world.add_obstacle({{{-100, -10}, {100, 0}}});
  PropSpec shelf;
  shelf.name = "shelf";
  shelf.type = PropType::static_body;
  shelf.size = {1.05 * count + 1.0, 0.2};
  shelf.position = {0, 2.9};
  world.add_prop(shelf);
  for (int i = 0; i < count; ++i) world.add_tire(tire_at({(i - 0.5 * (count - 1)) * 1.05, 3.0 + kRestY}));
  return world;
}

}  // namespace

TEST_CASE("sleep: a resting tire falls asleep after sleep_time still, and stays where it lay",
          "[unit][sleep]") {
  World world = flat_world(tire_at({0, 0.5}));
  const int ticks = sleep_within(world, 600);
  INFO("asleep after " << ticks << " ticks");
  REQUIRE(ticks > 0);
  // Not before it had been still for sleep_time.
  CHECK(ticks * world.config().dt >= world.config().sleep_time);
  const Tire& t = world.tires().front();
  const Vec2 hub = t.centroid();
  CHECK(hub.y == Approx(kRestY).margin(0.01));
  const std::uint64_t hash = world.state_hash();
  run(world, 120);
  CHECK(t.asleep);
  CHECK(t.centroid().x == hub.x);  // not simulated: exactly where it fell asleep
  CHECK(t.centroid().y == hub.y);
  CHECK(world.state_hash() != hash);  // the tick count moves on
}

TEST_CASE("sleep: a sleeping tire is not solved while tires elsewhere touch each other", "[unit][sleep]") {
  // The global method solves touching tires by colour (tire_neighbours.h); its colours held every
  // tire, asleep or not, and each sleeping tire was solved every substep: 9 900 sleeping tires cost
  // 96 times 100 awake ones (tirectl bench --scene global-crowd-10000).
  World world = flat_world(tire_at({-20, 0.5}));
  REQUIRE(sleep_within(world, 600) > 0);
  const std::uint32_t before = world.tires().front().global_work.solves;
  const Vec2 hub = world.tires().front().centroid();
  world.add_tire(tire_at({20, 0.5}));
  world.add_tire(tire_at({20.2, 1.6}));  // lands on the first and rolls off it
  const Tire& sleeper = world.tires().front();
  for (int i = 0; i < 120; ++i) {
    world.step({});
    REQUIRE(sleeper.asleep);
  }
  CHECK(world.tires()[2].global_work.solves > 0);
  CHECK(sleeper.global_work.solves == before);
  CHECK(sleeper.centroid().x == hub.x);
  CHECK(sleeper.centroid().y == hub.y);
}

TEST_CASE("sleep: \"sleep\": false keeps every tire awake", "[unit][sleep]") {
  SolverConfig config;
  config.sleep = false;
  World world = flat_world(tire_at({0, 0.5}), config);
  run(world, 600);
  CHECK(world.asleep_count() == 0);
}

TEST_CASE("sleep: remove the shelf under 30 resting tires and they all fall", "[unit][sleep]") {
  // The same shelf with sleeping off, for the same ticks: the tires must fall the same way.
  SolverConfig awake;
  awake.sleep = false;
  World world = shelf_world(30), reference = shelf_world(30, awake);
  const int ticks = sleep_within(world, 900);
  REQUIRE(ticks >= 0);
  run(reference, ticks);
  REQUIRE(world.rigid().remove_prop("shelf"));
  REQUIRE(reference.rigid().remove_prop("shelf"));
  run(world, 45);  // 0.75 s: from 3 m, about to land
  run(reference, 45);
  CHECK(world.asleep_count() == 0);
  double worst = 0.0;
  for (std::size_t i = 0; i < world.tires().size(); ++i) {
    const Vec2 hub = world.tires()[i].centroid();
    CHECK(hub.y < 1.0);  // fell 2.5 m and more
    worst = std::max(worst, length(hub - reference.tires()[i].centroid()));
  }
  INFO("largest distance from the same tire with sleeping off: " << worst << " m");
  CHECK(worst < 0.01);
}

TEST_CASE("sleep: a lift under a resting tire starts moving and carries it", "[unit][sleep]") {
  World world(SolverConfig{}, {0, -9.81});
  world.add_obstacle({{{-100, -10}, {100, 0}}});
  PropSpec lift;
  lift.name = "lift";
  lift.type = PropType::kinematic_body;
  lift.size = {3.0, 0.2};
  lift.position = {0, 0.9};
  lift.path.waypoints = {{0, 0.9}, {0, 4.9}};
  lift.path.speed = 1.0;
  lift.path.running = false;
  world.add_prop(lift);
  world.add_tire(tire_at({0, 1.0 + kRestY}));
  REQUIRE(sleep_within(world, 600) >= 0);
  const double rested = world.tires().front().centroid().y;
  REQUIRE(world.rigid().path_command("lift", PathCommand::start));
  run(world, 120);  // 2 s at 1 m/s
  const Tire& t = world.tires().front();
  CHECK_FALSE(t.asleep);
  CHECK(t.centroid().y == Approx(rested + 2.0).margin(0.05));  // on the lift, 2 m up
}

TEST_CASE("sleep: a tire thrown onto a sleeping pile lands on it as it does with sleeping off",
          "[unit][sleep]") {
  // A pile of 12 in a walled pit, settled; then a tire thrown in from the side. With sleeping off
  // the pile is awake throughout: the thrown tire must end where it does there.
  const auto pile = [](const SolverConfig& config) {
    World world(config, {0, -9.81});
    world.add_obstacle({{{-100, -10}, {100, 0}}});
    world.add_obstacle({{{-3.2, 0}, {-2.2, 6}}});
    world.add_obstacle({{{2.2, 0}, {3.2, 6}}});
    for (int row = 0; row < 3; ++row)
      for (int k = 0; k < 4; ++k)
        world.add_tire(tire_at({-1.6 + 1.05 * k + 0.3 * (row % 2), 0.5 + 1.05 * row}));
    return world;
  };
  SolverConfig off;
  off.sleep = false;
  World world = pile({}), reference = pile(off);
  const int ticks = sleep_within(world, 1200);
  REQUIRE(ticks >= 0);
  run(reference, ticks);
  TireSpec thrown = tire_at({-1.0, 6.0});
  thrown.velocity = {2.0, 0.0};
  world.add_tire(thrown);
  reference.add_tire(thrown);
  bool woke = false;
  for (int i = 0; i < 180; ++i) {
    world.step({});
    reference.step({});
    woke = woke || world.asleep_count() < 12;
  }
  const Vec2 here = world.tires().back().centroid(), there = reference.tires().back().centroid();
  INFO("thrown tire at " << here.x << ", " << here.y << "; with sleeping off " << there.x << ", " << there.y);
  CHECK(woke);
  // Onto the pile's top row, as with sleeping off (where along it is chaotic: 0.3 m apart across
  // the two runs, 7 cm in height), and through none of its tires.
  CHECK(here.y > 2.5);
  CHECK(here.y == Approx(there.y).margin(0.15));
  for (std::size_t i = 0; i + 1 < world.tires().size(); ++i)
    CHECK(length(world.tires()[i].centroid() - here) > 0.9);
}

TEST_CASE("sleep: what wakes a sleeping tire", "[unit][sleep]") {
  World world = flat_world(tire_at({0, 0.5}));
  const TireId id = world.tires().front().id;
  const auto asleep = [&] { return world.tires().front().asleep; };
  REQUIRE(sleep_within(world, 600) >= 0);
  SECTION("a script's impulse") { world.apply_impulse_to_tire(id, {0, 50}); }
  SECTION("live tuning") { CHECK(world.set_parameter("tires.friction", 0.8)); }
  SECTION("gravity") { world.set_gravity({0, -5}); }
  SECTION("a mouse grab") { world.grab_particle(id, 0, {0, 2}); }
  SECTION("the player's input, and it stays awake while a key is held") {
    // A jump wakes it and is made: 0.5 s later the hub is more than 1 m up (5 m/s: 1.3 m).
    for (int i = 0; i < 30; ++i) world.step({0.0, i == 0});
    CHECK_FALSE(asleep());
    CHECK(world.tires().front().centroid().y > kRestY + 1.0);
    for (int i = 0; i < 120; ++i) world.step({0.3, false});
    CHECK_FALSE(asleep());
    return;
  }
  CHECK_FALSE(asleep());
}

TEST_CASE("sleep: the same state hash for any thread count", "[unit][sleep]") {
  // The default method: the pile of 35 rests and sleeps within the 15 s (docs/at-rest.md).
  const auto pile = [](unsigned threads) {
    World world(SolverConfig{}, {0, -9.81});
    world.set_threads(threads);
    world.add_obstacle({{{-100, -10}, {100, 0}}});
    world.add_obstacle({{{-5, 0}, {-4, 12}}});
    world.add_obstacle({{{4, 0}, {5, 12}}});
    // 35 tires (parallel from 32), five rows of seven, each row shifted by a quarter.
    for (int k = 0; k < 35; ++k)
      world.add_tire(tire_at({-3.3 + 1.1 * (k % 7) + 0.25 * (k / 7 % 2), 0.5 + 1.2 * (k / 7)}));
    run(world, 900);
    return world;
  };
  const World one = pile(1), two = pile(2);
  CHECK(one.asleep_count() > 0);
  CHECK(one.asleep_count() == two.asleep_count());
  CHECK(one.state_hash() == two.state_hash());
}

// Same binary, same input: the same state, bit for bit, every tick.
#include <catch2/catch.hpp>

#include "tire/math/state_hash.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {
TickInput scripted_input(int tick) {
  return {tick < 100 ? 1.0 : tick < 200 ? -0.5 : 0.0, tick == 80 || tick == 150};
}
}  // namespace

TEST_CASE("the same input twice gives the same hash at every tick", "[unit][determinism]") {
  const Level level = default_level();
  World a(level.solver, level.gravity), b(level.solver, level.gravity);
  populate_world(level, a);
  populate_world(level, b);
  for (int tick = 0; tick < 300; ++tick) {
    if (tick == 120) a.add_tire(tire_at({2, 3})), b.add_tire(tire_at({2, 3}));
    a.step(scripted_input(tick));
    b.step(scripted_input(tick));
    REQUIRE(a.state_hash() == b.state_hash());
  }
}

TEST_CASE("a different input gives a different hash", "[unit][determinism]") {
  const Level level = default_level();
  World a(level.solver, level.gravity), b(level.solver, level.gravity);
  populate_world(level, a);
  populate_world(level, b);
  for (int tick = 0; tick < 60; ++tick) {
    a.step({});
    b.step({tick == 30 ? 0.01 : 0.0, false});
  }
  CHECK(a.state_hash() != b.state_hash());
  CHECK(to_hex(a.state_hash()).size() == 16);
}

TEST_CASE("results do not depend on the number of threads", "[unit][determinism]") {
  // A pile big enough to run in parallel, with crates for the deferred prop impulses, and without
  // (where each substep's velocity pass shares a sweep with the next one's prediction). Five
  // threads on this machine's two cores: some are put aside mid-step and others take their chunks.
  const bool crates = GENERATE(true, false);
  CAPTURE(crates);
  SolverConfig config;
  config.method = GENERATE(SolverMethod::gauss_seidel, SolverMethod::global);
  CAPTURE(method_name(config.method));
  auto build = [crates, config](unsigned threads) {
    auto world = std::make_unique<World>(config, Vec2{0, -9.81});
    world->set_threads(threads);
    world->add_obstacle({{{-1, -1}, {16, 0}}});
    world->add_obstacle({{{-1, 0}, {0, 50}}});
    world->add_obstacle({{{15, 0}, {16, 50}}});
    for (int i = 0; i < 100; ++i)
      world->add_tire(tire_at({0.6 + 1.05 * (i % 14) + 0.2 * ((i / 14) % 2), 0.5 + 1.0 * (i / 14)}));
    for (int i = 0; i < (crates ? 6 : 0); ++i) {
      PropSpec crate;
      crate.type = PropType::dynamic_body;
      crate.size = {0.6, 0.6};
      crate.density = 20;
      crate.position = {1.0 + 2.2 * i, 9.0};
      world->add_prop(crate);
    }
    return world;
  };
  auto one = build(1), two = build(2), five = build(5);
  for (int tick = 0; tick < 90; ++tick) {
    one->step({1.0, tick == 40});
    two->step({1.0, tick == 40});
    five->step({1.0, tick == 40});
    REQUIRE(one->state_hash() == two->state_hash());
    REQUIRE(one->state_hash() == five->state_hash());
  }
}

TEST_CASE("the island solve gives the same result on any thread count", "[unit][determinism][island]") {
  // Islands of tires solved as one problem (island_contacts.h): the tires' solves, their responses
  // and their moves run on the threads, the contact problem between them on the caller.
  SolverConfig config;
  config.method = SolverMethod::global;
  config.island_tires = 128;
  auto build = [config](unsigned threads) {
    auto world = std::make_unique<World>(config, Vec2{0, -9.81});
    world->set_threads(threads);
    world->add_obstacle({{{-1, -1}, {9, 0}}});
    world->add_obstacle({{{-1, 0}, {0, 50}}});
    world->add_obstacle({{{8, 0}, {9, 50}}});
    for (int i = 0; i < 40; ++i)
      world->add_tire(tire_at({0.6 + 1.05 * (i % 7) + 0.2 * ((i / 7) % 2), 0.5 + 1.0 * (i / 7)}));
    return world;
  };
  auto one = build(1), two = build(2), five = build(5);
  for (int tick = 0; tick < 60; ++tick) {
    one->step({1.0, tick == 40});
    two->step({1.0, tick == 40});
    five->step({1.0, tick == 40});
    REQUIRE(one->state_hash() == two->state_hash());
    REQUIRE(one->state_hash() == five->state_hash());
  }
  CHECK(two->threads_in_use() == 2);
  CHECK(one->island_work().solves > 50);  // the islands were solved, not left to Gauss–Seidel
  CHECK(one->island_work().rows == two->island_work().rows);
}

TEST_CASE("a tire with more neighbours than colours gives the same result on any thread count",
          "[unit][determinism]") {
  // Tire pairs are solved a colour at a time, a colour's pairs in parallel: no two of them may share
  // a tire. A tire has a colour for each of 64 neighbours; its pairs beyond go to one last colour,
  // whose pairs therefore can share a tire and are solved in order. A tire dropped into a pile at
  // 3 km/s has its broad-phase bounds grown over all 100 others in its first tick (its speed is
  // clamped in the substeps, not in the broad phase): 36 of its pairs overflow.
  auto build = [](unsigned threads) {
    auto world = std::make_unique<World>(SolverConfig{}, Vec2{0, -9.81});
    world->set_threads(threads);
    world->add_obstacle({{{-1, -1}, {16, 0}}});
    world->add_obstacle({{{-1, 0}, {0, 50}}});
    world->add_obstacle({{{15, 0}, {16, 50}}});
    for (int i = 0; i < 100; ++i)
      world->add_tire(tire_at({0.6 + 1.05 * (i % 14) + 0.2 * ((i / 14) % 2), 0.5 + 1.0 * (i / 14)}));
    TireSpec fast = tire_at({7.3, 8.2});
    fast.velocity = {0.0, -3000.0};
    world->add_tire(fast);
    return world;
  };
  auto one = build(1), two = build(2), five = build(5);
  for (int tick = 0; tick < 30; ++tick) {
    one->step({});
    two->step({});
    five->step({});
    REQUIRE(one->state_hash() == two->state_hash());
    REQUIRE(one->state_hash() == five->state_hash());
  }
}

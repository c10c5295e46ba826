// Same binary, same input: the same state, bit for bit, every tick.
#include <catch2/catch.hpp>

#include "tire/math/numbers.h"
#include "tire/math/state_hash.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {
TickInput scripted_input(int tick) {
  return {tick < 100 ? 1.0 : tick < 200 ? -0.5 : 0.0, tick == 80 || tick == 150};
}

// The same scene built for 1, 2 and 5 threads (five on this machine's two cores: some are put aside
// mid-step and others take their chunks), stepped side by side with one hash required every tick;
// the worlds, for the caller's own checks.
struct OnThreads {
  std::unique_ptr<World> one, two, five;
};
template <class Build, class Input>
OnThreads step_on_1_2_5_threads(const Build& build, int ticks, const Input& input) {
  OnThreads w{build(1), build(2), build(5)};
  for (int tick = 0; tick < ticks; ++tick) {
    w.one->step(input(tick));
    w.two->step(input(tick));
    w.five->step(input(tick));
    REQUIRE(w.one->state_hash() == w.two->state_hash());
    REQUIRE(w.one->state_hash() == w.five->state_hash());
  }
  return w;
}
TickInput drive_and_jump_at_40(int tick) { return {1.0, tick == 40}; }
TickInput no_input(int) { return {}; }

// `count` tires in rows of `columns`, every other row shifted, in a box one metre wider.
std::unique_ptr<World> boxed_pile(const SolverConfig& config, unsigned threads, int count, int columns) {
  auto world = std::make_unique<World>(config, Vec2{0, -9.81});
  world->set_threads(threads);
  const double width = columns + 1.0;
  world->add_obstacle({{{-1, -1}, {width + 1, 0}}});
  world->add_obstacle({{{-1, 0}, {0, 50}}});
  world->add_obstacle({{{width, 0}, {width + 1, 50}}});
  for (int i = 0; i < count; ++i)
    world->add_tire(
        tire_at({0.6 + 1.05 * (i % columns) + 0.2 * ((i / columns) % 2), 0.5 + 1.0 * (i / columns)}));
  return world;
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
  // (where each substep's velocity pass shares a sweep with the next one's prediction).
  const bool crates = GENERATE(true, false);
  CAPTURE(crates);
  SolverConfig config;
  config.method = GENERATE(SolverMethod::gauss_seidel, SolverMethod::global);
  CAPTURE(method_name(config.method));
  auto build = [crates, config](unsigned threads) {
    auto world = boxed_pile(config, threads, 100, 14);
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
  step_on_1_2_5_threads(build, 90, drive_and_jump_at_40);
}

TEST_CASE("the island solve gives the same result on any thread count", "[unit][determinism][island]") {
  // Islands of tires solved as one problem (island_contacts.h): the tires' solves, their responses
  // and their moves run on the threads, the contact problem between them on the caller.
  SolverConfig config;
  config.method = SolverMethod::global;
  config.island_tires = 128;
  auto build = [config](unsigned threads) { return boxed_pile(config, threads, 40, 7); };
  const OnThreads w = step_on_1_2_5_threads(build, 60, drive_and_jump_at_40);
  CHECK(w.two->threads_in_use() == 2);
  CHECK(w.one->island_work().solves > 50);  // the islands were solved, not left to Gauss–Seidel
  CHECK(w.one->island_work().rows == w.two->island_work().rows);
}

TEST_CASE("a tire with more neighbours than colours gives the same result on any thread count",
          "[unit][determinism]") {
  // Tire pairs are solved a colour at a time, a colour's pairs in parallel: no two of them may share
  // a tire. A tire has a colour for each of 64 neighbours; its pairs beyond go to one last colour,
  // whose pairs therefore can share a tire and are solved in order. A tire dropped into a pile at
  // 3 km/s has its broad-phase bounds grown over all 100 others in its first tick (its speed is
  // clamped in the substeps, not in the broad phase): 36 of its pairs overflow.
  auto build = [](unsigned threads) {
    auto world = boxed_pile(SolverConfig{}, threads, 100, 14);
    TireSpec fast = tire_at({7.3, 8.2});
    fast.velocity = {0.0, -3000.0};
    world->add_tire(fast);
    return world;
  };
  step_on_1_2_5_threads(build, 30, no_input);
}

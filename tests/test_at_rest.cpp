// At rest means at rest (issue 33, docs/at-rest.md): a pile under the default method stops moving
// and sleeps, and a sleeping tire has the shape it would settle to awake.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {

// 60 default tires dropped in rows of five into a 6 m box.
World pile_of_60(const SolverConfig& config) {
  World world(config, {0, -9.81});
  world.add_obstacle({{{-100, -10}, {100, 0}}});
  world.add_obstacle({{{-4, 0}, {-3, 40}}});
  world.add_obstacle({{{3, 0}, {4, 40}}});
  for (int k = 0; k < 60; ++k)
    world.add_tire(tire_at({-2.4 + 1.1 * (k % 5) + 0.25 * (k / 5 % 2), 0.5 + 1.2 * (k / 5)}));
  return world;
}

}  // namespace

TEST_CASE("at rest: a pile of 60 tires stops moving under the default method", "[unit][rest]") {
  SolverConfig config;
  config.sleep = false;
  World world = pile_of_60(config);
  run(world, 20 * 60);
  std::vector<Vec2> at20;
  for (const Tire& t : world.tires()) at20.push_back(t.centroid());
  run(world, 10 * 60);
  std::vector<double> moved;
  double rise = -1.0;
  for (std::size_t i = 0; i < at20.size(); ++i) {
    const Vec2 d = world.tires()[i].centroid() - at20[i];
    moved.push_back(length(d));
    rise = std::max(rise, d.y);
  }
  std::sort(moved.begin(), moved.end());
  INFO("from 20 to 30 s: median " << moved[30] * 1e3 << " mm, most " << moved.back() * 1e3 << " mm, rise "
                                  << rise * 1e3 << " mm");
  CHECK(moved[30] < 1e-3);  // the figures (before: 2.5 mm, one tire climbing 4.3 mm)
  CHECK(rise < 2e-3);
}

TEST_CASE("at rest: a pile of 60 tires falls asleep within 30 s under the default method", "[unit][rest]") {
  World world = pile_of_60({});
  int ticks = 0;
  while (ticks < 30 * 60 && world.asleep_count() < world.tires().size()) {
    world.step({});
    ++ticks;
  }
  INFO(world.asleep_count() << " of 60 asleep after " << ticks / 60.0 << " s");
  CHECK(world.asleep_count() == world.tires().size());
}

TEST_CASE("at rest: a soft tire's sag asleep is its sag awake, at 2, 8 and 32 substeps",
          "[unit][rest][sleep]") {
  // Soft enough to sag 9.4 mm (6 of them its flat segment's): with the deformation threshold that
  // let jittering piles sleep (0.25 m/s) it fell asleep ringing, up to 4.5 % off at 32 substeps.
  TireSpec soft = tire_at({0, 0.5});
  soft.compliance.outer = 1e-5;
  soft.compliance.spoke = 1e-4;
  soft.compliance.pressure = 1e-3;
  for (const int substeps : {2, 8, 32}) {
    double sag[2];
    for (const bool sleep : {false, true}) {
      SolverConfig config;
      config.substeps = substeps;
      config.sleep = sleep;
      World world = flat_world(soft, config);
      run(world, 600);
      if (sleep) REQUIRE(world.tires().front().asleep);
      sag[sleep] = 0.5 - world.tires().front().centroid().y;
    }
    INFO(substeps << " substeps: sag awake " << sag[0] * 1e3 << " mm, asleep " << sag[1] * 1e3 << " mm");
    CHECK(std::abs(sag[1] - sag[0]) <= 0.01 * sag[0]);
  }
}

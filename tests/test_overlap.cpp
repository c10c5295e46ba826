// deepest_tire_overlap (tire/world/overlap.h): how far tires are inside each other.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "tire/world/overlap.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {

// Two default tires in empty space, hubs `apart` along x, never stepped.
World two_tires(double apart) {
  World world(SolverConfig{}, {0.0, 0.0});
  world.add_tire(tire_at({0.0, 0.0}));
  world.add_tire(tire_at({apart, 0.0}));
  return world;
}

}  // namespace

TEST_CASE("overlap: two tires pressed d into each other are found as deep as their polygons meet",
          "[unit][overlap]") {
  const double radius = TireSpec{}.outer_radius;
  for (const double d : {0.005, 0.02, 0.1}) {
    const World world = two_tires(2.0 * radius - d);
    const std::uint32_t n = world.tires().front().n;
    // Each tread is a regular n-gon with an edge facing the other (tire.cpp: at angle 0 an edge
    // lies flat at the bottom), R cos(π/n) from its hub: the edges meet once d passes twice the
    // sagitta, 2 R (1 − cos(π/n)), and then the deepest particles are the ends of one tire's edge,
    // max(0, d − 2s) inside the other's edge line and that times cos(2π/n) from its next edge.
    const double sagitta = radius * (1.0 - std::cos(std::numbers::pi / n));
    const double expected = std::max(0.0, d - 2.0 * sagitta) * std::cos(2.0 * std::numbers::pi / n);
    const TireOverlap overlap = deepest_tire_overlap(world);
    INFO("pressed " << d * 1e3 << " mm in: found " << overlap.depth * 1e3 << " mm, tire " << overlap.tire
                    << " in " << overlap.inside << "; expected " << expected * 1e3 << " mm");
    CHECK(overlap.depth == Approx(expected).margin(1e-12));
    if (expected > 0.0) CHECK(overlap.tire != overlap.inside);
  }
}

TEST_CASE("overlap: tires apart or just touching are not inside each other", "[unit][overlap]") {
  const double radius = TireSpec{}.outer_radius;
  CHECK(deepest_tire_overlap(two_tires(2.0 * radius + 1e-6)).depth == 0.0);
  CHECK(deepest_tire_overlap(two_tires(5.0)).depth == 0.0);
  World alone(SolverConfig{}, {0.0, 0.0});
  CHECK(deepest_tire_overlap(alone).depth == 0.0);
  alone.add_tire(tire_at({0.0, 0.0}));
  CHECK(deepest_tire_overlap(alone).depth == 0.0);
}

// The tire as built, and how its shape holds: recovery from squashing, inflation, divergence.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

TEST_CASE("a tire is built as two rings with a flat tread segment at the bottom", "[unit][shape]") {
  TireSpec spec;
  spec.position = {2, 3};
  spec.segments = 12;
  const Tire t(0, spec);
  CHECK(t.particle_count() == 24);
  CHECK(t.centroid().x == Approx(2));
  CHECK(t.centroid().y == Approx(3));
  // Rings of N edges each, N radial spokes and 2N diagonals with the default cross pattern.
  CHECK(t.distance.size() == 12u * 5u);
  CHECK(t.area_ratio() == Approx(1.0));
  CHECK(t.particles.x[11].y == Approx(t.particles.x[0].y));  // the bottom segment is level
  CHECK(t.particles.x[0].y == Approx(3 - 0.5 * std::cos(std::numbers::pi / 12)));
  CHECK(t.particle_mass() * t.particle_count() == Approx(spec.mass));
  for (const DistanceConstraint& c : t.distance.constraints())
    CHECK(length(t.particles.x[c.b] - t.particles.x[c.a]) == Approx(c.rest_length));
  spec.spokes = SpokePattern::radial;
  CHECK(Tire(1, spec).distance.size() == 12u * 3u);
}

TEST_CASE("a squashed tire recovers its area and shape", "[unit][shape][physics]") {
  SolverConfig config;
  World world(config, {0, 0});
  TireSpec spec;
  spec.position = {0, 0};
  world.add_tire(spec);
  Tire& t = *world.find_tire(0);
  for (Vec2& x : t.particles.x) x.y *= 0.5;  // flattened to half its height
  REQUIRE(t.area_ratio() < 0.6);
  run(world, 120);
  CHECK(t.area_ratio() == Approx(1.0).epsilon(0.01));
  double worst = 0.0;
  for (const DistanceConstraint& c : t.distance.constraints())
    worst = std::max(worst, std::abs(length(t.particles.x[c.b] - t.particles.x[c.a]) / c.rest_length - 1));
  CHECK(worst < 0.01);
}

TEST_CASE("pressure above 1 inflates the tire and below 1 deflates it", "[unit][shape][physics]") {
  auto settled_ratio = [](double pressure) {
    SolverConfig config;
    World world(config, {0, 0});
    TireSpec spec;
    spec.position = {0, 0};
    spec.pressure = pressure;
    // A stretchy tread and sidewall, so that the air can change the area.
    spec.compliance = {1e-3, 1e-3, 1e-3, 1e-5};
    world.add_tire(spec);
    run(world, 240);
    return world.tires().front().area_ratio();
  };
  const double deflated = settled_ratio(0.7), normal = settled_ratio(1.0), inflated = settled_ratio(1.5);
  INFO("area ratios at pressure 0.7, 1.0, 1.5: " << deflated << ", " << normal << ", " << inflated);
  CHECK(normal == Approx(1.0).epsilon(0.01));
  CHECK(inflated > 1.3);
  CHECK(deflated < 0.85);
}

TEST_CASE("a NaN never spreads: the tire is reset and a warning raised", "[unit][shape]") {
  TireSpec spec;
  spec.position = {0, 2};
  World world = flat_world(spec);
  world.add_tire(tire_at({3, 2}));
  run(world, 10);
  world.find_tire(0)->particles.x[5].x = std::numeric_limits<double>::quiet_NaN();
  world.step({});
  REQUIRE(world.warnings().size() == 1);
  CHECK(world.warnings().front().find("diverged") != std::string::npos);
  for (const Tire& t : world.tires()) CHECK(t.is_finite());
  CHECK(world.find_tire(0)->centroid().y == Approx(2.0).margin(0.05));  // back at its spawn
  CHECK(world.find_tire(1)->centroid().y < 1.99);  // the other tire carried on falling
}

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
  // The solve that met the NaN is reported (its step skipped), then the reset.
  REQUIRE(world.warnings().size() == 2);
  CHECK(world.warnings().front().find("global solve(s) failed") != std::string::npos);
  CHECK(world.warnings().back().find("diverged") != std::string::npos);
  for (const Tire& t : world.tires()) CHECK(t.is_finite());
  CHECK(world.find_tire(0)->centroid().y == Approx(2.0).margin(0.05));  // back at its spawn
  CHECK(world.find_tire(1)->centroid().y < 1.99);                       // the other tire carried on falling
}

TEST_CASE("a tire blown up by a kinematic box spinning at 1000 rad/s is seen, reported and reset",
          "[unit][shape]") {
  // The hostile audit's case (issue 34): the tire reached 1180 times its area while every
  // coordinate stayed finite and near, and nothing was reported. Since the global solve keeps a
  // stretched link's transverse stiffness, and the substeps are refined before a spinning tire
  // reaches what it may land on (World::update_refinement), the tire reaches about 4.5 times its
  // area, so the guard is set at 3 here. Since a particle that starts a substep inside a surface is
  // pushed out at contact_push_speed, not at once, the box no longer blows the tire up (2.5 times
  // its area at most): the guard is tested with the push unbounded, as it was, and the bound on its
  // own.
  const auto run_case = [](double push_speed) {
    SolverConfig config;
    config.divergence_area = 3.0;
    config.contact_push_speed = push_speed;
    World world = flat_world(tire_at({0, 2.6}), config);
    PropSpec box;
    box.type = PropType::kinematic_body;
    box.size = {4, 0.25};
    box.position = {0, 1.5};
    box.angular_velocity = 1000;
    world.add_prop(box);
    double largest = 0.0;
    int diverged = 0;
    for (int i = 0; i < 120; ++i) {
      world.step({});
      for (const Tire& t : world.tires()) largest = std::max(largest, std::abs(t.area_ratio()));
      for (const std::string& w : world.warnings()) diverged += w.find("diverged") != std::string::npos;
      world.warnings().clear();
    }
    INFO("push speed " << push_speed << ": largest area ratio after a tick " << largest << ", " << diverged
                       << " resets");
    if (std::isinf(push_speed)) CHECK(diverged > 0);
    CHECK(largest <= world.config().divergence_area);
    return diverged;
  };
  run_case(std::numeric_limits<double>::infinity());
  CHECK(run_case(SolverConfig{}.contact_push_speed) == 0);
}

TEST_CASE("tires of one shape share one topology and keep their own compliance", "[unit][shape]") {
  // Issue 12: the topology (pairs, compliance groups, SIMD batch cut) is shared by the tires of a
  // shape; what is tuned per tire (compliance) stays per tire.
  // Gauss–Seidel 8 × 1, which steps tires that never touch exactly as each alone. The global method
  // (the default) kept b only to 4e-10 m of its lone run over 120 ticks here: why is not established.
  const auto make_world = [] {
    World w(SolverConfig::gauss_seidel_8x1(), {0, -9.81});
    w.add_obstacle({{{-100, -1}, {100, 0}}});
    return w;
  };
  TireSpec a = tire_at({0.0, 0.8});
  TireSpec b = tire_at({20.0, 0.8});  // far from a: the two never touch
  TireSpec other_segments = tire_at({40.0, 0.8});
  other_segments.segments = 20;
  TireSpec other_spokes = tire_at({60.0, 0.8});
  other_spokes.spokes = SpokePattern::radial;

  World both = make_world();
  const TireId ia = both.add_tire(a), ib = both.add_tire(b);
  const TireId is = both.add_tire(other_segments), ip = both.add_tire(other_spokes);
  CHECK(both.find_tire(ia)->topology == both.find_tire(ib)->topology);
  CHECK(both.find_tire(ia)->distance.layout() == both.find_tire(ib)->distance.layout());
  CHECK(both.find_tire(is)->topology != both.find_tire(ia)->topology);
  CHECK(both.find_tire(ip)->topology != both.find_tire(ia)->topology);
  CHECK(both.find_tire(ip)->topology != both.find_tire(is)->topology);

  // Soften a alone: b must move exactly as it does in a world of its own.
  TireCompliance soft = a.compliance;
  soft.outer *= 100.0;
  soft.spoke *= 100.0;
  both.find_tire(ia)->set_compliance(soft);
  CHECK(both.find_tire(ib)->distance.constraints()[0].compliance == b.compliance.outer);
  CHECK(both.find_tire(ia)->distance.constraints()[0].compliance == soft.outer);

  World alone_b = make_world();
  alone_b.add_tire(b);
  World alone_a = make_world();
  alone_a.add_tire(a);
  alone_a.find_tire(alone_a.tires().front().id)->set_compliance(soft);
  for (int i = 0; i < 120; ++i) {
    both.step({0.0, false});
    alone_b.step({0.0, false});
    alone_a.step({0.0, false});
  }
  const Tire& b_in_both = *both.find_tire(ib);
  const Tire& a_in_both = *both.find_tire(ia);
  const Tire& b_alone = alone_b.tires().front();
  const Tire& a_alone = alone_a.tires().front();
  for (std::uint32_t i = 0; i < b_alone.particle_count(); ++i) {
    CHECK(b_in_both.particles.x[i].x == b_alone.particles.x[i].x);
    CHECK(b_in_both.particles.x[i].y == b_alone.particles.x[i].y);
    CHECK(a_in_both.particles.x[i].x == a_alone.particles.x[i].x);
    CHECK(a_in_both.particles.x[i].y == a_alone.particles.x[i].y);
  }
  // And the softened tire did behave otherwise: it sags more than b.
  CHECK(a_in_both.centroid().y < b_in_both.centroid().y);
}

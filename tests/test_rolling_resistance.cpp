// Rolling resistance held at the position level (the global method's rolling row): the turn it
// holds (tire/math/turn.h) against its finite differences, and what it means: a tire stays put on a
// slope gentler than its coefficient C_rr, as a real tire in neutral does, and rolls down a steeper
// one, at any substep count.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "tire/math/turn.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {

// A tire's particles after a second of resting on the ground (a flattened, uneven set), turned a
// little about an arbitrary point so that no axis is special.
std::vector<Vec2> deformed_tire() {
  TireSpec spec = tire_at({0.3, 0.5});
  find_material("soft")->apply_to(spec);
  World world = flat_world(spec);
  run(world, 60);
  std::vector<Vec2> x(world.tires()[0].particles.x.begin(), world.tires()[0].particles.x.end());
  for (Vec2& p : x) p = rotate(p - Vec2{0.1, 0.2}, std::cos(0.3), std::sin(0.3));
  return x;
}

// A tire of the soft preset (C_rr 0.01) at rest on the ground under gravity tilted by atan(slope)
// (a slope down towards +x), sleeping off, its roll held or not (SolverConfig::rolling_hold): how far its
// centroid moves from 10 to 20 s, and the most it turned in any substep of the last tick, read from its
// positions.
struct OnSlope {
  double moved, turn;
};
OnSlope on_slope(double slope, int substeps, bool hold = true) {
  SolverConfig config;
  config.sleep = false;
  config.substeps = substeps;
  config.rolling_hold = hold;
  const double a = std::atan(slope);
  TireSpec spec = tire_at({0.0, 0.5});
  find_material("soft")->apply_to(spec);
  World world = flat_world(spec, config, {9.81 * std::sin(a), -9.81 * std::cos(a)});
  run(world, 10 * 60);
  const Vec2 start = world.tires()[0].centroid();
  run(world, 10 * 60 - 1);
  const Tire& t = world.tires()[0];
  std::vector<Vec2> before(t.particles.x.begin(), t.particles.x.end());
  run(world, 1);
  const double turn = turn_between(before, {t.particles.x.begin(), t.particles.x.end()});
  return {length(t.centroid() - start), std::abs(turn)};
}

}  // namespace

TEST_CASE("rolling resistance: the turn's gradient is its finite differences", "[unit][rolling]") {
  const std::vector<Vec2> x = deformed_tire();
  std::vector<Vec2> g(x.size());
  REQUIRE(turn_gradient(x, g));
  const double eps = 1e-6;
  double worst = 0.0, largest = 0.0;
  std::vector<Vec2> moved = x;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (int axis = 0; axis < 2; ++axis) {
      Vec2 d{axis == 0 ? eps : 0.0, axis == 1 ? eps : 0.0};
      moved[i] = x[i] + d;
      const double plus = turn_between(x, moved);
      moved[i] = x[i] - d;
      const double minus = turn_between(x, moved);
      moved[i] = x[i];
      const double fd = (plus - minus) / (2.0 * eps);
      const double analytic = axis == 0 ? g[i].x : g[i].y;
      worst = std::max(worst, std::abs(fd - analytic));
      largest = std::max(largest, std::abs(analytic));
    }
  }
  INFO("largest entry " << largest << ", worst difference " << worst);
  CHECK(largest > 0.01);  // |r| / Σ|r|²: about 0.05 per metre for the 56 particles of a 0.5 m tire
  CHECK(worst < 1e-6 * largest);
  // What the turn means: a rigid turn by φ about any point is φ; a translation is none.
  std::vector<Vec2> turned = x;
  for (Vec2& p : turned) p = rotate(p - Vec2{2.0, -1.0}, std::cos(0.01), std::sin(0.01)) + Vec2{5.0, 3.0};
  CHECK(turn_between(x, turned) == Approx(0.01).epsilon(1e-12));
  std::vector<Vec2> coincident(4, Vec2{1.0, 1.0});
  std::vector<Vec2> none(4);
  CHECK_FALSE(turn_gradient(coincident, none));
}

TEST_CASE("rolling resistance: a tire stays put on a slope gentler than C_rr and rolls down a steeper one",
          "[unit][rolling][rest]") {
  // The soft preset's C_rr is 0.01: it holds a moment of 0.01·N·R, and the slope's is N·tan θ·R
  // (its hub a sag lower). Before the rolling row, the velocity pass alone stopped the spin each
  // substep and the position solve turned it again: on a 0.5 % slope it crept 60 mm in 10 s.
  for (const int substeps : {1, 2, 8, 32}) {
    const OnSlope held = on_slope(0.008, substeps);
    const OnSlope rolls = on_slope(0.012, substeps);
    INFO(substeps << " substeps: on 0.8 % it moved " << held.moved * 1e3 << " mm (last turn " << held.turn
                  << " rad); on 1.2 % " << rolls.moved * 1e3 << " mm");
    CHECK(held.moved < 1e-5);
    CHECK(held.turn < 1e-9);
    CHECK(rolls.moved > 0.1);
  }
  // Without the hold (solver.rolling_hold false, the default) the same tire creeps on the gentle
  // slope: the velocity pass stops its spin each substep, and the position solve turns it again.
  const OnSlope creeps = on_slope(0.005, 2, false);
  INFO("without the hold, on 0.5 % it moved " << creeps.moved * 1e3 << " mm in 10 s");
  CHECK(creeps.moved > 1e-3);
}

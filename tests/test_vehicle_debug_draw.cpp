// Simulation::debug_draw with vehicles (tire/world/debug_draw.h, DebugShape::head): each driver's
// head, which the level session keeps, is reported with the structure as the circle the level
// watches and a line to its chassis' centre of mass, where the drawer draws the chassis.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "tire/engine.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {

// Keeps the head's shapes; moves every chassis by `shift` (as a drawer between ticks would).
class HeadRecorder : public DebugDraw {
 public:
  void segment(Vec2 a, Vec2 b, DebugShape kind) override {
    if (kind == DebugShape::head) segments.push_back({a, b});
  }
  void polygon(std::span<const Vec2> points, DebugShape kind) override {
    if (kind == DebugShape::head) rings.emplace_back(points.begin(), points.end());
  }
  void point(Vec2, DebugShape) override {}
  void vector(Vec2, Vec2, DebugShape) override {}
  void box(const Aabb&, DebugShape) override {}
  Pose prop_pose(std::uint32_t, const Pose& now) override {
    return Pose::make(now.position + shift, now.angle);
  }

  Vec2 shift;
  std::vector<std::vector<Vec2>> rings;
  std::vector<std::array<Vec2, 2>> segments;
};

}  // namespace

TEST_CASE("debug drawing: a driver's head is its circle and a line to the chassis' centre of mass",
          "[unit][debug_draw][vehicle_level]") {
  const SimulationLoad load = Simulation::load(source_path("tests/levels/vehicle-car.json"));
  REQUIRE(load.simulation);
  Simulation& sim = *load.simulation;
  for (int i = 0; i < 30; ++i) sim.step({1.0});
  const VehicleView v = *sim.vehicle_at(0);
  REQUIRE(v.head_center);

  HeadRecorder none;
  none.set_flags(DebugDraw::contacts | DebugDraw::velocities | DebugDraw::bounds);
  sim.debug_draw(none);
  CHECK(none.rings.empty());  // only with the structure

  HeadRecorder draw;
  draw.set_flags(DebugDraw::structure);
  sim.debug_draw(draw);
  REQUIRE(draw.rings.size() == 1);
  REQUIRE(draw.segments.size() == 1);
  Vec2 sum;
  for (const Vec2 p : draw.rings[0]) {
    CHECK(length(p - *v.head_center) == Approx(v.head_radius).epsilon(1e-9));
    sum += p;
  }
  CHECK(length(sum / static_cast<double>(draw.rings[0].size()) - *v.head_center) < 1e-9);
  CHECK(length(draw.segments[0][0] - v.center) < 1e-9);
  CHECK(length(draw.segments[0][1] - *v.head_center) < 1e-9);

  // A drawer that draws the chassis elsewhere (blended between ticks) gets the head there too.
  HeadRecorder moved;
  moved.set_flags(DebugDraw::structure);
  moved.shift = {1.0, 0.5};
  sim.debug_draw(moved);
  REQUIRE(moved.segments.size() == 1);
  CHECK(length(moved.segments[0][1] - (*v.head_center + moved.shift)) < 1e-9);
}

// World::debug_draw (tire/world/debug_draw.h): a recording DebugDraw sees, for each flag, exactly
// the tire's rings, spokes, contacts and broad-phase lists, and nothing the flags leave out.
#include <catch2/catch.hpp>
#include <vector>

#include "tire/world/debug_draw.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {

enum class Primitive { segment, polygon, point, vector, box };

struct Shape {
  Primitive primitive;
  DebugShape kind;
  std::vector<Vec2> points;  // segment: a, b; polygon: its points; point: p; vector: at, v; box: min, max
};

// Keeps every call, in order.
class Recorder : public DebugDraw {
 public:
  void segment(Vec2 a, Vec2 b, DebugShape kind) override {
    shapes.push_back({Primitive::segment, kind, {a, b}});
  }
  void polygon(std::span<const Vec2> points, DebugShape kind) override {
    shapes.push_back({Primitive::polygon, kind, {points.begin(), points.end()}});
  }
  void point(Vec2 p, DebugShape kind) override { shapes.push_back({Primitive::point, kind, {p}}); }
  void vector(Vec2 at, Vec2 v, DebugShape kind) override {
    shapes.push_back({Primitive::vector, kind, {at, v}});
  }
  void box(const Aabb& b, DebugShape kind) override {
    shapes.push_back({Primitive::box, kind, {b.min, b.max}});
  }
  std::span<const Vec2> tire_positions(const TireView& t) override {
    ++position_calls;
    return DebugDraw::tire_positions(t);
  }

  std::vector<const Shape*> of(Primitive primitive, DebugShape kind) const {
    std::vector<const Shape*> out;
    for (const Shape& s : shapes)
      if (s.primitive == primitive && s.kind == kind) out.push_back(&s);
    return out;
  }

  std::vector<Shape> shapes;
  int position_calls = 0;
};

// One tire resting on a ground box, beside a static crate (a prop its broad phase finds).
World resting_tire() {
  World world = flat_world(tire_at({0, 0.52}));
  PropSpec crate;
  crate.name = "crate";
  crate.type = PropType::static_body;
  crate.position = {0.9, 0.2};
  crate.size = {0.4, 0.4};
  world.add_prop(crate);
  run(world, 60);
  return world;
}

Recorder drawn(const World& world, unsigned flags) {
  Recorder r;
  r.set_flags(flags);
  world.debug_draw(r);
  return r;
}

}  // namespace

TEST_CASE("a debug drawing with no flags draws nothing", "[unit][debug_draw]") {
  const World world = resting_tire();
  const Recorder r = drawn(world, 0);
  CHECK(r.shapes.empty());
  CHECK(r.position_calls == 0);  // nor asks where to draw a tire
}

TEST_CASE("the structure is the tire's two rings, their particles and its spokes", "[unit][debug_draw]") {
  const World world = resting_tire();
  const Tire& t = world.tires().front();
  const std::uint32_t n = t.segments();
  const Recorder r = drawn(world, DebugDraw::structure);

  const auto tread = r.of(Primitive::polygon, DebugShape::tread);
  const auto rim = r.of(Primitive::polygon, DebugShape::rim);
  REQUIRE(tread.size() == 1);
  REQUIRE(rim.size() == 1);
  CHECK(tread[0]->points.size() + rim[0]->points.size() == 2 * n);  // closed rings: 2N segments
  for (std::uint32_t i = 0; i < n; ++i) {
    CHECK(tread[0]->points[i] == t.particles.x[i]);
    CHECK(rim[0]->points[i] == t.particles.x[n + i]);
  }
  CHECK(r.of(Primitive::point, DebugShape::tread).size() == n);
  CHECK(r.of(Primitive::point, DebugShape::rim).size() == n);

  const auto spokes = r.of(Primitive::segment, DebugShape::spoke);
  const auto& constraints = t.distance.constraints();
  REQUIRE(spokes.size() == constraints.size() - t.spokes_first());
  for (std::size_t k = 0; k < spokes.size(); ++k) {
    const DistanceConstraint& c = constraints[t.spokes_first() + k];
    CHECK(spokes[k]->points[0] == t.particles.x[c.a]);
    CHECK(spokes[k]->points[1] == t.particles.x[c.b]);
  }
  CHECK(r.shapes.size() == 2 + 2 * n + spokes.size());  // nothing else
}

TEST_CASE("the contacts are the particles touching the ground, with its normal", "[unit][debug_draw]") {
  const World world = resting_tire();
  const Tire& t = world.tires().front();
  const Recorder r = drawn(world, DebugDraw::contacts);

  const auto points = r.of(Primitive::point, DebugShape::contact);
  const auto normals = r.of(Primitive::vector, DebugShape::contact);
  REQUIRE(t.touching_particles() > 0);
  CHECK(points.size() == t.touching_particles());
  REQUIRE(normals.size() == points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    CHECK(normals[k]->points[0] == points[k]->points[0]);
    CHECK(normals[k]->points[1] == Vec2{0.0, 1.0});  // the top face of the ground box
    CHECK(points[k]->points[0].y == Approx(0.0).margin(1e-3));
  }
  CHECK(r.shapes.size() == 2 * points.size());
}

TEST_CASE("the velocity is drawn at the hub", "[unit][debug_draw]") {
  const World world = resting_tire();
  const Tire& t = world.tires().front();
  const Recorder r = drawn(world, DebugDraw::velocities);
  REQUIRE(r.shapes.size() == 1);
  const auto v = r.of(Primitive::vector, DebugShape::velocity);
  REQUIRE(v.size() == 1);
  CHECK(v[0]->points[0].x == Approx(t.centroid().x));
  CHECK(v[0]->points[0].y == Approx(t.centroid().y));
  CHECK(v[0]->points[1] == t.velocity());
}

TEST_CASE("the bounds box the tire, the props and the obstacles", "[unit][debug_draw]") {
  const World world = resting_tire();
  const Tire& t = world.tires().front();
  const Recorder r = drawn(world, DebugDraw::bounds);

  const auto tire_box = r.of(Primitive::box, DebugShape::tire_bounds);
  REQUIRE(tire_box.size() == 1);
  for (const Vec2& p : t.particles.x) {
    CHECK(p.x >= tire_box[0]->points[0].x);
    CHECK(p.y >= tire_box[0]->points[0].y);
    CHECK(p.x <= tire_box[0]->points[1].x);
    CHECK(p.y <= tire_box[0]->points[1].y);
  }
  const auto prop_box = r.of(Primitive::box, DebugShape::prop_bounds);
  REQUIRE(prop_box.size() == 1);
  CHECK(prop_box[0]->points[0].x == Approx(0.7));
  CHECK(prop_box[0]->points[0].y == Approx(0.0).margin(1e-6));
  CHECK(prop_box[0]->points[1].x == Approx(1.1));
  CHECK(prop_box[0]->points[1].y == Approx(0.4));
  const auto obstacle_box = r.of(Primitive::box, DebugShape::obstacle_bounds);
  REQUIRE(obstacle_box.size() == 1);
  CHECK(obstacle_box[0]->points[0] == world.rigid().obstacles()[0].box.min);
  CHECK(obstacle_box[0]->points[1] == world.rigid().obstacles()[0].box.max);
  CHECK(r.shapes.size() == 3);
}

TEST_CASE("the broad phase shows each tire's candidates and its narrow-phase pairs", "[unit][debug_draw]") {
  const World world = resting_tire();
  const Tire& t = world.tires().front();
  REQUIRE(t.candidates.size() == 1);       // the ground
  REQUIRE(t.prop_candidates.size() == 1);  // the crate
  REQUIRE(!t.pairs.empty());
  const Recorder r = drawn(world, DebugDraw::broadphase);

  CHECK(r.of(Primitive::box, DebugShape::candidate_obstacle).size() == 1);
  CHECK(r.of(Primitive::segment, DebugShape::candidate_obstacle).size() == 1);
  CHECK(r.of(Primitive::box, DebugShape::candidate_prop).size() == 1);
  const auto links = r.of(Primitive::segment, DebugShape::candidate_prop);
  REQUIRE(links.size() == 1);
  CHECK(links[0]->points[0].x == Approx(t.centroid().x));  // from the hub
  CHECK(links[0]->points[1].x == Approx(0.9));             // to the crate's centre
  CHECK(links[0]->points[1].y == Approx(0.2));
  CHECK(r.of(Primitive::point, DebugShape::pair).size() == t.pairs.size());
  CHECK(r.shapes.size() == 4 + t.pairs.size());
}

TEST_CASE("a drawer that says where tires and props are drawn gets everything there", "[unit][debug_draw]") {
  // As the game does, drawing between ticks: here everything one metre to the right.
  class Shifted : public Recorder {
   public:
    std::span<const Vec2> tire_positions(const TireView& t) override {
      moved.clear();
      for (const Vec2& p : t.positions) moved.push_back(p + Vec2{1.0, 0.0});
      return moved;
    }
    Pose prop_pose(std::uint32_t, const Pose& now) override {
      return Pose::make(now.position + Vec2{1.0, 0.0}, now.angle);
    }
    std::vector<Vec2> moved;
  };
  const World world = resting_tire();
  const Tire& t = world.tires().front();
  Shifted r;
  r.set_flags(DebugDraw::structure | DebugDraw::contacts | DebugDraw::velocities | DebugDraw::bounds);
  world.debug_draw(r);
  const auto tread = r.of(Primitive::polygon, DebugShape::tread);
  REQUIRE(tread.size() == 1);
  CHECK(tread[0]->points[0] == t.particles.x[0] + Vec2{1.0, 0.0});
  for (const Shape* c : r.of(Primitive::point, DebugShape::contact)) CHECK(c->points[0].x > 0.5);
  CHECK(r.of(Primitive::vector, DebugShape::velocity)[0]->points[0].x == Approx(t.centroid().x + 1.0));
  CHECK(r.of(Primitive::box, DebugShape::prop_bounds)[0]->points[0].x == Approx(1.7));
}

// The broad phase: Box2D's tree answers which obstacles are near, in a stable order. A prop's state
// as Box2D holds it, read without Box2D.
#include <catch2/catch.hpp>
#include <random>

#include "tire/rigid/rigid_world.h"

using namespace tire;

TEST_CASE("the broad phase finds every overlapping obstacle and few others, sorted", "[unit][broadphase]") {
  RigidWorld field({0, -9.81});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-500, 500), size(0.1, 3);
  for (int i = 0; i < 2000; ++i) {
    const Vec2 min{pos(rng), pos(rng)};
    field.add_obstacle({{min, min + Vec2{size(rng), size(rng)}}});
  }
  std::vector<std::uint32_t> found, props;
  for (int q = 0; q < 200; ++q) {
    const Vec2 c{pos(rng), pos(rng)};
    const Aabb region{c - Vec2{2, 2}, c + Vec2{2, 2}};
    field.query(region, found, props);
    REQUIRE(std::is_sorted(found.begin(), found.end()));
    std::size_t overlapping = 0;
    for (std::uint32_t i = 0; i < field.obstacles().size(); ++i) {
      if (!field.obstacles()[i].box.overlaps(region)) continue;
      ++overlapping;
      REQUIRE(std::binary_search(found.begin(), found.end(), i));  // nothing missed
    }
    CHECK(found.size() <= overlapping + 4);  // only fattened-AABB near misses on top
  }
}

TEST_CASE("a prop's state is its Box2D body's, in the engine's types", "[unit][props]") {
  RigidWorld rigid({0, -10});
  PropSpec crate;
  crate.name = "crate";
  crate.type = PropType::dynamic_body;
  crate.position = {1.0, 2.0};
  crate.angle = 0.5;
  crate.size = {0.4, 0.2};
  crate.density = 50.0;
  crate.velocity = {3.0, 0.0};
  crate.angular_velocity = 2.0;
  const std::uint32_t i = rigid.add_prop(crate);
  PropSpec wall;
  wall.type = PropType::static_body;
  const std::uint32_t j = rigid.add_prop(wall);

  const PropState s = rigid.prop_state(i);
  CHECK(s.pose.position.x == Approx(1.0));
  CHECK(s.pose.position.y == Approx(2.0));
  CHECK(s.pose.angle == Approx(0.5));
  CHECK(s.center.x == Approx(1.0));  // a box's centre of mass is its origin
  CHECK(s.velocity.x == Approx(3.0));
  CHECK(s.angular_velocity == Approx(2.0));
  const double mass = 50.0 * 0.4 * 0.2;
  CHECK(s.mass == Approx(mass));
  CHECK(s.inertia == Approx(mass * (0.4 * 0.4 + 0.2 * 0.2) / 12.0));  // about the centre
  CHECK(s.awake);
  const PropState fixed = rigid.prop_state(j);
  CHECK(fixed.mass == 0.0);
  CHECK(fixed.inertia == 0.0);
}

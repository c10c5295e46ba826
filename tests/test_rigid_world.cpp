// The broad phase: Box2D's tree answers which obstacles are near, in a stable order.
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

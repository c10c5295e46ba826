#include "obstacle_field.h"

#include <box2d/box2d.h>

#include <algorithm>

namespace tire {

namespace {

class CollectFixtures final : public b2QueryCallback {
 public:
  explicit CollectFixtures(std::vector<std::uint32_t>& out) : out_(out) {}
  bool ReportFixture(b2Fixture* fixture) override {
    out_.push_back(static_cast<std::uint32_t>(fixture->GetUserData().pointer));
    return true;  // keep going: we want every candidate
  }

 private:
  std::vector<std::uint32_t>& out_;
};

b2Vec2 to_b2(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

}  // namespace

ObstacleField::ObstacleField() : world_(std::make_unique<b2World>(b2Vec2{0.0f, 0.0f})) {
  b2BodyDef def;
  def.type = b2_staticBody;
  ground_ = world_->CreateBody(&def);
}

ObstacleField::~ObstacleField() = default;
ObstacleField::ObstacleField(ObstacleField&&) noexcept = default;
ObstacleField& ObstacleField::operator=(ObstacleField&&) noexcept = default;

std::uint32_t ObstacleField::add(const Obstacle& obstacle) {
  const auto index = static_cast<std::uint32_t>(obstacles_.size());
  obstacles_.push_back(obstacle);
  const Vec2 half = (obstacle.box.max - obstacle.box.min) * 0.5;
  const Vec2 center = (obstacle.box.max + obstacle.box.min) * 0.5;
  b2PolygonShape shape;
  shape.SetAsBox(static_cast<float>(half.x), static_cast<float>(half.y), to_b2(center), 0.0f);
  b2FixtureDef fixture;
  fixture.shape = &shape;
  fixture.friction = static_cast<float>(obstacle.friction);
  fixture.userData.pointer = index;
  ground_->CreateFixture(&fixture);
  return index;
}

void ObstacleField::query(const Aabb& region, std::vector<std::uint32_t>& out) const {
  out.clear();
  // Widen by a float ulp's worth so rounding to float never drops a touching box.
  const Aabb r = region.expanded(1e-3 + 1e-6 * std::max({std::abs(region.min.x), std::abs(region.min.y),
                                                         std::abs(region.max.x), std::abs(region.max.y)}));
  b2AABB aabb;
  aabb.lowerBound = to_b2(r.min);
  aabb.upperBound = to_b2(r.max);
  CollectFixtures collect(out);
  world_->QueryAABB(&collect, aabb);
  std::sort(out.begin(), out.end());
}

}  // namespace tire

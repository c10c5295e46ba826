// The static obstacles, held as static bodies in a Box2D world so that "which obstacles are near
// this tire" is answered by Box2D's broad phase (a dynamic AABB tree), not by a loop over all of
// them. Box2D stores float AABBs fattened by b2_aabbExtension; they serve only as candidates, the
// exact test runs on the double-precision boxes kept here.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "obstacle.h"

class b2World;
class b2Body;

namespace tire {

class ObstacleField {
 public:
  ObstacleField();
  ~ObstacleField();
  ObstacleField(const ObstacleField&) = delete;
  ObstacleField& operator=(const ObstacleField&) = delete;
  ObstacleField(ObstacleField&&) noexcept;
  ObstacleField& operator=(ObstacleField&&) noexcept;

  std::uint32_t add(const Obstacle& obstacle);
  const std::vector<Obstacle>& obstacles() const { return obstacles_; }
  const Obstacle& operator[](std::uint32_t i) const { return obstacles_[i]; }

  // Replaces `out` with the indices of the obstacles whose boxes may overlap `region`, in
  // ascending order (so the solver's order never depends on the tree's layout). Does not allocate
  // once `out` has grown to the largest answer.
  void query(const Aabb& region, std::vector<std::uint32_t>& out) const;

 private:
  std::unique_ptr<b2World> world_;
  b2Body* ground_ = nullptr;  // one static body carries every obstacle fixture
  std::vector<Obstacle> obstacles_;
};

}  // namespace tire

// A rigid body's pose in the plane: where its origin is and how far it has turned (rad, CCW), with
// the cosine and sine of the turn kept, so that moving points between its frame and the world's
// costs no trigonometry.
#pragma once

#include "tire/math/aabb.h"
#include "tire/math/vec2.h"

namespace tire {

struct Pose {
  Vec2 position;
  double angle = 0.0;
  double cos_a = 1.0;
  double sin_a = 0.0;

  static Pose make(Vec2 position, double angle);
  Vec2 to_world(Vec2 local) const { return position + rotate(local); }
  Vec2 to_local(Vec2 world) const {
    const Vec2 d = world - position;
    return {cos_a * d.x + sin_a * d.y, -sin_a * d.x + cos_a * d.y};
  }
  Vec2 rotate(Vec2 v) const { return {cos_a * v.x - sin_a * v.y, sin_a * v.x + cos_a * v.y}; }
  // The world box around the local box `local` placed at this pose: its four corners, moved.
  Aabb to_world(const Aabb& local) const {
    const Vec2 corners[4] = {to_world(local.min), to_world({local.max.x, local.min.y}), to_world(local.max),
                             to_world({local.min.x, local.max.y})};
    return bounds_of(corners);
  }
};

}  // namespace tire

// An axis-aligned box, min < max on both axes.
#pragma once

#include <algorithm>
#include <span>

#include "tire/math/vec2.h"

namespace tire {

struct Aabb {
  Vec2 min;
  Vec2 max;

  constexpr bool overlaps(const Aabb& o) const {
    return min.x <= o.max.x && o.min.x <= max.x && min.y <= o.max.y && o.min.y <= max.y;
  }
  constexpr Aabb expanded(double margin) const {
    return {{min.x - margin, min.y - margin}, {max.x + margin, max.y + margin}};
  }
};

// The smallest box holding `points` (at least one), taken in order.
inline Aabb bounds_of(std::span<const Vec2> points) {
  Aabb box{points.front(), points.front()};
  for (const Vec2& p : points) {
    box.min = {std::min(box.min.x, p.x), std::min(box.min.y, p.y)};
    box.max = {std::max(box.max.x, p.x), std::max(box.max.y, p.y)};
  }
  return box;
}

}  // namespace tire

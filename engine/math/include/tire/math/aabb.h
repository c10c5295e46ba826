// An axis-aligned box, min < max on both axes.
#pragma once

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

}  // namespace tire

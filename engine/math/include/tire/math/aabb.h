// An axis-aligned box, min < max on both axes.
#pragma once

#include <algorithm>
#include <limits>
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

  // The box holding nothing (min above max): include() of a point makes it that point.
  static constexpr Aabb none() {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {{inf, inf}, {-inf, -inf}};
  }
  constexpr bool holds_nothing() const { return min.x > max.x; }
  // Grows the box to hold p.
  constexpr void include(Vec2 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y)};
  }
};

// The smallest box holding `points` (at least one), taken in order.
inline Aabb bounds_of(std::span<const Vec2> points) {
  Aabb box = Aabb::none();
  for (const Vec2& p : points) box.include(p);
  return box;
}

}  // namespace tire

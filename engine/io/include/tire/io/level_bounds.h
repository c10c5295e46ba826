// A level's bounds: the box the player must stay inside (levels/README.md, "bounds"). Leaving it
// loses the level, or, in a level with checkpoints, puts the player back at the last one
// (LevelSession). A side the level does not give is computed from its geometry, `margin` beyond it.
#pragma once

#include <optional>

#include "tire/math/geometry.h"

namespace tire {

struct Level;

struct LevelBounds {
  // The corners as the level gives them; none: computed from the level's geometry.
  std::optional<Vec2> min, max;
  double margin = 10.0;  // m: how far below and beside the geometry a computed side lies
  // The box in force, filled by the level reader from the above. A computed top is open (+inf): a
  // jump or a bounce never leaves the level upwards, the fall after it does.
  Aabb box;

  bool contains(Vec2 p) const {
    return p.x >= box.min.x && p.x <= box.max.x && p.y >= box.min.y && p.y <= box.max.y;
  }
};

// The box around everything the level places: its obstacles, its props (kinematic ones along their
// paths), its regions, its tires where they start, and, from its script, the tires and props it
// spawns and its checkpoints. A level with none of those: the box around the origin.
Aabb level_extent(const Level& level);

// The box in force: `bounds.min` and `bounds.max` where given; otherwise `extent` grown by
// `bounds.margin` below and at the sides, and open above.
Aabb resolve_bounds(const LevelBounds& bounds, const Aabb& extent);

}  // namespace tire

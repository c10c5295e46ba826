// A static axis-aligned obstacle with exact minimal-overlap contact.
#pragma once

#include "tire/math/aabb.h"

namespace tire {

struct Obstacle {
  Aabb box;
  double friction = 1.0;  // mixed with the tire's as sqrt(μ_tire · μ_obstacle), as Box2D does
};

}  // namespace tire

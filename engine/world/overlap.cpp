#include "tire/world/overlap.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "tire/world/world.h"

namespace tire {

namespace {

// How deep p is inside the closed polygon `tread` (counter-clockwise): its distance to the nearest
// edge when an even–odd crossing test puts it inside, else 0.
double depth_inside(Vec2 p, std::span<const Vec2> tread) {
  bool inside = false;
  double nearest2 = HUGE_VAL;
  for (std::size_t k = 0, j = tread.size() - 1; k < tread.size(); j = k++) {
    const Vec2 u = tread[j], v = tread[k];
    if ((u.y > p.y) != (v.y > p.y) && p.x < u.x + (v.x - u.x) * (p.y - u.y) / (v.y - u.y)) inside = !inside;
    const Vec2 e = v - u;
    const double e2 = length_squared(e);
    const double s = e2 > 0.0 ? std::clamp(dot(p - u, e) / e2, 0.0, 1.0) : 0.0;
    nearest2 = std::min(nearest2, length_squared(p - (u + e * s)));
  }
  return inside ? std::sqrt(nearest2) : 0.0;
}

}  // namespace

TireOverlap deepest_tire_overlap(const World& world) {
  const std::vector<Tire>& tires = world.tires();
  struct Bound {
    Vec2 hub;
    double reach = 0.0;  // the farthest tread particle from the hub
    std::size_t index = 0;
  };
  std::vector<Bound> bounds;
  bounds.reserve(tires.size());
  for (std::size_t i = 0; i < tires.size(); ++i) {
    const Tire& t = tires[i];
    const std::span<const Vec2> tread(t.particles.x.data(), t.n);
    Bound b{t.centroid(), 0.0, i};
    for (const Vec2 x : tread) b.reach = std::max(b.reach, length(x - b.hub));
    bounds.push_back(b);
  }
  // In order of each bound's left end, ties by index: the same pairs in the same order every run.
  std::sort(bounds.begin(), bounds.end(), [](const Bound& a, const Bound& b) {
    const double la = a.hub.x - a.reach, lb = b.hub.x - b.reach;
    return la != lb ? la < lb : a.index < b.index;
  });
  TireOverlap deepest;
  const auto test = [&](const Tire& a, const Tire& b) {  // a's particles in b's tread
    const std::span<const Vec2> tread(b.particles.x.data(), b.n);
    for (std::uint32_t i = 0; i < a.n; ++i) {
      const double d = depth_inside(a.particles.x[i], tread);
      if (d > deepest.depth) deepest = {d, a.id, b.id};
    }
  };
  for (std::size_t k = 0; k < bounds.size(); ++k)
    for (std::size_t j = k + 1; j < bounds.size(); ++j) {
      const Bound &a = bounds[k], &b = bounds[j];
      if (b.hub.x - b.reach > a.hub.x + a.reach) break;  // every later bound starts further right
      if (length(a.hub - b.hub) > a.reach + b.reach) continue;
      test(tires[a.index], tires[b.index]);
      test(tires[b.index], tires[a.index]);
    }
  return deepest;
}

}  // namespace tire

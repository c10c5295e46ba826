#include "tire/math/turn.h"

#include "tire/math/check.h"
#include "tire/math/trig.h"

namespace tire {

double turn_between(std::span<const Vec2> from, std::span<const Vec2> to) {
  TIRE_ASSERT(from.size() == to.size(), "a turn between point sets of different sizes");
  const Vec2 a = mean(from), b = mean(to);
  double c = 0.0, s = 0.0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    const Vec2 r = from[i] - a, q = to[i] - b;
    c += dot(r, q);
    s += cross(r, q);
  }
  return c == 0.0 && s == 0.0 ? 0.0 : tire::atan2(s, c);
}

bool turn_gradient(std::span<const Vec2> from, std::span<Vec2> out) {
  TIRE_ASSERT(from.size() == out.size(), "a turn's gradient of another size than its points");
  const Vec2 a = mean(from);
  double inertia = 0.0;  // Σ |rⱼ|²
  for (const Vec2& p : from) inertia += length_squared(p - a);
  if (!(inertia > 0.0)) return false;
  const double scale = 1.0 / inertia;
  for (std::size_t i = 0; i < from.size(); ++i) out[i] = perp(from[i] - a) * scale;
  return true;
}

}  // namespace tire

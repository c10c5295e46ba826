// The plane's geometry: a 2D vector of doubles (Vec2), an axis-aligned box (Aabb) and a rigid
// body's pose (Pose).
//
// Doubles, not floats: a level spans ±10 km and a float has only millimetre resolution out there,
// which is larger than a stiff constraint's stretch.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace tire {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2() = default;
  constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}

  constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
  constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
  constexpr Vec2 operator-() const { return {-x, -y}; }
  constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
  constexpr Vec2 operator/(double s) const { return {x / s, y / s}; }
  constexpr Vec2& operator+=(Vec2 o) {
    x += o.x;
    y += o.y;
    return *this;
  }
  constexpr Vec2& operator-=(Vec2 o) {
    x -= o.x;
    y -= o.y;
    return *this;
  }
  constexpr Vec2& operator*=(double s) {
    x *= s;
    y *= s;
    return *this;
  }
  constexpr bool operator==(const Vec2&) const = default;
};

constexpr Vec2 operator*(double s, Vec2 v) { return {s * v.x, s * v.y}; }
constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
// z-component of the 3D cross product: positive when b is counter-clockwise of a.
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
// a rotated by +90 degrees (counter-clockwise).
constexpr Vec2 perp(Vec2 a) { return {-a.y, a.x}; }
// v turned counter-clockwise by the angle whose cosine and sine are c and s.
constexpr Vec2 rotate(Vec2 v, double c, double s) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }
constexpr double length_squared(Vec2 a) { return dot(a, a); }
inline double length(Vec2 a) { return std::sqrt(dot(a, a)); }
// The mean of the points, summed in order (a tire's centroid: its particles weigh the same).
inline Vec2 mean(std::span<const Vec2> points) {
  Vec2 sum;
  for (const Vec2& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}
inline bool is_finite(Vec2 a) { return std::isfinite(a.x) && std::isfinite(a.y); }

// An axis-aligned box, min < max on both axes.
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

// A rigid body's pose in the plane: where its origin is and how far it has turned (rad, CCW), with
// the cosine and sine of the turn kept, so that moving points between its frame and the world's
// costs no trigonometry.
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
  Vec2 rotate(Vec2 v) const { return tire::rotate(v, cos_a, sin_a); }
  // The world box around the local box `local` placed at this pose: its four corners, moved.
  Aabb to_world(const Aabb& local) const {
    const Vec2 corners[4] = {to_world(local.min), to_world({local.max.x, local.min.y}), to_world(local.max),
                             to_world({local.min.x, local.max.y})};
    return bounds_of(corners);
  }
};

}  // namespace tire

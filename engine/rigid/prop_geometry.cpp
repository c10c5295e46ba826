#include "tire/rigid/prop_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "tire/math/trig.h"
#include "tire/xpbd/area_constraint.h"

namespace tire {

PropGeometry PropGeometry::from_spec(const PropSpec& spec) {
  PropGeometry g;
  g.shape = spec.shape;
  switch (spec.shape) {
    case PropShape::box: {
      const Vec2 h = spec.size * 0.5;
      g.vertices = {{-h.x, -h.y}, {h.x, -h.y}, {h.x, h.y}, {-h.x, h.y}};
      break;
    }
    case PropShape::polygon: g.vertices = spec.points; break;
    case PropShape::circle:
      g.radius = spec.radius;
      g.bounds = {{-g.radius, -g.radius}, {g.radius, g.radius}};
      return g;
    case PropShape::chain:
      g.vertices = spec.points;
      g.loop = spec.loop;
      g.thickness = spec.thickness;
      // A closed chain is solid inside: with counter-clockwise points the inside is on the left,
      // so reverse them to keep "solid on the right".
      if (g.loop && polygon_area(g.vertices.data(), static_cast<std::uint32_t>(g.vertices.size())) > 0.0)
        std::reverse(g.vertices.begin(), g.vertices.end());
      break;
  }
  const std::size_t n = g.vertices.size();
  const std::size_t edges = (g.shape == PropShape::chain && !g.loop) ? n - 1 : n;
  for (std::size_t i = 0; i < edges; ++i) {
    const Vec2 d = g.vertices[(i + 1) % n] - g.vertices[i];
    // Polygon (CCW): outward is to the right of each edge. Chain: solid on the right, so the
    // surface faces left. Both are ±perp(d).
    const Vec2 right{d.y, -d.x};
    const Vec2 normal = g.shape == PropShape::chain ? -right : right;
    g.normals.push_back(normal * (1.0 / length(normal)));
  }
  const Aabb box = bounds_of(g.vertices);
  g.bounds = g.shape == PropShape::chain ? box.expanded(g.thickness) : box;
  if (g.shape == PropShape::chain) {
    // Each edge's box widened by the thickness, and by a hair more than rounding could take a
    // point's distance from its line past it (a few ulps of the largest coordinate).
    const double scale =
        std::max({std::abs(box.min.x), std::abs(box.min.y), std::abs(box.max.x), std::abs(box.max.y), 1.0});
    g.edges.build(g.vertices, edges, g.thickness + 1e-9 * scale);
  }
  return g;
}

namespace {

std::optional<SurfaceContact> circle_contact(double r, Vec2 from, Vec2 to) {
  const double d2 = length_squared(to);
  if (d2 >= r * r) {
    // Crossed the whole circle in one substep? Closest approach of the segment to the centre.
    const Vec2 seg = to - from;
    const double len2 = length_squared(seg);
    if (len2 <= 0.0) return std::nullopt;
    const double t = std::clamp(-dot(from, seg) / len2, 0.0, 1.0);
    if (t <= 0.0 || t >= 1.0 || length_squared(from + seg * t) >= r * r) return std::nullopt;
    const Vec2 n = from * (1.0 / length(from));  // back out on the side it came from
    return SurfaceContact{n, r - dot(to, n)};
  }
  const double d = std::sqrt(d2);
  // At the exact centre there is no nearest direction: use the side it came from.
  const Vec2 n =
      d > 0.0 ? to * (1.0 / d) : (length(from) > 0.0 ? from * (1.0 / length(from)) : Vec2{0.0, 1.0});
  return SurfaceContact{n, r - d};
}

std::optional<SurfaceContact> polygon_contact(const PropGeometry& g, Vec2 from, Vec2 to) {
  const std::size_t n = g.vertices.size();
  // Separation of `to` and `from` from each edge's line (negative: on the inner side).
  double best_to = -std::numeric_limits<double>::infinity();
  std::size_t best_edge = 0;
  std::size_t outside_from = 0, from_edge = 0;
  bool inside_to = true;
  for (std::size_t i = 0; i < n; ++i) {
    const double s_to = dot(g.normals[i], to - g.vertices[i]);
    const double s_from = dot(g.normals[i], from - g.vertices[i]);
    if (s_to >= 0.0) inside_to = false;
    if (s_to > best_to) best_to = s_to, best_edge = i;
    if (s_from >= 0.0) ++outside_from, from_edge = i;
  }
  if (inside_to) {
    if (outside_from == 0)
      return SurfaceContact{g.normals[best_edge], -best_to};  // started inside: least overlap
    if (outside_from == 1)  // came in through the one edge it was outside of
      return SurfaceContact{g.normals[from_edge], -dot(g.normals[from_edge], to - g.vertices[from_edge])};
  } else if (outside_from == 0) {
    return std::nullopt;  // left the polygon: nothing to push
  }
  // Cyrus–Beck clip of the segment against the polygon: the entry edge is where it comes in.
  const Vec2 d = to - from;
  double t_enter = 0.0, t_exit = 1.0;
  std::size_t enter_edge = n;
  for (std::size_t i = 0; i < n; ++i) {
    const double denom = dot(g.normals[i], d);
    const double num = -dot(g.normals[i], from - g.vertices[i]);
    if (denom == 0.0) {
      if (num < 0.0) return std::nullopt;  // parallel and outside this edge
      continue;
    }
    const double t = num / denom;
    if (denom < 0.0) {
      if (t > t_enter) t_enter = t, enter_edge = i;
    } else {
      t_exit = std::min(t_exit, t);
    }
  }
  if (enter_edge == n || t_enter >= t_exit) return std::nullopt;
  const double depth = -dot(g.normals[enter_edge], to - g.vertices[enter_edge]);
  if (depth <= 0.0) return std::nullopt;
  return SurfaceContact{g.normals[enter_edge], depth};
}

// Whether `p` is inside the chain's solid: behind an edge's line by less than `thickness`, within
// the edge's extent. Only the edges near p are asked (EdgeTree).
bool inside_chain(const PropGeometry& g, Vec2 p) {
  const std::size_t n = g.vertices.size();
  bool inside = false;
  g.edges.visit({p, p}, [&](std::size_t i) {
    const Vec2 a = g.vertices[i], edge = g.vertices[(i + 1) % n] - a;
    const double s = dot(g.normals[i], p - a);
    if (s >= 0.0 || s <= -g.thickness) return true;
    const double t = dot(p - a, edge) / length_squared(edge);
    inside = t >= 0.0 && t <= 1.0;
    return !inside;
  });
  return inside;
}

// One-sided thick chain: inside an edge means behind its line by less than `thickness`, within
// its extent. A particle that crossed an edge's line from the front this substep is sent back
// through that edge; one already inside at the substep's start is pushed out through the edge it
// is least deep behind, if a surface held it at the end of the substep before (`held`). One that
// comes in from behind the solid (from below a floating slope, or past its end) passes, as through
// Box2D's one-sided edges: pushed out through the front, it would be thrown by up to `thickness` in
// one substep (a tire driven up under level 07's slope left it at 105 m/s).
std::optional<SurfaceContact> chain_contact(const PropGeometry& g, Vec2 from, Vec2 to, bool held) {
  const std::size_t n = g.vertices.size();
  std::optional<SurfaceContact> best;
  const bool from_inside = held && inside_chain(g, from);
  // Only the edges whose thick box meets the path's box can hold `to` or be crossed by the path
  // (EdgeTree), and they come in ascending order, as a loop over every edge would meet them.
  g.edges.visit(bounds_of(std::array{from, to}), [&](std::size_t i) {
    const Vec2 a = g.vertices[i], b = g.vertices[(i + 1) % n];
    const Vec2 normal = g.normals[i];
    const double s_to = dot(normal, to - a);
    if (s_to >= 0.0 || s_to <= -g.thickness) return true;
    const Vec2 edge = b - a;
    const double s_from = dot(normal, from - a);
    if (s_from < 0.0 && !from_inside) return true;  // came from behind the solid
    double t;
    if (s_from >= 0.0) {
      // Crossed the line this substep: where along the edge?
      const double u = s_from / (s_from - s_to);
      t = dot(from + (to - from) * u - a, edge) / length_squared(edge);
    } else {
      t = dot(to - a, edge) / length_squared(edge);
    }
    if (t < 0.0 || t > 1.0) return true;
    const SurfaceContact c{normal, -s_to};
    // Prefer the edge it crossed (the first such); otherwise the least deep.
    if (!best || (s_from >= 0.0) || c.depth < best->depth) best = c;
    return s_from < 0.0;
  });
  return best;
}

}  // namespace

std::optional<SurfaceContact> local_contact(const PropGeometry& g, Vec2 from, Vec2 to, bool held) {
  switch (g.shape) {
    case PropShape::circle: return circle_contact(g.radius, from, to);
    case PropShape::box:
    case PropShape::polygon: return polygon_contact(g, from, to);
    case PropShape::chain: return chain_contact(g, from, to, held);
  }
  return std::nullopt;
}

bool is_convex_ccw(const std::vector<Vec2>& points) {
  const std::size_t n = points.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = points[i], b = points[(i + 1) % n], c = points[(i + 2) % n];
    if (cross(b - a, c - b) <= 0.0) return false;
  }
  // Left turns everywhere and exactly one revolution in all (a star also turns left everywhere,
  // but twice round).
  double turning = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = points[i], b = points[(i + 1) % n], c = points[(i + 2) % n];
    turning += tire::atan2(cross(b - a, c - b), dot(b - a, c - b));
  }
  return std::abs(turning - 2.0 * 3.141592653589793) < 1e-6;
}

namespace {

double segment_distance_squared(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = length_squared(ab);
  const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return length_squared(p - (a + ab * t));
}

}  // namespace

bool circle_touches(const PropGeometry& g, Vec2 center, double radius) {
  if (g.shape == PropShape::circle) return length(center) <= g.radius + radius;
  const std::vector<Vec2>& v = g.vertices;
  const std::size_t n = v.size();
  const bool closed = g.shape != PropShape::chain || g.loop;
  const double r2 = radius * radius;
  for (std::size_t i = 0; i + (closed ? 0 : 1) < n; ++i)
    if (segment_distance_squared(center, v[i], v[(i + 1) % n]) <= r2) return true;
  if (!closed || n < 3) return false;
  // Inside a closed outline (a convex polygon, or a closed chain of either winding): crossings.
  bool inside = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++)
    if ((v[i].y > center.y) != (v[j].y > center.y) &&
        center.x < v[j].x + (v[i].x - v[j].x) * (center.y - v[j].y) / (v[i].y - v[j].y))
      inside = !inside;
  return inside;
}

}  // namespace tire

// The edge tree of a chain prop: a particle's contact asks the edges near its path, not the chain,
// and gets what a loop over every edge would give.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "tire/rigid/edge_tree.h"
#include "tire/rigid/prop_geometry.h"

using namespace tire;

namespace {

// The chain's contact as a loop over every edge in order gives it (prop_geometry.h's rules: the
// first edge the path crossed, else the least deep edge holding its end, the first of equals; one
// that starts inside counts only if `held`): the reference the tree must match bit for bit.
bool inside_by_every_edge(const PropGeometry& g, Vec2 p) {
  const std::size_t n = g.vertices.size();
  for (std::size_t i = 0; i < g.normals.size(); ++i) {
    const Vec2 a = g.vertices[i], edge = g.vertices[(i + 1) % n] - a;
    const double s = dot(g.normals[i], p - a);
    if (s >= 0.0 || s <= -g.thickness) continue;
    const double t = dot(p - a, edge) / length_squared(edge);
    if (t >= 0.0 && t <= 1.0) return true;
  }
  return false;
}

std::optional<SurfaceContact> contact_by_every_edge(const PropGeometry& g, Vec2 from, Vec2 to, bool held) {
  const std::size_t n = g.vertices.size();
  std::optional<SurfaceContact> best;
  const bool from_inside = held && inside_by_every_edge(g, from);
  for (std::size_t i = 0; i < g.normals.size(); ++i) {
    const Vec2 a = g.vertices[i], b = g.vertices[(i + 1) % n];
    const Vec2 normal = g.normals[i];
    const double s_to = dot(normal, to - a);
    if (s_to >= 0.0 || s_to <= -g.thickness) continue;
    const Vec2 edge = b - a;
    const double s_from = dot(normal, from - a);
    if (s_from < 0.0 && !from_inside) continue;
    double t;
    if (s_from >= 0.0) {
      const double u = s_from / (s_from - s_to);
      t = dot(from + (to - from) * u - a, edge) / length_squared(edge);
    } else {
      t = dot(to - a, edge) / length_squared(edge);
    }
    if (t < 0.0 || t > 1.0) continue;
    const SurfaceContact c{normal, -s_to};
    if (!best || (s_from >= 0.0) || c.depth < best->depth) best = c;
    if (s_from >= 0.0) break;
  }
  return best;
}

// The bench's ground (tirectl bench chain-*): `points` points 0.2 m apart from x = −0.1·points,
// on a wave 2 cm high and 10 m long.
PropGeometry wave_chain(int points) {
  PropSpec spec;
  spec.shape = PropShape::chain;
  for (int k = 0; k < points; ++k) {
    const double x = -0.1 * points + 0.2 * k;
    spec.points.push_back({x, 0.02 * std::sin(2.0 * std::numbers::pi * x / 10.0)});
  }
  return PropGeometry::from_spec(spec);
}

}  // namespace

TEST_CASE("the edge tree visits every edge whose widened box meets the query, in ascending order",
          "[unit][props][contact]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> step(-1.0, 1.0), where(-12.0, 12.0), size(0.0, 3.0);
  for (const std::size_t points : {2u, 3u, 5u, 17u, 300u}) {
    std::vector<Vec2> line{{0.0, 0.0}};
    for (std::size_t k = 1; k < points; ++k) line.push_back(line.back() + Vec2{step(rng), step(rng)});
    for (const bool loop : {false, true}) {
      const std::size_t edges = loop ? points : points - 1;
      const double margin = 0.3;
      EdgeTree tree;
      tree.build(line, edges, margin);
      REQUIRE(tree.edge_count() == edges);
      for (int q = 0; q < 200; ++q) {
        const Vec2 c{where(rng) * 0.5, where(rng) * 0.5};
        const Aabb box{c, c + Vec2{size(rng), size(rng)}};
        std::vector<std::size_t> seen;
        const std::size_t visited = tree.visit(box, [&](std::size_t i) {
          seen.push_back(i);
          return true;
        });
        CHECK(visited == seen.size());
        CHECK(std::is_sorted(seen.begin(), seen.end()));
        CHECK(std::adjacent_find(seen.begin(), seen.end()) == seen.end());
        for (std::size_t i = 0; i < edges; ++i) {
          const Aabb edge = bounds_of(std::vector<Vec2>{line[i], line[(i + 1) % points]}).expanded(margin);
          if (edge.overlaps(box)) CHECK(std::binary_search(seen.begin(), seen.end(), i));
        }
      }
    }
  }
}

TEST_CASE("a chain's contact through its edge tree is the one every edge in order gives",
          "[unit][props][contact]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0), signed_unit(-1.0, 1.0);
  int contacts = 0, crossed = 0;
  for (int chain = 0; chain < 40; ++chain) {
    PropSpec spec;
    spec.shape = PropShape::chain;
    spec.loop = chain % 4 == 3;
    spec.thickness = 0.05 + 0.6 * unit(rng);
    // A wandering line: steps of 0.05 to 2 m, turning freely (it may cross itself).
    Vec2 p{0.0, 0.0};
    double heading = 0.0;
    const int points = 3 + static_cast<int>(unit(rng) * 60);
    for (int k = 0; k < points; ++k) {
      spec.points.push_back(p);
      heading += signed_unit(rng) * 1.2;
      p += Vec2{std::cos(heading), std::sin(heading)} * (0.05 + 1.95 * unit(rng));
    }
    const PropGeometry g = PropGeometry::from_spec(spec);
    for (int q = 0; q < 400; ++q) {
      // A path near a point of an edge: its end within two thicknesses of the line, its start up to
      // half a metre away (a crossing, a start inside, a pass behind).
      const std::size_t e = static_cast<std::size_t>(unit(rng) * static_cast<double>(g.normals.size()));
      const Vec2 a = g.vertices[e], b = g.vertices[(e + 1) % g.vertices.size()];
      const Vec2 on = a + (b - a) * (1.2 * unit(rng) - 0.1);
      const Vec2 to = on + g.normals[e] * (2.0 * g.thickness * signed_unit(rng));
      const Vec2 from = to + Vec2{signed_unit(rng), signed_unit(rng)} * 0.5;
      for (const bool held : {false, true}) {
        const auto want = contact_by_every_edge(g, from, to, held);
        const auto got = local_contact(g, from, to, held);
        REQUIRE(want.has_value() == got.has_value());
        if (!want) continue;
        ++contacts;
        crossed += dot(want->normal, from - to) > 0.0;
        CHECK(got->normal.x == want->normal.x);
        CHECK(got->normal.y == want->normal.y);
        CHECK(got->depth == want->depth);
      }
    }
  }
  // The cases were met, not only misses.
  CHECK(contacts > 3000);
  CHECK(crossed > 1000);
}

TEST_CASE("a particle's contact with a chain of 100 000 points asks a few of its edges",
          "[unit][props][contact]") {
  const PropGeometry g = wave_chain(100000);
  REQUIRE(g.edges.edge_count() == 99999);
  const auto edges_asked = [&](Vec2 from, Vec2 to) {
    return g.edges.visit(bounds_of(std::vector<Vec2>{from, to}), [](std::size_t) { return true; });
  };
  // A tread particle's path over a substep at the tire's top speed (15 m/s at 2 substeps: 0.125 m),
  // anywhere along the chain: the edges within the thickness (0.5 m) of it, each leaf's four.
  for (const double x : {-9999.0, -90.0, 0.0, 1234.5, 9990.0}) {
    const Vec2 from{x, 0.05}, to{x + 0.125, -0.01};
    const std::size_t asked = edges_asked(from, to);
    CHECK(asked >= 5);   // the ground is there
    CHECK(asked <= 16);  // and only it: (0.125 + 2 × 0.5) m of edges 0.2 m long, in leaves of 4
    const auto got = local_contact(g, from, to), want = contact_by_every_edge(g, from, to, true);
    REQUIRE(got.has_value() == want.has_value());
    if (got) CHECK((got->normal == want->normal && got->depth == want->depth));
  }
  // Far above or below the ground, none.
  CHECK(edges_asked({0.0, 3.0}, {0.1, 2.9}) == 0);
  CHECK(edges_asked({0.0, -3.0}, {0.1, -2.9}) == 0);
}

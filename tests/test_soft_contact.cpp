// Contacts between tires: no gap, no passing through, momentum kept, piles that settle.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>
#include <random>
#include <span>
#include <tuple>
#include <vector>

#include "tire/tire/soft_contact.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {
// Deepest any tread particle of `a` sits inside `b`'s tread polygon (0 when none is inside).
double deepest_inside(const Tire& a, const Tire& b) {
  double deepest = 0.0;
  const std::uint32_t n = b.n;
  for (std::uint32_t i = 0; i < a.n; ++i) {
    const Vec2 p = a.particles.x[i];
    double inside_by = 1e300;  // distance to the nearest edge line, if inside all of them
    bool inside = true;
    for (std::uint32_t k = 0; k < n && inside; ++k) {
      const Vec2 e = b.particles.x[(k + 1) % n] - b.particles.x[k];
      const double s = cross(e, p - b.particles.x[k]) / length(e);  // > 0: to the left (inside, CCW)
      if (s <= 0.0) inside = false;
      inside_by = std::min(inside_by, s);
    }
    if (inside) deepest = std::max(deepest, inside_by);
  }
  return deepest;
}
}  // namespace

TEST_CASE("the tire broad phase finds exactly the overlapping pairs, in a fixed order", "[unit][soft]") {
  std::vector<Tire> tires;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> pos(-20, 20);
  for (TireId i = 0; i < 60; ++i) tires.emplace_back(i, tire_at({pos(rng), pos(rng)}));
  TirePairFinder finder;
  std::vector<TirePair> pairs, again;
  std::vector<std::uint32_t> all(tires.size());
  std::iota(all.begin(), all.end(), 0u);
  finder.find(tires, all, 1.0 / 60.0, 0.0, 32, pairs);  // at rest: bounds grow by the skin only
  finder.find(tires, all, 1.0 / 60.0, 0.0, 32, again);
  REQUIRE(pairs.size() == again.size());
  for (std::size_t k = 0; k < pairs.size(); ++k)
    CHECK((pairs[k].a == again[k].a && pairs[k].b == again[k].b));
  std::size_t brute = 0;
  for (std::uint32_t i = 0; i < tires.size(); ++i)
    for (std::uint32_t j = i + 1; j < tires.size(); ++j) {
      // Square bounds of side 2R + 2·skin overlap when the hubs are that close on both axes.
      const Vec2 d = tires[i].centroid() - tires[j].centroid();
      const double side = 2 * 0.5 + 2 * kTirePairSkin;
      const bool near = std::abs(d.x) < side - 1e-9 && std::abs(d.y) < side - 1e-9;
      const bool listed =
          std::any_of(pairs.begin(), pairs.end(), [&](const TirePair& p) { return p.a == i && p.b == j; });
      if (near) CHECK(listed);
      brute += listed;
    }
  CHECK(brute == pairs.size());
}

namespace {
// Each tire's count of pairs.
std::vector<std::uint32_t> pairs_per_tire(std::size_t tires, std::span<const TirePair> pairs) {
  std::vector<std::uint32_t> count(tires, 0);
  for (const TirePair& p : pairs) {
    ++count[p.a];
    ++count[p.b];
  }
  return count;
}
}  // namespace

TEST_CASE("the tire broad phase keeps at most max_neighbours pairs a tire, the same ones every time",
          "[unit][soft]") {
  // 200 tires on one spot (each inside every other: 19 900 candidate pairs), and beside them,
  // far off, 60 spread over a field as in the test above.
  std::vector<Tire> tires;
  for (TireId i = 0; i < 200; ++i) tires.emplace_back(i, tire_at({0, 0}));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> pos(-20, 20);
  for (TireId i = 200; i < 260; ++i) tires.emplace_back(i, tire_at({100 + pos(rng), pos(rng)}));
  std::vector<std::uint32_t> all(tires.size());
  std::iota(all.begin(), all.end(), 0u);
  constexpr std::uint32_t kMax = 16;
  TirePairFinder finder;
  std::vector<TirePair> pairs, again, uncapped;
  finder.find(tires, all, 1.0 / 60.0, 0.0, kMax, pairs);
  CHECK(finder.capped());
  finder.find(tires, all, 1.0 / 60.0, 0.0, kMax, again);
  REQUIRE(pairs.size() == again.size());
  for (std::size_t k = 0; k < pairs.size(); ++k)
    CHECK((pairs[k].a == again[k].a && pairs[k].b == again[k].b));
  finder.find(tires, all, 1.0 / 60.0, 0.0, 1000, uncapped);
  CHECK_FALSE(finder.capped());
  CHECK(uncapped.size() > 19900);
  const std::vector<std::uint32_t> count = pairs_per_tire(tires.size(), pairs);
  for (std::uint32_t i = 0; i < 200; ++i) {
    INFO("tire " << i);
    CHECK(count[i] <= kMax);
    // Every tire of the heap keeps neighbours (ties of distance go to the nearest index): the
    // first and last have half as many, being at the ends.
    CHECK(count[i] >= kMax / 2);
  }
  // Kept pairs are candidates, each once, lowest index first; the spread tires, none of which has
  // kMax candidates, keep every pair they had.
  std::size_t spread_pairs = 0;
  for (const TirePair& p : uncapped) spread_pairs += p.a >= 200;
  std::size_t kept_spread = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const TirePair p = pairs[k];
    CHECK(p.a < p.b);
    CHECK(std::any_of(uncapped.begin(), uncapped.end(),
                      [&](const TirePair& u) { return u.a == p.a && u.b == p.b; }));
    if (k > 0) CHECK_FALSE((pairs[k - 1].a == p.a && pairs[k - 1].b == p.b));
    kept_spread += p.a >= 200;
  }
  CHECK(spread_pairs > 0);
  CHECK(kept_spread == spread_pairs);
}

TEST_CASE("tires heaped on one spot: each tread particle meets at most solver.tire_neighbours treads",
          "[unit][soft][physics]") {
  // 150 default tires all on one spot, over the ground: every tire inside every other. The work of
  // their contacts is bounded by counts: the pairs each tire keeps, and (global method) the tests
  // of a tread particle against a neighbour's tread in each search for contacts.
  SolverConfig config;
  config.method = GENERATE(SolverMethod::gauss_seidel, SolverMethod::global);
  config.sleep = false;
  config.tire_neighbours = 12;
  World world(config, {0, -9.81});
  world.add_obstacle({{{-50, -1}, {50, 0}}});
  constexpr std::uint32_t kTires = 150;
  for (std::uint32_t i = 0; i < kTires; ++i) world.add_tire(tire_at({0, 0.5}));
  for (int tick = 0; tick < 3; ++tick) {
    world.step({});
    const std::vector<std::uint32_t> count = pairs_per_tire(kTires, world.tire_pairs());
    CHECK(*std::max_element(count.begin(), count.end()) <= 12u);
    CHECK(*std::min_element(count.begin(), count.end()) >= 1u);
    if (config.method != SolverMethod::global) continue;
    for (const Tire& t : world.tires()) {
      const Tire::GlobalWork& w = t.global_work;
      REQUIRE(w.searches > 0);
      CHECK(w.tread_tests <= std::uint64_t{12} * t.n * w.searches);
      CHECK(w.tread_tests > 0);
    }
  }
  for (const Tire& t : world.tires()) CHECK(t.is_finite());
}

TEST_CASE("two tires colliding keep momentum and never pass into each other", "[unit][soft][physics]") {
  SolverConfig config;
  config.method = GENERATE(SolverMethod::gauss_seidel, SolverMethod::global);
  World world(config, {0, 0});
  TireSpec left = tire_at({-1.2, 0});
  left.velocity = {8, 0.5};
  TireSpec right = tire_at({1.2, 0.2});
  right.velocity = {-4, 0};
  right.mass = 20;
  world.add_tire(left);
  world.add_tire(right);
  const auto momentum = [&] {
    return world.tires()[0].velocity() * 10.0 + world.tires()[1].velocity() * 20.0;
  };
  const Vec2 before = momentum();
  double worst = 0.0;
  for (int i = 0; i < 90; ++i) {
    world.step({});
    worst = std::max({worst, deepest_inside(world.tires()[0], world.tires()[1]),
                      deepest_inside(world.tires()[1], world.tires()[0])});
  }
  const Vec2 after = momentum();
  INFO("velocities after: " << world.tires()[0].velocity().x << ", " << world.tires()[1].velocity().x);
  CHECK(world.tires()[0].velocity().x < 0.0);             // they bounced off each other
  CHECK(after.x == Approx(before.x).margin(1e-9 * 160));  // scale: |p| of each tire is 80 N·s
  CHECK(after.y == Approx(before.y).margin(1e-9 * 160));
  CHECK(worst < 0.02);  // at most a small overlap within a step, corrected: no passing through
  CHECK(length(world.tires()[0].centroid() - world.tires()[1].centroid()) > 0.9);
}

TEST_CASE("a tire resting in the groove of two others stays there, and can jump off",
          "[unit][soft][physics]") {
  // (One tire balanced on another is an unstable equilibrium and rolls off, as real wheels do.)
  World world = flat_world(tire_at({-0.5, 0.5}));
  world.add_obstacle({{{-2, 0}, {-1, 3}}});
  world.add_obstacle({{{1, 0}, {2, 3}}});
  world.add_tire(tire_at({0.5, 0.5}));
  world.add_tire(tire_at({0.02, 1.5}, true));
  run(world, 300);
  const Tire& top = world.tires()[2];
  // In the groove: the hubs form a triangle of side about 2R, so the top hub is near 0.5 + √3·0.5.
  CHECK(top.centroid().y == Approx(0.5 + std::sqrt(3.0) * 0.5).margin(0.06));
  for (int k = 0; k < 2; ++k) CHECK(deepest_inside(top, world.tires()[static_cast<std::size_t>(k)]) < 0.005);
  CHECK(top.grounded());  // standing on a tire counts as ground
  world.step({0.0, true});
  run(world, 5);
  CHECK(top.velocity().y > 2.0);
}

TEST_CASE("a pile of tires in a box settles without overlaps or NaN", "[unit][soft][physics]") {
  // Gauss–Seidel at its default, and the global method at 8 substeps and at 2, where its contacts
  // between tires need the tires solved a colour at a time, mass splitting and the clamp on pushes
  // (tire_neighbours.h).
  SolverConfig config;
  std::tie(config.method, config.substeps) =
      GENERATE(std::make_tuple(SolverMethod::gauss_seidel, 8), std::make_tuple(SolverMethod::global, 8),
               std::make_tuple(SolverMethod::global, 2));
  CAPTURE(method_name(config.method), config.substeps);
  World world(config, {0, -9.81});
  world.add_obstacle({{{-10, -1}, {10, 0}}});
  world.add_obstacle({{{-4, 0}, {-3, 10}}});
  world.add_obstacle({{{3, 0}, {4, 10}}});
  for (int i = 0; i < 16; ++i)
    world.add_tire(tire_at({-2.0 + 1.1 * (i % 4) + 0.1 * (i / 4), 0.6 + 1.2 * (i / 4)}));
  run(world, 600);
  double worst = 0.0, fastest = 0.0, least_area = 1.0;
  for (const Tire& a : world.tires()) {
    REQUIRE(a.is_finite());
    fastest = std::max(fastest, length(a.velocity()));
    least_area = std::min(least_area, a.area_ratio());
    for (const Tire& b : world.tires())
      if (&a != &b) worst = std::max(worst, deepest_inside(a, b));
  }
  CHECK(worst < 0.01);
  CHECK(fastest < 0.05);
  CHECK(world.warnings().empty());
  if (config.method == SolverMethod::global) CHECK(least_area > 0.995);  // as stiff as its material
}

TEST_CASE("global: a column of tires between walls is as stiff as its tires, at 2 and 8 substeps",
          "[unit][soft][physics][global]") {
  // Six tires stacked between frictionless walls (tires without friction: the walls only keep the
  // column upright, so the weight goes down the column). Each contact carries the tires above. The
  // reference is Gauss–Seidel at 128 substeps (hubs 0.9916, 0.9920 and 0.9924 m apart, bottom up,
  // after 16 s); Gauss–Seidel at 8 × 1 sags to 0.937 m between the bottom two (docs/physics.md, "The
  // global method"). Solving each tire's neighbours inside its system keeps the spacing and the areas at
  // 2 and 8 substeps. (At 32 substeps and more the global column sags, 0.970 m at 32: see docs/physics.md.)
  SolverConfig config;
  config.method = SolverMethod::global;
  config.substeps = GENERATE(2, 8);
  CAPTURE(config.substeps);
  World world(config, {0, -9.81});
  world.add_obstacle({{{-10, -1}, {10, 0}}});
  world.add_obstacle({{{-1.3, 0}, {-0.51, 20}}});
  world.add_obstacle({{{0.51, 0}, {1.3, 20}}});
  for (int k = 0; k < 6; ++k) {
    TireSpec spec = tire_at({0.0, 0.5 + 1.0 * k});
    spec.friction = 0.0;
    spec.kinetic_friction = 0.0;
    world.add_tire(spec);
  }
  run(world, 960);
  for (std::size_t k = 0; k < 6; ++k) {
    CAPTURE(k);
    const Tire& t = world.tires()[k];
    CHECK(t.area_ratio() > 0.998);
    if (k == 0) continue;
    const double gap = t.centroid().y - world.tires()[k - 1].centroid().y;
    CHECK(gap == Approx(0.992).margin(0.006));
    CHECK(deepest_inside(t, world.tires()[k - 1]) < 0.005);
  }
  CHECK(world.warnings().empty());
}

TEST_CASE("a tread particle inside another tire is projected along the particle-edge gradient",
          "[unit][soft]") {
  // C = n·(p − (1−t) b0 − t b1) ≥ 0 with ∇_p C = n, ∇_b0 C = −(1−t) n, ∇_b1 C = −t n: one
  // projection of the real solve_tire_contact moves each of the three by w ∇C Δλ with
  // Δλ = −C / Σ w|∇C|² (XPBD eq. 17–18, α = 0), the gradients taken by finite differences; that
  // puts p on the edge and, the gradients summing to zero, keeps momentum.
  TireSpec spec = tire_at({0.0, 0.0});
  spec.friction = 0.0;  // the normal projection alone
  Tire b(0, spec);
  spec.position = {1.2, 0.0};
  Tire a(1, spec);
  const std::uint32_t n = b.n;
  // B's tread edge facing +x, and the particle of A facing B, moved 1 cm inside that edge, off centre.
  std::uint32_t k = 0, i = 0;
  for (std::uint32_t j = 0; j < n; ++j) {
    if (b.particles.x[j].x + b.particles.x[(j + 1) % n].x > b.particles.x[k].x + b.particles.x[(k + 1) % n].x)
      k = j;
    if (a.particles.x[j].x < a.particles.x[i].x) i = j;
  }
  const std::uint32_t k1 = (k + 1) % n;
  const Vec2 b0 = b.particles.x[k], b1 = b.particles.x[k1], e = b1 - b0;
  const Vec2 normal = Vec2{e.y, -e.x} * (1.0 / length(e));  // outward
  const double t = 0.3;
  a.particles.x[i] = b0 + e * t - normal * 0.01;
  for (Tire* tire : {&a, &b}) {
    tire->tread_hub = {};
    for (std::uint32_t j = 0; j < n; ++j) tire->tread_hub += tire->particles.x[j] / static_cast<double>(n);
    tire->tread_reach = 0.0;
    for (std::uint32_t j = 0; j < n; ++j)
      tire->tread_reach = std::max(tire->tread_reach, length(tire->particles.x[j] - tire->tread_hub));
  }
  const std::vector<Vec2> a_before(a.particles.x.begin(), a.particles.x.end()),
      b_before(b.particles.x.begin(), b.particles.x.end());
  const Vec2 p = a_before[i];
  const double C = dot(normal, p - b0 - e * t);
  REQUIRE(C == Approx(-0.01));

  // The gradients, by central differences of C written from its definition: the signed distance of
  // p from the line of the edge (b0, b1), positive outside.
  const auto line_C = [](Vec2 q, Vec2 e0, Vec2 e1) {
    const Vec2 d = e1 - e0;
    return (d.y * (q.x - e0.x) - d.x * (q.y - e0.y)) / std::hypot(d.x, d.y);
  };
  const double eps = 1e-7;
  const auto fd = [&](int which) {
    const auto at = [&](Vec2 dq) {
      return line_C(p + (which == 0 ? dq : Vec2{}), b0 + (which == 1 ? dq : Vec2{}),
                    b1 + (which == 2 ? dq : Vec2{}));
    };
    return Vec2{(at({eps, 0}) - at({-eps, 0})) / (2 * eps), (at({0, eps}) - at({0, -eps})) / (2 * eps)};
  };
  const Vec2 grad_p = fd(0), grad_b0 = fd(1), grad_b1 = fd(2);
  CHECK(line_C(p, b0, b1) == Approx(C).margin(1e-12));
  CHECK(length(grad_p - normal) < 1e-7);             // ∇_p C = n
  CHECK(length(grad_b0 + normal * (1 - t)) < 1e-7);  // ∇_b0 C = −(1−t) n
  CHECK(length(grad_b1 + normal * t) < 1e-7);        // ∇_b1 C = −t n

  solve_tire_contact(a, b, 0.7);

  const double wp = a.particles.w[i], w0 = b.particles.w[k], w1 = b.particles.w[k1];
  const double delta_lambda =
      -C / (wp * length_squared(grad_p) + w0 * length_squared(grad_b0) + w1 * length_squared(grad_b1));
  const Vec2 dp = a.particles.x[i] - p, db0 = b.particles.x[k] - b0, db1 = b.particles.x[k1] - b1;
  CHECK(dp.x == Approx(wp * delta_lambda * grad_p.x).margin(1e-10));
  CHECK(dp.y == Approx(wp * delta_lambda * grad_p.y).margin(1e-10));
  CHECK(db0.x == Approx(w0 * delta_lambda * grad_b0.x).margin(1e-10));
  CHECK(db0.y == Approx(w0 * delta_lambda * grad_b0.y).margin(1e-10));
  CHECK(db1.x == Approx(w1 * delta_lambda * grad_b1.x).margin(1e-10));
  CHECK(db1.y == Approx(w1 * delta_lambda * grad_b1.y).margin(1e-10));
  // Equal particle masses: Σ m Δx = 0 means the displacements cancel.
  const Vec2 momentum = dp + db0 + db1;
  CHECK(length(momentum) < 1e-15);
  // p now lies on the (moved) edge, to first order.
  const Vec2 e_after = b.particles.x[k1] - b.particles.x[k];
  const Vec2 n_after = Vec2{e_after.y, -e_after.x} * (1.0 / length(e_after));
  CHECK(std::abs(dot(n_after, a.particles.x[i] - b.particles.x[k] - e_after * t)) < 1e-4);
  // Nothing else moved.
  for (std::uint32_t j = 0; j < a.particle_count(); ++j)
    if (j != i) CHECK(a.particles.x[j] == a_before[j]);
  for (std::uint32_t j = 0; j < b.particle_count(); ++j)
    if (j != k && j != k1) CHECK(b.particles.x[j] == b_before[j]);
}

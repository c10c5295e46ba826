// The area (pressure) constraint: its gradient, and what its compliance means physically.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "tire/xpbd/area_constraint.h"
#include "tire/xpbd/particles.h"

using namespace tire;

namespace {
std::vector<Vec2> regular_polygon(int n, double radius, Vec2 centre = {}) {
  std::vector<Vec2> x;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    x.push_back(centre + Vec2{radius * std::cos(a), radius * std::sin(a)});
  }
  return x;
}
}  // namespace

TEST_CASE("polygon area is the shoelace area, positive counter-clockwise", "[unit][area]") {
  std::vector<Vec2> square{{0, 0}, {2, 0}, {2, 3}, {0, 3}};
  CHECK(polygon_area(square.data(), 4) == Approx(6.0));
  std::reverse(square.begin(), square.end());
  CHECK(polygon_area(square.data(), 4) == Approx(-6.0));
}

TEST_CASE("area constraint gradient matches finite differences", "[unit][area]") {
  std::vector<Vec2> x = regular_polygon(7, 1.3, {0.4, -2.0});
  x[2] += Vec2{0.2, -0.1};  // not regular: every vertex's gradient differs
  std::vector<Vec2> grad(x.size());
  polygon_area_gradient(x.data(), 7, grad.data());
  const double eps = 1e-7;
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (const Vec2 dir : {Vec2{1, 0}, Vec2{0, 1}}) {
      std::vector<Vec2> plus = x, minus = x;
      plus[i] += dir * eps;
      minus[i] -= dir * eps;
      const double fd = (polygon_area(plus.data(), 7) - polygon_area(minus.data(), 7)) / (2 * eps);
      INFO("vertex " << i);
      CHECK(dot(grad[i], dir) == Approx(fd).margin(1e-8));
    }
  }
}

TEST_CASE("a rigid area constraint restores the target area", "[unit][area]") {
  Particles p;
  p.resize(12);
  p.x = regular_polygon(12, 1.0);
  p.x_prev = p.x;
  std::fill(p.w.begin(), p.w.end(), 1.0);
  const double rest = polygon_area(p.x.data(), 12);
  for (Vec2& v : p.x) v *= 0.8;  // squash to 64 % of the area
  const AreaConstraint c{0, 12, rest, 1.0, 0.0};
  double lambda = 0.0;
  for (int it = 0; it < 4; ++it) solve_area_constraint(c, lambda, p.x.data(), p.w.data(), 1e4);
  CHECK(polygon_area(p.x.data(), 12) == Approx(rest).epsilon(1e-9));
}

TEST_CASE("an area compliance alpha under a pressure load P loses alpha*P of area",
          "[unit][area][physics]") {
  // A polygon of free particles held only by its area constraint, with an external inward
  // pressure: force −P ∇A on each vertex. At equilibrium the constraint force λ/h² balances P,
  // and C = −α λ/h² = −α P.  Mean over an oscillation, as for the hanging particle.
  const int n = 16;
  const double alpha = 1e-3, P = 10.0, m = 1.0;
  for (const int substeps : {4, 16, 64}) {
    const double h = (1.0 / 60.0) / substeps;
    Particles p;
    p.resize(n);
    p.x = regular_polygon(n, 1.0);
    std::fill(p.w.begin(), p.w.end(), 1.0 / m);
    const double rest = polygon_area(p.x.data(), n);
    const AreaConstraint c{0, static_cast<std::uint32_t>(n), rest, 1.0, alpha};
    std::vector<Vec2> grad(n);
    const int total = static_cast<int>(6.0 / h);
    double sum = 0.0;
    int count = 0;
    for (int s = 0; s < total; ++s) {
      polygon_area_gradient(p.x.data(), n, grad.data());
      for (int i = 0; i < n; ++i) p.v[i] -= grad[i] * (P / m * h);
      predict_positions(p, h);
      double lambda = 0.0;
      solve_area_constraint(c, lambda, p.x.data(), p.w.data(), 1.0 / (h * h));
      derive_velocities(p, h);
      if (s >= total / 2) sum += polygon_area(p.x.data(), n) - rest, ++count;
    }
    INFO("substeps " << substeps);
    CHECK(sum / count == Approx(-alpha * P).epsilon(0.02));
  }
}

TEST_CASE("area damping removes the rate of area change and nothing else", "[unit][area][physics]") {
  // Every vertex moving outward: the area grows. Damping slows the growth; a rigid translation
  // (no change of area) is left alone.
  Particles p;
  p.resize(8);
  p.x = regular_polygon(8, 1.0);
  std::fill(p.w.begin(), p.w.end(), 1.0);
  const AreaConstraint c{0, 8, polygon_area(p.x.data(), 8), 1.0, 1e-4};
  for (std::size_t i = 0; i < 8; ++i) p.v[i] = p.x[i] * 0.5;  // expanding
  std::vector<Vec2> grad(8);
  const auto rate = [&] {
    polygon_area_gradient(p.x.data(), 8, grad.data());
    double r = 0.0;
    for (std::size_t i = 0; i < 8; ++i) r += dot(grad[i], p.v[i]);
    return r;
  };
  const double before = rate();
  double sum_w_grad2 = 0.0;
  for (const Vec2& g : grad) sum_w_grad2 += length_squared(g);
  const double tau = 1e-3, h = 1e-3;
  damp_area_constraint(c, p.x.data(), p.v.data(), p.w.data(), tau, h);
  // Implicit dashpot c = τ/α: the rate decays to 1/(1 + (τ/α)·h·Σ w|∇A|²) of itself.
  CHECK(rate() == Approx(before / (1.0 + tau / c.compliance * h * sum_w_grad2)).epsilon(1e-12));
  for (Vec2& v : p.v) v = {3.0, -1.0};
  damp_area_constraint(c, p.x.data(), p.v.data(), p.w.data(), 1e-3, 1e-3);
  for (const Vec2& v : p.v) CHECK(length(v - Vec2{3.0, -1.0}) < 1e-12);
}

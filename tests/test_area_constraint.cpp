// The area (pressure) constraint: the gradient its real solve and dashpot use, and what its
// compliance means physically.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <span>
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

namespace {

// C(x) = A(x) − p·A0 with A the shoelace area, written here rather than taken from the engine: the
// solver's gradient is checked against this function's finite differences.
double area_constraint_value(std::span<const Vec2> x, std::size_t first, std::size_t count, double target) {
  double twice_area = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const Vec2 a = x[first + i], b = x[first + (i + 1) % count];
    twice_area += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice_area - target;
}

// ∂C/∂x_i for each vertex by central differences.
std::vector<Vec2> area_fd_gradient(std::span<const Vec2> x, std::size_t first, std::size_t count,
                                   double target) {
  const double eps = 1e-6;
  std::vector<Vec2> grad(count);
  for (std::size_t i = 0; i < count; ++i) {
    for (const Vec2 dir : {Vec2{1, 0}, Vec2{0, 1}}) {
      std::vector<Vec2> plus(x.begin(), x.end()), minus(x.begin(), x.end());
      plus[first + i] += dir * eps;
      minus[first + i] -= dir * eps;
      const double d = (area_constraint_value(plus, first, count, target) -
                        area_constraint_value(minus, first, count, target)) /
                       (2 * eps);
      (dir.x != 0.0 ? grad[i].x : grad[i].y) = d;
    }
  }
  return grad;
}

// A 9-gon, not regular (every vertex's gradient differs), at particles [2, 11) of 12: the
// particles around it must not move. Vertex masses differ; vertex 4 of the polygon is pinned.
struct Polygon {
  Particles p;
  AreaConstraint c;
};
Polygon irregular_polygon(double pressure, double compliance) {
  Polygon s;
  s.p = Particles(12);
  const std::vector<Vec2> ring = regular_polygon(9, 1.3, {0.4, -2.0});
  for (std::size_t i = 0; i < 9; ++i) {
    const auto k = static_cast<double>(i);
    s.p.x[2 + i] = ring[i] + Vec2{0.05 * static_cast<double>(i % 3), -0.04 * static_cast<double>(i % 4)};
    s.p.w[2 + i] = i == 4 ? 0.0 : 0.5 + 0.3 * static_cast<double>(i % 5);
    s.p.v[2 + i] = {0.3 * std::cos(1.1 * k) + 0.2, 0.4 * std::sin(0.9 * k)};
  }
  s.p.x[0] = {5, 5};
  s.p.x[1] = {-5, 5};
  s.p.x[11] = {0, 7};
  std::fill(s.p.w.begin(), s.p.w.begin() + 2, 1.0);
  s.p.w[11] = 1.0;
  const double rest = polygon_area(s.p.x.data() + 2, 9);
  s.c = AreaConstraint{2, 9, rest, pressure, compliance};
  return s;
}

}  // namespace

TEST_CASE("one projection of the real area solve moves along the finite-difference gradient",
          "[unit][area]") {
  // XPBD eq. 17-18 with λ = 0 at the start: vertex i moves by Δx_i = w_i ∇_i C Δλ with
  // Δλ = −C / (Σ_i w_i |∇_i C|² + α̃). The gradient the solver used is read off what it did,
  // ∇_i C = Δx_i / (w_i Δλ), and compared with finite differences of C.
  const double compliance = GENERATE(0.0, 1e-4);  // α̃ = 0, then 1
  const double h = 1e-2;
  const double alpha_tilde = compliance / (h * h);
  CAPTURE(compliance);
  const Polygon s = irregular_polygon(1.2, compliance);  // inflate by 20 %
  const double target = s.c.pressure * s.c.rest_area;
  const double C = area_constraint_value(s.p.x, 2, 9, target);
  REQUIRE(C < -0.1);
  const std::vector<Vec2> fd = area_fd_gradient(s.p.x, 2, 9, target);
  double sum_w_grad2 = 0.0;
  for (std::size_t i = 0; i < 9; ++i) sum_w_grad2 += s.p.w[2 + i] * length_squared(fd[i]);

  std::vector<Vec2> x(s.p.x.begin(), s.p.x.end());
  double lambda = 0.0;
  solve_area_constraint(s.c, lambda, x.data(), s.p.w.data(), 1.0 / (h * h));
  CHECK(lambda == Approx(-C / (sum_w_grad2 + alpha_tilde)).epsilon(1e-8));
  for (std::size_t i = 0; i < 9; ++i) {
    INFO("vertex " << i);
    const Vec2 dx = x[2 + i] - s.p.x[2 + i];
    if (s.p.w[2 + i] == 0.0) {
      CHECK(dx == Vec2{});
      continue;
    }
    const Vec2 grad = dx / (s.p.w[2 + i] * lambda);
    CHECK(grad.x == Approx(fd[i].x).margin(1e-8));
    CHECK(grad.y == Approx(fd[i].y).margin(1e-8));
  }
  for (const std::size_t j : {0, 1, 11}) CHECK(x[j] == s.p.x[j]);
  // polygon_area_gradient (what the pressure test below pushes with) agrees too.
  std::vector<Vec2> grad(9);
  polygon_area_gradient(s.p.x.data() + 2, 9, grad.data());
  for (std::size_t i = 0; i < 9; ++i) CHECK(length(grad[i] - fd[i]) < 1e-8);
}

TEST_CASE("the real area dashpot removes rate along the finite-difference gradient", "[unit][area]") {
  // damp_area_constraint: rate dA/dt = Σ_i ∇_i A · v_i, impulse p = rate·τh/(α + τh Σ_i w_i|∇_i A|²),
  // Δv_i = −w_i ∇_i A p. Predicted from finite-difference gradients, compared with what it did.
  const double h = 1e-3, tau = 2e-3, compliance = 1e-4;
  const Polygon s = irregular_polygon(1.0, compliance);
  const std::vector<Vec2> fd = area_fd_gradient(s.p.x, 2, 9, 0.0);
  double rate = 0.0, sum_w_grad2 = 0.0;
  for (std::size_t i = 0; i < 9; ++i) {
    rate += dot(fd[i], s.p.v[2 + i]);
    sum_w_grad2 += s.p.w[2 + i] * length_squared(fd[i]);
  }
  REQUIRE(std::abs(rate) > 0.1);
  const double impulse = rate * tau * h / (compliance + tau * h * sum_w_grad2);
  std::vector<Vec2> v(s.p.v.begin(), s.p.v.end());
  damp_area_constraint(s.c, s.p.x.data(), v.data(), s.p.w.data(), tau, h);
  for (std::size_t i = 0; i < 9; ++i) {
    INFO("vertex " << i);
    const Vec2 dv = v[2 + i] - s.p.v[2 + i];
    CHECK(dv.x == Approx(-s.p.w[2 + i] * fd[i].x * impulse).margin(1e-9));
    CHECK(dv.y == Approx(-s.p.w[2 + i] * fd[i].y * impulse).margin(1e-9));
  }
  for (const std::size_t j : {0, 1, 11}) CHECK(v[j] == s.p.v[j]);
}

TEST_CASE("a rigid area constraint restores the target area", "[unit][area]") {
  Particles p(12);
  p.x.assign(regular_polygon(12, 1.0));
  p.x_prev.assign(p.x);
  std::fill(p.w.begin(), p.w.end(), 1.0);
  const double rest = polygon_area(p.x.data(), 12);
  for (Vec2& v : p.x) v *= 0.8;  // squash to 64 % of the area
  const AreaConstraint c{0, 12, rest, 1.0, 0.0};
  double lambda = 0.0;
  for (int it = 0; it < 4; ++it) solve_area_constraint(c, lambda, p.x.data(), p.w.data(), 1e4);
  CHECK(polygon_area(p.x.data(), 12) == Approx(rest).epsilon(1e-9));
}

TEST_CASE("an area compliance alpha under a pressure load P loses alpha*P of area", "[unit][area][physics]") {
  // A polygon of free particles held only by its area constraint, with an external inward
  // pressure: force −P ∇A on each vertex. At equilibrium the constraint force λ/h² balances P,
  // and C = −α λ/h² = −α P.  Mean over an oscillation, as for the hanging particle.
  const int n = 16;
  const double alpha = 1e-3, P = 10.0, m = 1.0;
  for (const int substeps : {4, 16, 64}) {
    const double h = (1.0 / 60.0) / substeps;
    Particles p(n);
    p.x.assign(regular_polygon(n, 1.0));
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
  Particles p(8);
  p.x.assign(regular_polygon(8, 1.0));
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

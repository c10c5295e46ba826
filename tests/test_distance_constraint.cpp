// The distance constraint: its gradient, and what compliance means physically.
#include <catch2/catch.hpp>
#include <vector>

#include "distance_constraint.h"
#include "particles.h"

using namespace tire;

TEST_CASE("distance constraint gradient matches finite differences", "[unit][distance]") {
  const Vec2 xa{0.3, -0.2};
  const Vec2 xb{1.1, 0.45};
  const double rest = 0.7;
  const DistanceEval e = evaluate_distance(xa, xb, rest);
  const double eps = 1e-7;
  const auto C = [&](Vec2 a, Vec2 b) { return evaluate_distance(a, b, rest).C; };
  // ∂C/∂x_b by central differences, and ∂C/∂x_a = −∂C/∂x_b
  const Vec2 fd_b{(C(xa, xb + Vec2{eps, 0}) - C(xa, xb - Vec2{eps, 0})) / (2 * eps),
                  (C(xa, xb + Vec2{0, eps}) - C(xa, xb - Vec2{0, eps})) / (2 * eps)};
  const Vec2 fd_a{(C(xa + Vec2{eps, 0}, xb) - C(xa - Vec2{eps, 0}, xb)) / (2 * eps),
                  (C(xa + Vec2{0, eps}, xb) - C(xa - Vec2{0, eps}, xb)) / (2 * eps)};
  CHECK(e.grad_b.x == Approx(fd_b.x).margin(1e-8));
  CHECK(e.grad_b.y == Approx(fd_b.y).margin(1e-8));
  CHECK(-e.grad_b.x == Approx(fd_a.x).margin(1e-8));
  CHECK(-e.grad_b.y == Approx(fd_a.y).margin(1e-8));
  CHECK(e.C == Approx(length(xb - xa) - rest));
}

TEST_CASE("a rigid distance constraint is met exactly in one projection", "[unit][distance]") {
  Particles p;
  p.resize(2);
  p.x = {{0, 0}, {2, 0}};
  p.x_prev = p.x;
  p.w = {1.0, 3.0};
  std::vector<DistanceConstraint> c{{0, 1, 1.0, 0.0}};
  std::vector<double> lambda{0.0};
  prepare_distance_constraints(c, p.w.data(), 1.0 / (0.01 * 0.01));
  solve_distance_constraints(c, lambda, p.x.data(), p.w.data());
  CHECK(length(p.x[1] - p.x[0]) == Approx(1.0).margin(1e-12));
  // Corrections are weighted by inverse mass, so the centre of mass does not move.
  CHECK((p.x[0] * 1.0 + p.x[1] * (1.0 / 3.0)).x == Approx(2.0 / 3.0).margin(1e-12));
}

namespace {

// A particle of mass m hanging under gravity from a pinned anchor on a distance constraint of
// compliance α, stepped with the engine's XPBD substep for `seconds`. Returns the mean stretch
// over the second half: the oscillation about equilibrium averages out, leaving the static value.
double mean_hanging_stretch(double alpha, double m, int substeps, int iterations, double seconds) {
  const double g = 9.81, rest = 1.0, dt = 1.0 / 60.0, h = dt / substeps;
  Particles p;
  p.resize(2);
  p.x = {{0, 0}, {0, -rest}};
  p.w = {0.0, 1.0 / m};
  std::vector<DistanceConstraint> c{{0, 1, rest, alpha}};
  std::vector<double> lambda(1);
  prepare_distance_constraints(c, p.w.data(), 1.0 / (h * h));
  const int total = static_cast<int>(seconds / h);
  double sum = 0.0;
  int count = 0;
  for (int s = 0; s < total; ++s) {
    p.v[1].y -= g * h;
    predict_positions(p, h);
    lambda[0] = 0.0;
    for (int it = 0; it < iterations; ++it)
      solve_distance_constraints(c, lambda, p.x.data(), p.w.data());
    derive_velocities(p, h);
    if (s >= total / 2) sum += length(p.x[1] - p.x[0]) - rest, ++count;
  }
  return sum / count;
}

}  // namespace

TEST_CASE("a compliance alpha under weight mg stretches by alpha*mg, whatever the solver settings",
          "[unit][distance][physics]") {
  const double alpha = 1e-4, m = 1.0, expected = alpha * m * 9.81;  // ≈ 0.98 mm
  for (const int substeps : {4, 8, 16, 32, 64}) {
    for (const int iterations : {1, 2, 4, 8}) {
      INFO("substeps " << substeps << ", iterations " << iterations);
      const double stretch = mean_hanging_stretch(alpha, m, substeps, iterations, 4.0);
      CHECK(stretch == Approx(expected).epsilon(0.02));
    }
  }
}

TEST_CASE("a rigid distance constraint under load stays within 1e-4 m of its length",
          "[unit][distance][physics]") {
  for (const int substeps : {4, 16, 64}) {
    for (const int iterations : {1, 8}) {
      INFO("substeps " << substeps << ", iterations " << iterations);
      CHECK(std::abs(mean_hanging_stretch(0.0, 50.0, substeps, iterations, 1.0)) < 1e-4);
    }
  }
}

TEST_CASE("material damping removes the rate of stretch, implicitly, and leaves rigid motion alone",
          "[unit][distance][physics]") {
  // Two particles flying apart along x while the pair also moves and spins rigidly.
  const double tau = 1e-3, h = 1e-3, alpha = 1e-4;
  Particles p;
  p.resize(2);
  p.x = {{0, 0}, {1, 0}};
  p.w = {1.0, 1.0};
  std::vector<DistanceConstraint> c{{0, 1, 1.0, alpha}};
  const Vec2 rigid{2.0, 1.0};
  const double spin = 3.0;  // rad/s about the midpoint: tangential, no stretch
  p.v = {rigid + Vec2{-0.5, -0.5 * spin}, rigid + Vec2{0.5, 0.5 * spin}};
  damp_distance_constraints(c, p.x.data(), p.v.data(), p.w.data(), tau, h);
  // Implicit dashpot c = τ/α over h: the stretch rate 1.0 m/s decays to 1/(1 + (τ/α)·h·(w_a + w_b)).
  const double expected_rate = 1.0 / (1.0 + tau / alpha * h * 2.0);
  CHECK(p.v[1].x - p.v[0].x == Approx(expected_rate).epsilon(1e-12));
  CHECK(p.v[1].y - p.v[0].y == Approx(spin).epsilon(1e-12));         // the spin is untouched
  CHECK((p.v[0] + p.v[1]).x * 0.5 == Approx(rigid.x).epsilon(1e-12));  // momentum is kept
  CHECK((p.v[0] + p.v[1]).y * 0.5 == Approx(rigid.y).epsilon(1e-12));
  // A rigid constraint loses all of its stretch rate.
  c[0].compliance = 0.0;
  damp_distance_constraints(c, p.x.data(), p.v.data(), p.w.data(), tau, h);
  CHECK(p.v[1].x - p.v[0].x == Approx(0.0).margin(1e-12));
}

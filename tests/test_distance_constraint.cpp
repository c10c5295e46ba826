// The distance constraint: the gradient the real solver uses (both kernels), and what compliance
// means physically.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "tire/xpbd/distance_constraint.h"
#include "tire/xpbd/particles.h"

using namespace tire;

namespace {

// The constraint from its definition, C(x) = |x_b − x_a| − L0, written here rather than taken from
// the engine: the solver's gradient is checked against this function's finite differences.
double stretch(Vec2 a, Vec2 b, double rest) { return std::hypot(b.x - a.x, b.y - a.y) - rest; }

// ∂f/∂x by central differences, f a function of one particle's position.
template <typename F>
Vec2 central_difference(F&& f, Vec2 x) {
  const double eps = 1e-6;
  return {(f(x + Vec2{eps, 0}) - f(x - Vec2{eps, 0})) / (2 * eps),
          (f(x + Vec2{0, eps}) - f(x - Vec2{0, eps})) / (2 * eps)};
}

// 13 constraints that share no particle: 10 rigid ones (batches of 4, 4 and 2 lanes: full batches
// and a short one, whose unused lanes repeat its first), then 3 compliant ones (a batch of 3).
// Ends a weigh w = 0.7, ends b w = 1.9: the lanes of a batch share their inverse masses.
struct Independent {
  std::vector<DistanceConstraint> list;
  Particles p;
};
Independent independent_constraints(double alpha) {
  Independent s;
  s.p = Particles(26);
  for (std::uint32_t k = 0; k < 13; ++k) {
    const std::uint32_t a = 2 * k, b = 2 * k + 1;
    const double angle = 0.7 * k, len = 0.8 + 0.05 * k;
    s.p.x[a] = {0.3 * k - 1.0, 0.5 - 0.1 * k};
    s.p.x[b] = s.p.x[a] + Vec2{std::cos(angle), std::sin(angle)} * len;
    s.p.v[a] = {0.2 * (k % 3), -0.4 + 0.1 * k};
    s.p.v[b] = {-0.3 + 0.05 * k, 0.25 * (k % 4)};
    s.p.w[a] = 0.7;
    s.p.w[b] = 1.9;
    // Stretched or compressed by 15-20 %.
    s.list.push_back({a, b, len * (k % 2 == 0 ? 0.85 : 1.2), k < 10 ? 0.0 : alpha});
  }
  return s;
}

}  // namespace

TEST_CASE("one projection of the real solver moves along the finite-difference gradient, both kernels",
          "[unit][distance]") {
  // XPBD (Macklin et al. 2016) eq. 17-18 with λ = 0 at the start of the substep: the projection
  // moves end j by Δx_j = w_j ∇_j C Δλ with Δλ = −C / (Σ_j w_j |∇_j C|² + α̃). So the gradient the
  // solver used can be read off what it did, ∇_j C = Δx_j / (w_j Δλ), with Δλ the multiplier it
  // accumulated, and both are compared with finite differences of C.
  const auto kernel =
      GENERATE(DistanceConstraintSet::Kernel::automatic, DistanceConstraintSet::Kernel::scalar);
  CAPTURE(kernel == DistanceConstraintSet::Kernel::scalar);
  const double h = 1e-3, alpha = 1e-6, alpha_tilde = alpha / (h * h);  // α̃ = 1: as much as w_a + w_b
  const Independent s = independent_constraints(alpha);
  DistanceConstraintSet set(s.list);
  set.set_kernel(kernel);
  set.prepare(s.p.w.data(), h);
  REQUIRE(set.batch_count() == 4);
  std::vector<Vec2> x(s.p.x.begin(), s.p.x.end());
  set.solve(x.data());
  for (std::size_t k = 0; k < s.list.size(); ++k) {
    const DistanceConstraint& c = s.list[k];
    INFO("constraint " << k);
    const Vec2 xa = s.p.x[c.a], xb = s.p.x[c.b];
    const double C = stretch(xa, xb, c.rest_length);
    const Vec2 fd_a = central_difference([&](Vec2 q) { return stretch(q, xb, c.rest_length); }, xa);
    const Vec2 fd_b = central_difference([&](Vec2 q) { return stretch(xa, q, c.rest_length); }, xb);
    const double delta_lambda = set.lambda(k);
    const double expected_lambda =
        -C / (s.p.w[c.a] * length_squared(fd_a) + s.p.w[c.b] * length_squared(fd_b) +
              (c.compliance > 0 ? alpha_tilde : 0.0));
    CHECK(delta_lambda == Approx(expected_lambda).epsilon(1e-8));
    const Vec2 grad_a = (x[c.a] - xa) / (s.p.w[c.a] * delta_lambda);
    const Vec2 grad_b = (x[c.b] - xb) / (s.p.w[c.b] * delta_lambda);
    CHECK(grad_a.x == Approx(fd_a.x).margin(1e-8));
    CHECK(grad_a.y == Approx(fd_a.y).margin(1e-8));
    CHECK(grad_b.x == Approx(fd_b.x).margin(1e-8));
    CHECK(grad_b.y == Approx(fd_b.y).margin(1e-8));
  }
}

TEST_CASE("the real dashpot removes rate along the finite-difference gradient, both kernels",
          "[unit][distance]") {
  // damp(): the rate dC/dt = Σ_j ∇_j C · v_j, and the impulse p = rate·τh/(α + τh Σ_j w_j|∇_j C|²)
  // changes each velocity by Δv_j = −w_j ∇_j C p (the implicit Kelvin-Voigt dashpot). Predicted
  // from finite-difference gradients, compared with what the solver did.
  const auto kernel =
      GENERATE(DistanceConstraintSet::Kernel::automatic, DistanceConstraintSet::Kernel::scalar);
  CAPTURE(kernel == DistanceConstraintSet::Kernel::scalar);
  const double h = 1e-3, tau = 5e-3, alpha = 1e-4;
  const Independent s = independent_constraints(alpha);
  DistanceConstraintSet set(s.list);
  set.set_kernel(kernel);
  set.prepare(s.p.w.data(), h, tau);
  std::vector<Vec2> v(s.p.v.begin(), s.p.v.end());
  set.damp(s.p.x.data(), v.data());
  for (const DistanceConstraint& c : s.list) {
    INFO("constraint " << c.a / 2);
    const Vec2 xa = s.p.x[c.a], xb = s.p.x[c.b];
    const Vec2 fd_a = central_difference([&](Vec2 q) { return stretch(q, xb, c.rest_length); }, xa);
    const Vec2 fd_b = central_difference([&](Vec2 q) { return stretch(xa, q, c.rest_length); }, xb);
    const double rate = dot(fd_a, s.p.v[c.a]) + dot(fd_b, s.p.v[c.b]);
    const double tau_h = tau * h;
    const double impulse =
        rate * tau_h /
        (c.compliance + tau_h * (s.p.w[c.a] * length_squared(fd_a) + s.p.w[c.b] * length_squared(fd_b)));
    const Vec2 dv_a = v[c.a] - s.p.v[c.a], dv_b = v[c.b] - s.p.v[c.b];
    CHECK(dv_a.x == Approx(-s.p.w[c.a] * fd_a.x * impulse).margin(1e-8));
    CHECK(dv_a.y == Approx(-s.p.w[c.a] * fd_a.y * impulse).margin(1e-8));
    CHECK(dv_b.x == Approx(-s.p.w[c.b] * fd_b.x * impulse).margin(1e-8));
    CHECK(dv_b.y == Approx(-s.p.w[c.b] * fd_b.y * impulse).margin(1e-8));
    // A rigid constraint loses all of its rate, a compliant one part of it.
    const double rate_after = dot(fd_a, v[c.a]) + dot(fd_b, v[c.b]);
    if (c.compliance == 0.0)
      CHECK(rate_after == Approx(0.0).margin(1e-8));
    else
      CHECK(std::abs(rate_after) < std::abs(rate));
  }
}

TEST_CASE("a rigid distance constraint is met exactly in one projection", "[unit][distance]") {
  Particles p(2);
  p.x.assign({{0, 0}, {2, 0}});
  p.x_prev.assign(p.x);
  p.w.assign({1.0, 3.0});
  DistanceConstraintSet c({{0, 1, 1.0, 0.0}});
  c.prepare(p.w.data(), 0.01);
  c.solve(p.x.data());
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
  Particles p(2);
  p.x.assign({{0, 0}, {0, -rest}});
  p.w.assign({0.0, 1.0 / m});
  DistanceConstraintSet c({{0, 1, rest, alpha}});
  c.prepare(p.w.data(), h);
  const int total = static_cast<int>(seconds / h);
  double sum = 0.0;
  int count = 0;
  for (int s = 0; s < total; ++s) {
    p.v[1].y -= g * h;
    predict_positions(p, h);
    c.reset_lambda();
    for (int it = 0; it < iterations; ++it) c.solve(p.x.data());
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
  Particles p(2);
  p.x.assign({{0, 0}, {1, 0}});
  p.w.assign({1.0, 1.0});
  DistanceConstraintSet c({{0, 1, 1.0, alpha}});
  const Vec2 rigid{2.0, 1.0};
  const double spin = 3.0;  // rad/s about the midpoint: tangential, no stretch
  p.v.assign({rigid + Vec2{-0.5, -0.5 * spin}, rigid + Vec2{0.5, 0.5 * spin}});
  c.prepare(p.w.data(), h, tau);
  c.damp(p.x.data(), p.v.data());
  // Implicit dashpot c = τ/α over h: the stretch rate 1.0 m/s decays to 1/(1 + (τ/α)·h·(w_a + w_b)).
  const double expected_rate = 1.0 / (1.0 + tau / alpha * h * 2.0);
  CHECK(p.v[1].x - p.v[0].x == Approx(expected_rate).epsilon(1e-12));
  CHECK(p.v[1].y - p.v[0].y == Approx(spin).epsilon(1e-12));           // the spin is untouched
  CHECK((p.v[0] + p.v[1]).x * 0.5 == Approx(rigid.x).epsilon(1e-12));  // momentum is kept
  CHECK((p.v[0] + p.v[1]).y * 0.5 == Approx(rigid.y).epsilon(1e-12));
  // A rigid constraint loses all of its stretch rate.
  DistanceConstraintSet rigid_pair({{0, 1, 1.0, 0.0}});
  rigid_pair.prepare(p.w.data(), h, tau);
  rigid_pair.damp(p.x.data(), p.v.data());
  CHECK(p.v[1].x - p.v[0].x == Approx(0.0).margin(1e-12));
}

TEST_CASE("batched constraints solve exactly as one Gauss-Seidel sweep in their order", "[unit][distance]") {
  // A chain (even links, then odd ones) with shared particles and a few independent ones: batches
  // must keep the sequential result bit for bit, including the accumulated multipliers. Lanes of a
  // batch share compliance and inverse masses: with equal masses most links batch together, with
  // unequal ones (and a pinned particle) fewer do; either way the result is the sequential one.
  const bool equal_masses = GENERATE(true, false);
  CAPTURE(equal_masses);
  std::vector<DistanceConstraint> list;
  for (std::uint32_t parity = 0; parity < 2; ++parity)
    for (std::uint32_t i = parity; i + 1 < 17; i += 2)
      list.push_back({i, i + 1, 0.9 + 0.01 * i, 1e-5 * (i / 8)});
  list.push_back({0, 16, 7.0, 0.0});
  list.push_back({2, 6, 3.9, 1e-4});
  Particles p(17);
  for (std::uint32_t i = 0; i < 17; ++i) p.x[i] = {1.0 * i, 0.1 * (i % 3)};
  for (std::uint32_t i = 0; i < 17; ++i) p.w[i] = equal_masses ? 1.3 : i == 4 ? 0.0 : 1.0 + 0.1 * i;
  DistanceConstraintSet set(list);
  set.prepare(p.w.data(), 0.01);
  if (equal_masses) CHECK(set.batch_count() <= list.size() / 2);  // it did batch
  std::vector<Vec2> x(p.x.begin(), p.x.end());
  set.solve(x.data());
  // The reference: each constraint in order, one at a time.
  std::vector<Vec2> ref(p.x.begin(), p.x.end());
  for (std::size_t k = 0; k < list.size(); ++k) {
    DistanceConstraintSet one({list[k]});
    one.prepare(p.w.data(), 0.01);
    one.solve(ref.data());
    CHECK(set.lambda(k) == one.lambda(0));
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    CHECK(x[i].x == ref[i].x);
    CHECK(x[i].y == ref[i].y);
  }
}

TEST_CASE("the vector and the scalar kernels give the same bits", "[unit][distance][determinism]") {
  // Replays recorded on a machine with AVX must reproduce on one without. A ring (even links, then
  // odd ones: full batches of four), a few links of their own compliance, and spokes.
  std::vector<DistanceConstraint> list;
  for (std::uint32_t parity = 0; parity < 2; ++parity)
    for (std::uint32_t i = parity; i < 40; i += 2)
      list.push_back({i, (i + 1) % 40, 0.3, i % 9 == 0 ? 3e-6 : 1e-6});
  for (std::uint32_t parity = 0; parity < 2; ++parity)
    for (std::uint32_t i = parity; i < 20; i += 2) list.push_back({i, i + 20, 2.0, 1e-5});
  Particles p(40);
  for (std::uint32_t i = 0; i < 40; ++i) {
    p.x[i] = {std::cos(0.157 * i) * (1.0 + 0.01 * (i % 7)), std::sin(0.157 * i)};
    p.v[i] = {0.1 * (i % 5), -0.2 * (i % 3)};
    p.w[i] = 1.0 + 0.5 * (i % 2);
  }
  p.x[7] = p.x[8];  // coincident particles take the degenerate branch
  DistanceConstraintSet automatic(list), scalar(list);
  scalar.set_kernel(DistanceConstraintSet::Kernel::scalar);
  automatic.prepare(p.w.data(), 1e-3, 5e-3);
  scalar.prepare(p.w.data(), 1e-3, 5e-3);
  CHECK(automatic.batch_count() < list.size() / 2);  // mostly full batches, some short ones
  Particles a(p.size()), s(p.size());
  a.copy_from(p);
  s.copy_from(p);
  for (int it = 0; it < 5; ++it) {
    automatic.solve(a.x.data());
    scalar.solve(s.x.data());
    automatic.damp(a.x.data(), a.v.data());
    scalar.damp(s.x.data(), s.v.data());
  }
  for (std::size_t i = 0; i < 40; ++i) {
    REQUIRE(a.x[i].x == s.x[i].x);
    REQUIRE(a.x[i].y == s.x[i].y);
    REQUIRE(a.v[i].x == s.v[i].x);
    REQUIRE(a.v[i].y == s.v[i].y);
  }
  for (std::size_t k = 0; k < list.size(); ++k) REQUIRE(automatic.lambda(k) == scalar.lambda(k));
}

TEST_CASE("a new compliance or new masses take effect at the next prepare", "[unit][distance]") {
  // The batches are cut by compliance and inverse masses: tuning either must give exactly what a set
  // built with the new values gives.
  std::vector<DistanceConstraint> list;
  for (std::uint32_t parity = 0; parity < 2; ++parity)
    for (std::uint32_t i = parity; i < 12; i += 2) list.push_back({i, (i + 1) % 12, 0.5, 1e-6});
  Particles p(12);
  for (std::uint32_t i = 0; i < 12; ++i)
    p.x[i] = {std::cos(0.5 * i) * (1.0 + 0.02 * (i % 3)), std::sin(0.5 * i)};
  std::fill(p.w.begin(), p.w.end(), 2.0);
  DistanceConstraintSet tuned(list);
  tuned.prepare(p.w.data(), 1e-3);
  // Half the links softer, and one particle heavier.
  tuned.set_compliance(0, 3, 1e-4);
  p.w[5] = 0.5;
  tuned.prepare(p.w.data(), 1e-3);
  std::vector<DistanceConstraint> changed = list;
  for (std::size_t k = 0; k < 3; ++k) changed[k].compliance = 1e-4;
  DistanceConstraintSet fresh(changed);
  fresh.prepare(p.w.data(), 1e-3);
  std::vector<Vec2> a(p.x.begin(), p.x.end()), b(p.x.begin(), p.x.end());
  for (int it = 0; it < 3; ++it) {
    tuned.solve(a.data());
    fresh.solve(b.data());
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].x == b[i].x);
    CHECK(a[i].y == b[i].y);
  }
  CHECK(tuned.constraints()[0].compliance == 1e-4);
}

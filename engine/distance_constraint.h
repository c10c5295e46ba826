// Distance constraint C(x) = |x_b − x_a| − L0 (Macklin et al. 2016, "XPBD", Sec. 5; Müller et al.
// 2007, "Position Based Dynamics", Sec. 3.3), solved with XPBD compliance, accumulated λ and
// Rayleigh damping.
#pragma once

#include <cstdint>
#include <span>

#include "vec2.h"

namespace tire {

struct DistanceConstraint {
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  double rest_length = 0.0;  // L0 (m)
  double compliance = 0.0;   // α (m/N): inverse stiffness; 0 is rigid
  // Derived once per tick by prepare_distance_constraints (h and the masses are fixed within it):
  double alpha_tilde = 0.0;      // α̃ = α/h²  (XPBD eq. 4)
  double inv_denominator = 0.0;  // 1 / ((1 + γ)(w_a + w_b) + α̃), 0 when both ends are pinned
};

// C and ∇_{x_b}C = (x_b − x_a)/|x_b − x_a|; ∇_{x_a}C = −∇_{x_b}C. When the two particles coincide
// the gradient is undefined: it is returned as zero and the projection leaves them be.
struct DistanceEval {
  double C = 0.0;
  Vec2 grad_b;
};

inline DistanceEval evaluate_distance(Vec2 xa, Vec2 xb, double rest_length) {
  const Vec2 d = xb - xa;
  const double len = length(d);
  if (len <= 0.0) return {-rest_length, {}};
  return {len - rest_length, d * (1.0 / len)};
}

// The substep's constants shared by every projection.
struct ProjectionStep {
  double inv_h2 = 0.0;  // 1/h², so that α̃ = α/h²  (XPBD eq. 4)
  double gamma = 0.0;   // damping γ = α̃β̃/h (XPBD eq. 26); with Rayleigh damping β = τ/α it is τ/h
};

void prepare_distance_constraints(std::span<DistanceConstraint> constraints, const double* w,
                                  const ProjectionStep& step);

// One Gauss–Seidel sweep over `constraints`, always in the same order: the sweep's unconverged
// residual must look the same every substep, or v = (x − x_prev)/h turns its change into energy.
// `lambda[k]` is constraint k's accumulated multiplier for this substep; `x_prev` holds the
// positions at the start of the substep (for damping).
void solve_distance_constraints(std::span<const DistanceConstraint> constraints,
                                std::span<double> lambda, Vec2* x, const Vec2* x_prev, const double* w,
                                double gamma);

}  // namespace tire

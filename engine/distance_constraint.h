// Distance constraint C(x) = |x_b − x_a| − L0 (Macklin et al. 2016, "XPBD", Sec. 5; Müller et al.
// 2007, "Position Based Dynamics", Sec. 3.3), solved with XPBD compliance and accumulated λ, plus a
// dashpot in parallel (Kelvin–Voigt) applied to velocities.
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
  double inv_denominator = 0.0;  // 1 / (w_a + w_b + α̃), 0 when both ends are pinned
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

// Derives α̃ and the inverse denominator for substep h (inv_h2 = 1/h²).
void prepare_distance_constraints(std::span<DistanceConstraint> constraints, const double* w, double inv_h2);

// One Gauss–Seidel sweep over `constraints`, always in the same order: the sweep's unconverged
// residual must look the same every substep, or v = (x − x_prev)/h turns its change into energy.
// `lambda[k]` is constraint k's accumulated multiplier for this substep.
void solve_distance_constraints(std::span<const DistanceConstraint> constraints,
                                std::span<double> lambda, Vec2* x, const double* w);

// Kelvin–Voigt damping in the velocity pass (as Müller et al. 2020, Sec. 3.6, damp in theirs): a
// dashpot c = τ/α in parallel with each constraint's spring (stiffness-proportional, Rayleigh) acts
// on the rate dC/dt = ∇C·v. Integrated implicitly over h, the rate decays by the factor
// 1/(1 + c·h·(w_a + w_b)), so it is stable for any c; a rigid constraint (α = 0) loses all of it.
// At rest there is no rate: the static solution is untouched.
void damp_distance_constraints(std::span<const DistanceConstraint> constraints, const Vec2* x, Vec2* v,
                               const double* w, double tau, double h);

}  // namespace tire

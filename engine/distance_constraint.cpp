#include "distance_constraint.h"

#include <cmath>

namespace tire {

void prepare_distance_constraints(std::span<DistanceConstraint> constraints, const double* w, double inv_h2) {
  for (DistanceConstraint& c : constraints) {
    c.alpha_tilde = c.compliance * inv_h2;
    const double denominator = w[c.a] + w[c.b] + c.alpha_tilde;  // ∇C M⁻¹ ∇Cᵀ + α̃, |∇C| = 1 per end
    c.inv_denominator = denominator > 0.0 ? 1.0 / denominator : 0.0;
  }
}

void solve_distance_constraints(std::span<const DistanceConstraint> constraints,
                                std::span<double> lambda, Vec2* x, const double* w) {
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    const DistanceConstraint& c = constraints[k];
    const Vec2 d = x[c.b] - x[c.a];
    const double len = std::sqrt(dot(d, d));
    if (len <= 0.0) continue;  // coincident: ∇C undefined
    const Vec2 n = d * (1.0 / len);  // ∇_{x_b}C
    // Δλ = (−C − α̃λ) / (∇C M⁻¹ ∇Cᵀ + α̃)  (XPBD eq. 18)
    const double delta_lambda = (c.rest_length - len - c.alpha_tilde * lambda[k]) * c.inv_denominator;
    lambda[k] += delta_lambda;
    // Δx = M⁻¹ ∇Cᵀ Δλ  (XPBD eq. 17)
    x[c.a] -= n * (w[c.a] * delta_lambda);
    x[c.b] += n * (w[c.b] * delta_lambda);
  }
}

void damp_distance_constraints(std::span<const DistanceConstraint> constraints, const Vec2* x, Vec2* v,
                               const double* w, double tau, double h) {
  for (const DistanceConstraint& c : constraints) {
    const double w_sum = w[c.a] + w[c.b];
    if (w_sum <= 0.0) continue;
    const Vec2 d = x[c.b] - x[c.a];
    const double len = std::sqrt(dot(d, d));
    if (len <= 0.0) continue;
    const Vec2 n = d * (1.0 / len);
    const double rate = dot(n, v[c.b] - v[c.a]);  // dC/dt
    // Fraction of the rate removed: c h W / (1 + c h W) with c = τ/α; all of it when α = 0.
    const double chw = tau * h * w_sum;
    const double removed = c.compliance > 0.0 ? chw / (c.compliance + chw) : 1.0;
    const double impulse = rate * removed / w_sum;  // per unit ∇C, shared by inverse mass
    v[c.a] += n * (w[c.a] * impulse);
    v[c.b] -= n * (w[c.b] * impulse);
  }
}

}  // namespace tire

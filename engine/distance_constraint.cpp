#include "distance_constraint.h"

#include <cmath>

namespace tire {

void prepare_distance_constraints(std::span<DistanceConstraint> constraints, const double* w,
                                  const ProjectionStep& step) {
  for (DistanceConstraint& c : constraints) {
    c.alpha_tilde = c.compliance * step.inv_h2;
    // (1 + γ) ∇C M⁻¹ ∇Cᵀ + α̃ with |∇C| = 1 at each end  (XPBD eq. 26's denominator)
    const double denominator = (1.0 + step.gamma) * (w[c.a] + w[c.b]) + c.alpha_tilde;
    c.inv_denominator = denominator > 0.0 ? 1.0 / denominator : 0.0;
  }
}

namespace {

template <bool Damped>
void sweep(std::span<const DistanceConstraint> constraints, std::span<double> lambda, Vec2* x,
           const Vec2* x_prev, const double* w, double gamma) {
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    const DistanceConstraint& c = constraints[k];
    const Vec2 d = x[c.b] - x[c.a];
    const double len = std::sqrt(dot(d, d));
    if (len <= 0.0) continue;  // coincident: ∇C undefined
    const Vec2 n = d * (1.0 / len);  // ∇_{x_b}C
    const double C = len - c.rest_length;
    // Δλ = (−C − α̃λ − γ∇C(x − xⁿ)) / ((1 + γ)∇C M⁻¹ ∇Cᵀ + α̃)  (XPBD eq. 26; eq. 18 when γ = 0)
    double numerator = -C - c.alpha_tilde * lambda[k];
    if constexpr (Damped) numerator -= gamma * dot(n, (x[c.b] - x_prev[c.b]) - (x[c.a] - x_prev[c.a]));
    const double delta_lambda = numerator * c.inv_denominator;
    lambda[k] += delta_lambda;
    // Δx = M⁻¹ ∇Cᵀ Δλ  (XPBD eq. 17)
    x[c.a] -= n * (w[c.a] * delta_lambda);
    x[c.b] += n * (w[c.b] * delta_lambda);
  }
}

}  // namespace

void solve_distance_constraints(std::span<const DistanceConstraint> constraints,
                                std::span<double> lambda, Vec2* x, const Vec2* x_prev, const double* w,
                                double gamma) {
  if (gamma > 0.0) sweep<true>(constraints, lambda, x, x_prev, w, gamma);
  else sweep<false>(constraints, lambda, x, x_prev, w, gamma);
}

}  // namespace tire

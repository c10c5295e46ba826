#include "area_constraint.h"

namespace tire {

double polygon_area(const Vec2* x, std::uint32_t count) {
  double twice_area = 0.0;
  for (std::uint32_t i = 0, j = count - 1; i < count; j = i++) twice_area += cross(x[j], x[i]);
  return 0.5 * twice_area;
}

namespace {
// ∇_{x_i}A from the neighbours of i.
inline Vec2 area_gradient(Vec2 prev, Vec2 next) { return {0.5 * (next.y - prev.y), 0.5 * (prev.x - next.x)}; }
}  // namespace

void polygon_area_gradient(const Vec2* x, std::uint32_t count, Vec2* grad) {
  for (std::uint32_t i = 0; i < count; ++i)
    grad[i] = area_gradient(x[(i + count - 1) % count], x[(i + 1) % count]);
}

void solve_area_constraint(const AreaConstraint& c, double& lambda, Vec2* x, const double* w, double inv_h2) {
  Vec2* p = x + c.first;
  const double* wp = w + c.first;
  const std::uint32_t n = c.count;

  // First pass: C and Σ w_i |∇_i C|² at the current positions.
  double twice_area = cross(p[n - 1], p[0]);
  double sum_w_grad2 = wp[0] * length_squared(area_gradient(p[n - 1], p[1])) +
                       wp[n - 1] * length_squared(area_gradient(p[n - 2], p[0]));
  for (std::uint32_t i = 1; i < n; ++i) twice_area += cross(p[i - 1], p[i]);
  for (std::uint32_t i = 1; i + 1 < n; ++i) sum_w_grad2 += wp[i] * length_squared(area_gradient(p[i - 1], p[i + 1]));

  const double C = 0.5 * twice_area - c.pressure * c.rest_area;
  const double alpha_tilde = c.compliance * inv_h2;  // α̃ = α/h²  (XPBD eq. 4)
  const double denominator = sum_w_grad2 + alpha_tilde;
  if (denominator <= 0.0) return;
  const double delta_lambda = (-C - alpha_tilde * lambda) / denominator;  // XPBD eq. 18
  lambda += delta_lambda;

  // Second pass: Δx_i = w_i ∇_i C Δλ (XPBD eq. 17). Every gradient must use the positions before
  // this update, so the original of the previous vertex (and of vertex 0) is carried along.
  const Vec2 first_original = p[0];
  Vec2 prev_original = p[n - 1];
  for (std::uint32_t i = 0; i + 1 < n; ++i) {
    const Vec2 grad = area_gradient(prev_original, p[i + 1]);
    prev_original = p[i];
    p[i] += grad * (wp[i] * delta_lambda);
  }
  p[n - 1] += area_gradient(prev_original, first_original) * (wp[n - 1] * delta_lambda);
}

void damp_area_constraint(const AreaConstraint& c, const Vec2* x, Vec2* v, const double* w, double tau, double h) {
  const Vec2* p = x + c.first;
  Vec2* vp = v + c.first;
  const double* wp = w + c.first;
  const std::uint32_t n = c.count;
  double rate = 0.0;  // dA/dt
  double sum_w_grad2 = 0.0;
  for (std::uint32_t i = 0; i < n; ++i) {
    const Vec2 grad = area_gradient(p[i == 0 ? n - 1 : i - 1], p[i + 1 == n ? 0 : i + 1]);
    rate += dot(grad, vp[i]);
    sum_w_grad2 += wp[i] * length_squared(grad);
  }
  if (sum_w_grad2 <= 0.0) return;
  const double chw = tau * h * sum_w_grad2;
  const double removed = c.compliance > 0.0 ? chw / (c.compliance + chw) : 1.0;
  const double impulse = rate * removed / sum_w_grad2;
  for (std::uint32_t i = 0; i < n; ++i)
    vp[i] -= area_gradient(p[i == 0 ? n - 1 : i - 1], p[i + 1 == n ? 0 : i + 1]) * (wp[i] * impulse);
}

}  // namespace tire

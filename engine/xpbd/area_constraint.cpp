#include "tire/xpbd/area_constraint.h"

#include <cmath>

#include "tire/math/check.h"

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
  grad[0] = area_gradient(x[count - 1], x[1]);
  for (std::uint32_t i = 1; i + 1 < count; ++i) grad[i] = area_gradient(x[i - 1], x[i + 1]);
  grad[count - 1] = area_gradient(x[count - 2], x[0]);
}

void solve_area_constraint(const AreaConstraint& c, double& lambda, Vec2* x, const double* w, double inv_h2) {
  TIRE_ASSERT(c.count >= 3, "an area constraint on fewer than three vertices");
  TIRE_ASSERT(c.compliance >= 0.0 && std::isfinite(c.compliance),
              "an area compliance is negative, NaN or infinite");
  TIRE_ASSERT(inv_h2 > 0.0 && std::isfinite(inv_h2), "1/h² is not positive and finite");
  Vec2* p = x + c.first;
  const double* wp = w + c.first;
  const std::uint32_t n = c.count;

  // First pass, at the current positions: C and Σ w_i |∇_i C|², in one sweep (two independent
  // sums the CPU can overlap; each in the same order as polygon_area and polygon_area_gradient).
  double twice_area = cross(p[n - 1], p[0]);
  double sum_w_grad2 = wp[0] * length_squared(area_gradient(p[n - 1], p[1]));
  for (std::uint32_t i = 1; i < n; ++i) {
    twice_area += cross(p[i - 1], p[i]);
    sum_w_grad2 += wp[i] * length_squared(area_gradient(p[i - 1], i + 1 < n ? p[i + 1] : p[0]));
  }

  const double C = 0.5 * twice_area - c.pressure * c.rest_area;
  const double alpha_tilde = c.compliance * inv_h2;  // α̃ = α/h²  (XPBD eq. 4)
  const double denominator = sum_w_grad2 + alpha_tilde;
  if (denominator <= 0.0) return;
  const double delta_lambda = (-C - alpha_tilde * lambda) / denominator;  // XPBD eq. 18
  lambda += delta_lambda;
  TIRE_ASSERT(std::isfinite(lambda) || !std::isfinite(C) || !std::isfinite(denominator),
              "an area solve from finite positions left its multiplier NaN or infinite");
  // Second pass: Δx_i = w_i ∇_i C Δλ  (XPBD eq. 17), every ∇_i C at the positions before the
  // pass: the previous vertex's and the first one's old positions are carried along.
  const Vec2 first = p[0];
  Vec2 previous = p[n - 1];
  for (std::uint32_t i = 0; i < n; ++i) {
    const Vec2 current = p[i];
    const Vec2 next = i + 1 < n ? p[i + 1] : first;
    p[i] += area_gradient(previous, next) * (wp[i] * delta_lambda);
    previous = current;
  }
}

void damp_area_constraint(const AreaConstraint& c, const Vec2* x, Vec2* v, const double* w, double tau,
                          double h) {
  TIRE_ASSERT(c.count >= 3, "an area constraint on fewer than three vertices");
  TIRE_ASSERT(h > 0.0 && tau >= 0.0, "a negative damping time or a substep that is not positive");
  const Vec2* p = x + c.first;
  Vec2* vp = v + c.first;
  const double* wp = w + c.first;
  const std::uint32_t n = c.count;
  double rate = 0.0;  // dA/dt
  double sum_w_grad2 = 0.0;
  for (std::uint32_t i = 0; i < n; ++i) {
    const Vec2 grad = area_gradient(p[i == 0 ? n - 1 : i - 1], p[i + 1 < n ? i + 1 : 0]);
    rate += dot(grad, vp[i]);
    sum_w_grad2 += wp[i] * length_squared(grad);
  }
  // Impulse per unit ∇A: rate·removed/ΣW with removed = chΣW/(1 + chΣW), c = τ/α, which is
  // rate·τh/(α + τhΣW) and removes all of the rate when α = 0.
  const double tau_h = tau * h;
  if (sum_w_grad2 <= 0.0 || tau_h <= 0.0) return;
  const double impulse = rate * tau_h / (c.compliance + tau_h * sum_w_grad2);
  for (std::uint32_t i = 0; i < n; ++i)
    vp[i] -= area_gradient(p[i == 0 ? n - 1 : i - 1], p[i + 1 < n ? i + 1 : 0]) * (wp[i] * impulse);
}

}  // namespace tire

#include "soft_contact.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tire {

void TirePairFinder::find(const std::vector<Tire>& tires, double dt, double gravity, std::vector<TirePair>& out) {
  out.clear();
  const auto n = static_cast<std::uint32_t>(tires.size());
  bounds_.resize(n);
  order_.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::vector<Vec2>& x = tires[i].particles.x;
    const std::vector<Vec2>& v = tires[i].particles.v;
    Aabb b{x.front(), x.front()};
    double speed2 = 0.0;
    for (std::uint32_t k = 0; k < tires[i].n; ++k) {  // the tread bounds the tire
      b.min = {std::min(b.min.x, x[k].x), std::min(b.min.y, x[k].y)};
      b.max = {std::max(b.max.x, x[k].x), std::max(b.max.y, x[k].y)};
      speed2 = std::max(speed2, length_squared(v[k]));
    }
    // Both tires of a pair are expanded, so each covers its own travel.
    bounds_[i] = b.expanded(std::sqrt(speed2) * dt + 0.5 * gravity * dt * dt + kTirePairSkin);
    order_[i] = {bounds_[i].min.x, i};
  }
  std::sort(order_.begin(), order_.end(), [](const Entry& l, const Entry& r) {
    return l.min_x < r.min_x || (l.min_x == r.min_x && l.index < r.index);
  });
  for (std::uint32_t s = 0; s < n; ++s) {
    const Aabb& a = bounds_[order_[s].index];
    for (std::uint32_t k = s + 1; k < n && order_[k].min_x <= a.max.x; ++k) {
      const std::uint32_t i = order_[s].index, j = order_[k].index;
      if (a.overlaps(bounds_[j])) out.push_back({std::min(i, j), std::max(i, j)});
    }
  }
}

namespace {

// Index k of the tread edge (x_k, x_k+1) whose wedge from `hub` contains direction d. The tread
// stays star-shaped about its hub, so the edge is found from the angle of d relative to particle 0,
// then confirmed by walking at most a few edges either way.
std::uint32_t wedge_edge(const Vec2* x, std::uint32_t n, Vec2 hub, Vec2 d) {
  const Vec2 r0 = x[0] - hub;
  double turn = std::atan2(cross(r0, d), dot(r0, d));
  if (turn < 0.0) turn += 2.0 * std::numbers::pi;
  auto k = static_cast<std::uint32_t>(turn / (2.0 * std::numbers::pi) * n) % n;
  for (std::uint32_t step = 0; step < n; ++step) {
    const Vec2 a = x[k] - hub, b = x[(k + 1) % n] - hub;
    if (cross(a, d) < 0.0) k = (k + n - 1) % n;       // d is before edge k: step back
    else if (cross(d, b) < 0.0) k = (k + 1) % n;      // d is past edge k: step on
    else return k;
  }
  return k;
}

// Particles of `a`'s tread against `b`'s tread edges.
void push_out(Tire& a, Tire& b, double ground_normal_y) {
  const std::uint32_t nb = b.n;
  Vec2* xb = b.particles.x.data();
  const Vec2* xb_prev = b.particles.x_prev.data();
  const double* wb = b.particles.w.data();
  const Vec2 hub = b.tread_hub;
  const double reach2 = b.tread_reach * b.tread_reach;
  const double mu = std::sqrt(a.spec.friction * b.spec.friction);

  for (std::uint32_t i = 0; i < a.n; ++i) {
    Vec2& p = a.particles.x[i];
    const Vec2 d = p - hub;
    if (length_squared(d) >= reach2) continue;  // outside b's bounding circle
    const std::uint32_t k = wedge_edge(xb, nb, hub, d);
    const std::uint32_t k1 = (k + 1) % nb;
    const Vec2 e = xb[k1] - xb[k];
    const double e2 = length_squared(e);
    if (e2 <= 0.0) continue;
    const Vec2 n = Vec2{e.y, -e.x} * (1.0 / std::sqrt(e2));  // outward: tread is counter-clockwise
    const double C = dot(n, p - xb[k]);
    if (C >= 0.0) continue;
    const double t = std::clamp(dot(p - xb[k], e) / e2, 0.0, 1.0);
    const double w0 = wb[k] * (1.0 - t) * (1.0 - t), w1 = wb[k1] * t * t, wp = a.particles.w[i];
    const double w_sum = wp + w0 + w1;
    if (w_sum <= 0.0) continue;
    // Normal: Δλ = −C / Σ w|∇C|²  (XPBD eq. 18, α = 0)
    const double dl = -C / w_sum;
    p += n * (wp * dl);
    xb[k] -= n * (wb[k] * (1.0 - t) * dl);
    xb[k1] -= n * (wb[k1] * t * dl);
    a.soft_lambda[i] += dl;
    if (n.y <= -ground_normal_y) b.on_tire[k] = b.on_tire[k1] = 1;  // b rests on a
    if (n.y >= ground_normal_y) a.on_tire[i] = 1;                   // a rests on b
    // Static friction on the motion of p relative to the edge point this substep.
    const Vec2 edge_motion = (xb[k] - xb_prev[k]) * (1.0 - t) + (xb[k1] - xb_prev[k1]) * t;
    const Vec2 dp = (p - a.particles.x_prev[i]) - edge_motion;
    const Vec2 dp_t = dp - n * dot(dp, n);
    const double lt = length(dp_t) / w_sum;  // |Δλ_t| that would stop it
    if (lt <= 0.0 || lt >= mu * a.soft_lambda[i]) continue;
    const Vec2 g = dp_t * (1.0 / w_sum);
    p -= g * wp;
    xb[k] += g * (wb[k] * (1.0 - t));
    xb[k1] += g * (wb[k1] * t);
  }
}

}  // namespace

void solve_tire_contact(Tire& a, Tire& b, double ground_normal_y) {
  // Bounding circles apart: nothing to do.
  const double reach = a.tread_reach + b.tread_reach;
  if (length_squared(a.tread_hub - b.tread_hub) >= reach * reach) return;
  push_out(a, b, ground_normal_y);
  push_out(b, a, ground_normal_y);
}

}  // namespace tire

// Particle contacts as XPBD inequality constraints C(x) = (x − s)·n ≥ 0 with zero compliance,
// and Coulomb friction in the position-based form of Müller et al. 2020, "Detailed Rigid Body
// Simulation with Extended Position Based Dynamics" (Sec. 3.5 static, Sec. 3.6 kinetic).
//
// Against a surface of infinite mass the particle's inverse mass cancels out of every formula,
// so the multipliers are kept as distances: lambda_n is the normal correction applied so far in
// this substep (Müller's λ_n·w), and the Coulomb test λ_t < μ_s λ_n becomes |Δx_t| < μ_s·lambda_n.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>

#include "tire/math/check.h"
#include "tire/math/geometry.h"

namespace tire {

// A penetrating contact: push the particle by depth·normal to reach the surface.
struct SurfaceContact {
  Vec2 normal;         // unit, out of the surface
  double depth = 0.0;  // > 0
};

// Exact minimal-overlap contact of a point strictly inside an axis-aligned box: the face with
// the least overlap gives the normal. Ties prefer the top face (ground), then left, right, bottom,
// so the result never depends on anything but the inputs. Nullopt when the point is not inside.
inline std::optional<SurfaceContact> box_contact(Vec2 p, const Aabb& box) {
  if (!(p.x > box.min.x && p.x < box.max.x && p.y > box.min.y && p.y < box.max.y)) return std::nullopt;
  SurfaceContact best{{0.0, 1.0}, box.max.y - p.y};                         // top
  if (p.x - box.min.x < best.depth) best = {{-1.0, 0.0}, p.x - box.min.x};  // left
  if (box.max.x - p.x < best.depth) best = {{1.0, 0.0}, box.max.x - p.x};   // right
  if (p.y - box.min.y < best.depth) best = {{0.0, -1.0}, p.y - box.min.y};  // bottom
  return best;
}

// The contact of p against the face of `box` whose outward normal is `normal` (an axis): the
// distance from p back to that face's plane, along the normal; nullopt when p is on its outer side.
inline std::optional<SurfaceContact> face_contact(Vec2 normal, Vec2 p, const Aabb& box) {
  const double face = normal.x < 0   ? box.min.x
                      : normal.x > 0 ? box.max.x
                      : normal.y < 0 ? box.min.y
                                     : box.max.y;
  const double depth = normal.x != 0.0 ? (face - p.x) * normal.x : (face - p.y) * normal.y;
  if (depth <= 0.0) return std::nullopt;
  return SurfaceContact{normal, depth};
}

// Contact of a particle that moved from `from` (its position at the start of the substep) to `to`.
// A particle that started outside the box and entered it, or crossed it entirely, is sent back
// through the face it came in by (slab test on the segment); one that started inside, through the
// face nearest where it started. With the anti-tunneling clamp this stops even walls thinner than one
// substep's travel. Depth is measured from `to` to the entry face.
inline std::optional<SurfaceContact> swept_box_contact(Vec2 from, Vec2 to, const Aabb& box) {
  // Cheap reject: the segment's bounds miss the box (touching counts as missing: no margin).
  if (std::max(from.x, to.x) <= box.min.x || std::min(from.x, to.x) >= box.max.x ||
      std::max(from.y, to.y) <= box.min.y || std::min(from.y, to.y) >= box.max.y)
    return std::nullopt;
  const bool inside_x = from.x > box.min.x && from.x < box.max.x;
  const bool inside_y = from.y > box.min.y && from.y < box.max.y;
  if (inside_x && inside_y) {
    // It began the substep inside (a resting contact's residue, or a push by a neighbour): the face
    // nearest where it began, not where it is predicted to be, is the one it came in by. A particle
    // resting a nanometre inside a thin wall and predicted past its middle must go back, not through.
    // One that left through a side face (beyond the box across that face's axis) is free.
    const Vec2 n = box_contact(from, box)->normal;
    const bool beside =
        n.x != 0.0 ? !(to.y > box.min.y && to.y < box.max.y) : !(to.x > box.min.x && to.x < box.max.x);
    if (beside) return std::nullopt;
    return face_contact(n, to, box);
  }
  // Common case, exactly: the particle is now inside and started outside one slab only, so it came
  // in through that slab's face (a particle resting on the ground starts each substep on it).
  const bool now_inside = to.x > box.min.x && to.x < box.max.x && to.y > box.min.y && to.y < box.max.y;
  if (now_inside && inside_x)
    return from.y >= box.max.y ? SurfaceContact{{0.0, 1.0}, box.max.y - to.y}
                               : SurfaceContact{{0.0, -1.0}, to.y - box.min.y};
  if (now_inside && inside_y)
    return from.x >= box.max.x ? SurfaceContact{{1.0, 0.0}, box.max.x - to.x}
                               : SurfaceContact{{-1.0, 0.0}, to.x - box.min.x};
  // Slab test: the latest entry time over the axes is where the segment enters the box.
  const Vec2 d = to - from;
  double t_enter = 0.0, t_exit = 1.0;
  Vec2 normal;
  const double lo[2] = {box.min.x, box.min.y}, hi[2] = {box.max.x, box.max.y};
  const double p0[2] = {from.x, from.y}, dp[2] = {d.x, d.y};
  for (int axis = 0; axis < 2; ++axis) {
    if (dp[axis] == 0.0) {
      if (p0[axis] <= lo[axis] || p0[axis] >= hi[axis]) return std::nullopt;
      continue;
    }
    const double t0 = (lo[axis] - p0[axis]) / dp[axis];
    const double t1 = (hi[axis] - p0[axis]) / dp[axis];
    const double t_in = std::min(t0, t1), t_out = std::max(t0, t1);
    if (t_in >= t_enter) {
      t_enter = t_in;
      normal = axis == 0 ? Vec2{dp[0] > 0.0 ? -1.0 : 1.0, 0.0} : Vec2{0.0, dp[1] > 0.0 ? -1.0 : 1.0};
    }
    t_exit = std::min(t_exit, t_out);
  }
  if (t_enter >= t_exit || normal == Vec2{}) return std::nullopt;
  return face_contact(normal, to, box);
}

// What friction needs to know about one particle's contact during one substep.
struct ContactRecord {
  Vec2 normal;            // normal of the last contact found this substep
  Vec2 surface_velocity;  // velocity of the surface under the particle (moving props)
  double lambda_n = 0.0;  // accumulated normal correction of the particle this substep (m)
  double mu_static = 0.0;
  double mu_kinetic = 0.0;
  std::int32_t prop = -1;  // the prop touched, or −1 for an obstacle
  bool active = false;     // touched a surface this substep
  bool stuck = false;      // static friction held at the last projection
  // The global method's (GlobalSolver): the surface as a plane, C(x) = normal·x − plane, kept from
  // one iteration of the substep to the next, and the tangential multiplier as a distance (as
  // lambda_n), along perp(normal).
  double plane = 0.0;
  double lambda_t = 0.0;
  std::int32_t tire = -1;  // the global method's: the other tire's index in the world, or −1
  // Against another tire: what that tire gives way along the tangent at the contact as the rigid
  // body it is (TreadView::give), for the kinetic friction between them (reduced mass).
  double other_give_t = 0.0;
};

// Friction of two surfaces in contact, mixed as Box2D's b2MixFriction does.
inline double mix_friction(double a, double b) { return std::sqrt(a * b); }

// Projects a penetrating particle out of a surface, then applies position-level static friction:
// if the tangential displacement relative to the surface this substep is within the static cone,
// undo it. `surface_displacement` is how far the surface point moved this substep (zero for
// obstacles). Against a body of finite mass the particle takes only its share of each correction,
// w_p/(w_p + w_body) (Müller 2020 eq. 3–5 with generalized inverse masses); the body takes the rest
// as an impulse, which the caller sends.
inline void resolve_contact(Vec2& x, Vec2 x_prev, const SurfaceContact& c, double mu_static,
                            double mu_kinetic, ContactRecord& rec, Vec2 surface_displacement = {},
                            double normal_share = 1.0, double tangent_share = 1.0) {
  // (Written to let NaN through: a tire gone NaN is the world's divergence guard's to reset.)
  TIRE_ASSERT(!(c.depth < 0.0) && !(std::abs(length_squared(c.normal) - 1.0) > 1e-9),
              "a contact with a negative depth or a normal that is not unit");
  // A share is w_p/(w_p + w_body) in [0, 1], but rounding lets it pass 1 slightly: Prop::mobility,
  // 1 − (n·s)² with s a support normal from Box2D (unit in float, not in double), can come out a
  // few 1e-9 below 0 (replay 04-crates-goal: mobility −4.1e-9, share 1 + 1.2e-10). Clamping the
  // mobility at 0 is the fix, but it changes that recorded replay; until it is re-recorded the
  // check allows 1e-6 of excess, far above that rounding and far below a real error.
  TIRE_ASSERT(normal_share >= 0.0 && normal_share <= 1.0 + 1e-6 && tangent_share >= 0.0 &&
                  tangent_share <= 1.0 + 1e-6,
              "a particle's share of a contact correction outside [0, 1]");
  const double correction = c.depth * normal_share;
  x += c.normal * correction;  // Δx = −C n w/(Σw) for C = −depth
  rec.normal = c.normal;
  rec.lambda_n += correction;
  rec.mu_static = mu_static;
  rec.mu_kinetic = mu_kinetic;
  rec.active = true;
  const Vec2 dp = (x - x_prev) - surface_displacement;
  const Vec2 dp_t = dp - c.normal * dot(dp, c.normal);  // Müller 2020 eq. 27
  // Static friction (Müller 2020 Sec. 3.5): stick when λ_t < μ_s λ_n.
  const double limit = mu_static * rec.lambda_n;
  rec.stuck = length_squared(dp_t) * tangent_share * tangent_share < limit * limit;
  if (rec.stuck) x -= dp_t * tangent_share;
}

// Kinetic friction on the velocity relative to the surface (Müller 2020 eq. 30):
// Δv = −v_t/|v_t| · min(h μ_k |f_n|, |v_t|) with f_n = λ_n/h² per unit inverse mass, i.e. at most
// μ_k·lambda_n/h. Returns the change made to v.
inline Vec2 apply_kinetic_friction(Vec2& v, const ContactRecord& rec, double h) {
  if (!rec.active || rec.stuck) return {};
  const Vec2 v_rel = v - rec.surface_velocity;
  const Vec2 v_t = v_rel - rec.normal * dot(v_rel, rec.normal);
  const double speed_t = length(v_t);
  if (speed_t <= 0.0) return {};
  const double reduction = rec.mu_kinetic * rec.lambda_n / h;
  const Vec2 dv = v_t * -(reduction >= speed_t ? 1.0 : reduction / speed_t);
  v += dv;
  return dv;
}

}  // namespace tire

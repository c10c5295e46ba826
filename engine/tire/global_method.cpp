#include <algorithm>
#include <cmath>

#include "tire/math/check.h"
#include "tire/math/trig.h"
#include "tire/tire/global_solver.h"
#include "tire/tire/island_contacts.h"
#include "tire/tire/tire_method.h"
#include "tire/tire/tire_neighbours.h"
#include "tire/tire/tire_solver.h"
#include "tire/tire/vehicle_joints.h"

namespace tire {

namespace {

// The global method's prediction carries a tire's spin on as a rotation. v ← (x − xₙ)/h is a chord:
// a tire that turned by θ over the last substep moves along straight chords, and projecting them
// back onto its ring takes θ − atan θ of every turn away, about θ³/3 (a free tire spinning at
// 25 rad/s keeps 8.6 rad/s after a second at 2 substeps, 14.4 at 8, with Gauss–Seidel, which still
// steps so; it also made the tire accelerate more slowly at few substeps). So each particle's velocity
// relative to the hub's is turned by the angle the tire turned through: from the chords,
// Σ m r × (v − V) / Σ m |r|² = sin θ / h exactly for a rigid turn (r at the substep's end). A rigid
// spin then goes on at any substep count, as Müller et al. 2020 advance a rigid body's orientation
// by its angular velocity rather than along a chord; deformation is turned with the tire.
// Gauss–Seidel keeps the plain step, bit for bit.
void turn_velocities(Tire& t, double h) {
  const RigidMotion m = t.rigid_motion();
  const double sin_theta = std::clamp(m.omega * h, -1.0, 1.0);
  if (sin_theta == 0.0) return;
  const double cos_theta = std::sqrt(1.0 - sin_theta * sin_theta);
  for (std::size_t i = 0; i < t.particles.size(); ++i) {
    const Vec2 u = t.particles.v[i] - m.velocity;
    t.particles.v[i] = m.velocity + rotate(u, cos_theta, sin_theta);
  }
}

// A tire as built spins at ω with the tangent velocities V + ω × r. Turned as chords are
// (turn_velocities, sin θ = ωh), a tangent carries each particle inside its ring, to |r| cos θ: the
// first solve finds the ring's area short by sin²θ, one Newton step leaves part of that (a tire built
// spinning at 24 rad/s held 240 J in its springs after its first step at one substep), and the tire
// turned faster than it was built to (3 % at 25 rad/s and one substep). So before its first turn the
// spin becomes the chord of a turn by θ = ωh over the substep before, (r − R(−θ) r)/h: the tire then
// turns by exactly ωh a substep, its ring neither squeezed nor stretched.
void chord_spin(Tire& t, double h) {
  const RigidMotion m = t.rigid_motion();
  const CosSin cs = cos_sin(m.omega * h);
  const double radial = (1.0 - cs.cos) / h, tangential = cs.sin / h - m.omega;
  for (std::size_t i = 0; i < t.particles.size(); ++i) {
    const Vec2 r = t.particles.x[i] - m.centroid;
    t.particles.v[i] += r * radial + perp(r) * tangential;
  }
}

// The global method's kinetic friction (Müller et al. 2020, eq. 30: a sliding contact's friction
// impulse is at most μ_k times its normal impulse J_n = m λ_n/h), split between the tire's rigid
// motion and the particle's own motion about it. Taken off the particle's velocity alone, as
// Gauss–Seidel does, it stalls a particle of a stiff tire: a spinning tread landing in one substep
// has a normal impulse many times the particle's momentum, the particle is stopped dead while its
// ring spins on, and the next solve throws the tire off the stalled point (a spinning tire dropped
// 2 cm left the ground again at 5 m/s at 2 substeps). So, contact after contact:
//  - the rigid part: the slip of the tire's rigid motion at the point, v_t, is stopped by at most
//    j = min(μ_k J_n, m_eff |v_t|), with m_eff = (1/M + (r×t)²/I)⁻¹ the tire's mass there along the
//    tangent t; j changes the whole tire's velocity and spin (later contacts see the change);
//  - the deformation part: the particle's tangential velocity about that rigid motion (a tread
//    squeezed out sideways) takes what is left of μ_k J_n, at most all of it.
// Impulses owed to dynamic props are recorded. Against another tire (the global method's contacts
// between tires, whose static friction is in the position solve) the slip is relative to the
// neighbour's tread, the rigid part's mass is the pair's reduced mass (the neighbour's give along
// the tangent, TreadView::give, added to the tire's), and the neighbour takes the opposite impulse
// as a push for its next prediction (TireNeighbours::apply_reactions after the velocity pass). Without
// it a contact between tires that slipped had no friction at all, and a tire wedged in a pile could
// spin in place for ever (docs/at-rest.md). A spinning landing then rolls off at the speed its
// angular momentum gives at 1 to 256 substeps; Müller's per-particle form reaches that speed only at
// 256. Where a short slide decides (a polygon's landings on a slope) the two forms differ even at
// 2048 substeps, by up to 5 cm over a 2 s roll at 12 segments (docs/accuracy.md, the cross-check).
void apply_kinetic_friction_split(Tire& t, const SubstepContext& ctx) {
  Particles& p = t.particles;
  const RigidMotion m = t.rigid_motion();
  const double mass = t.total_mass(), particle_mass = t.particle_mass();
  if (!(m.inertia > 0.0)) return;
  Vec2 dv;          // change of the hub's velocity so far
  double dw = 0.0;  // and of the spin
  t.for_each_contact([&](std::uint32_t i) {
    const ContactRecord& c = t.contacts[i];
    if (!c.active || c.stuck || (c.tire >= 0 && !ctx.neighbours)) return;
    const Vec2 r = p.x[i] - m.centroid;
    const auto tangential = [&](Vec2 v) { return v - c.normal * dot(v, c.normal); };
    double budget = c.mu_kinetic * particle_mass * c.lambda_n / ctx.h;  // μ_k J_n (N·s)
    Vec2 impulse;
    const Vec2 slip = tangential(m.velocity + dv + perp(r) * (m.omega + dw) - c.surface_velocity);
    if (const double speed = length(slip); speed > 0.0 && budget > 0.0) {
      const Vec2 tangent = slip / speed;
      const double rt = cross(r, tangent);
      const double m_eff = 1.0 / (1.0 / mass + rt * rt / m.inertia + c.other_give_t);
      const double j = std::min(budget, m_eff * speed);
      budget -= j;
      impulse = tangent * -j;
      dv += impulse / mass;
      dw += cross(r, impulse) / m.inertia;
    }
    // The particle's own slip about the rigid motion (the rigid changes above do not alter it).
    const Vec2 own = tangential(p.v[i] - (m.velocity + perp(r) * m.omega));
    if (const double speed = length(own); speed > 0.0 && budget > 0.0) {
      const Vec2 dv_own = own * -(std::min(budget / particle_mass, speed) / speed);
      p.v[i] += dv_own;
      impulse += dv_own * particle_mass;
    }
    if (c.prop >= 0 && impulse != Vec2{} && ctx.rigid->props()[static_cast<std::size_t>(c.prop)].is_dynamic())
      t.prop_impulses.push_back(
          {static_cast<std::uint32_t>(c.prop), impulse * -1.0, p.x[i], ctx.time + ctx.h, ctx.time + ctx.h});
    if (c.tire >= 0 && impulse != Vec2{})  // the neighbour takes −impulse: a push of impulse·h (kg·m)
      ctx.neighbours->reactions(ctx.neighbours->index_of(t))
          .push_back({static_cast<std::uint32_t>(c.tire), 0, p.x[i], impulse * ctx.h, false});
  });
  if (dv == Vec2{} && dw == 0.0) return;
  for (std::uint32_t i = 0; i < p.size(); ++i) p.v[i] += dv + perp(p.x[i] - m.centroid) * dw;
}

// The global method (tire_method.h): one system a substep for the tire's constraints and contacts.
class GlobalMethod final : public TireMethod {
 public:
  bool couples_tires_in_solve() const override { return true; }
  bool steps_props_with_substeps() const override { return true; }
  bool refines_substeps() const override { return true; }
  bool needs_solver_pool() const override { return true; }

  void begin_tick(Tire&, double) const override {}
  void carry_velocities(Tire& t, double h) const override {
    if (t.spin_as_built) chord_spin(t, h);
    turn_velocities(t, h);
  }

  // Every constraint and surface contact of the tire at once (global_solver.h).
  void solve_constraints(Tire& t, const SubstepContext& ctx, bool) const override {
    if (ctx.vehicles && t.wheel >= 0) {
      ctx.vehicles->solver(t.wheel).solve(t, ctx);
    } else if (ctx.island) {
      ctx.island->solver_of(t).solve(t, ctx);
    } else {
      TIRE_ASSERT(ctx.global != nullptr, "the global method needs the world's GlobalSolverPool");
      const GlobalSolverPool::Lease solver = ctx.global->lend();
      solver->solve(t, ctx);
    }
    t.predicted_push = {};
  }
  void solve_surface_contacts(Tire&, const SubstepContext&) const override {}  // in the solve

  void apply_friction(Tire& t, const SubstepContext& ctx) const override {
    apply_kinetic_friction_split(t, ctx);
  }
  void damp_material(Tire&, double) const override {}  // inside the solve (XPBD eq. 26)
};

}  // namespace

const TireMethod& global_method() {
  static const GlobalMethod method;
  return method;
}

}  // namespace tire

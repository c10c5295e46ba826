#include <cmath>

#include "tire/math/check.h"
#include "tire/tire/tire_method.h"
#include "tire/tire/tire_solver.h"
#include "tire/xpbd/area_constraint.h"
#include "tire/xpbd/contact.h"

namespace tire {

namespace {

// The grab: C = |x − target| pulled to 0 with compliance α (XPBD eq. 18 with one particle).
void solve_grab(Tire& t, double inv_h2) {
  Vec2& x = t.particles.x[t.grab_particle];
  const double w = t.particles.w[t.grab_particle];
  const Vec2 d = x - t.grab_target;
  const double len = length(d);
  if (len <= 0.0 || w <= 0.0) return;
  const double alpha_tilde = t.grab_compliance * inv_h2;
  const double delta_lambda = (-len - alpha_tilde * t.grab_lambda) / (w + alpha_tilde);
  t.grab_lambda += delta_lambda;
  x += d * (w * delta_lambda / len);
}

// A particle against a prop: the contact in the prop's frame (its motion over the substep taken
// into account), friction relative to the moving surface, and for a dynamic prop the generalized
// inverse mass w = 1/M + (r×n)²/I (Müller 2020 eq. 2–3) and the reaction impulse −m Δx/h.
void resolve_prop_contact(Tire& t, const ContactPair& pair, const SubstepContext& ctx) {
  const PropFrame& frame = t.prop_frames[pair.index];
  const Prop& prop = ctx.rigid->props()[frame.prop];
  Vec2& x = t.particles.x[pair.particle];
  const Vec2 x_prev = t.particles.x_prev[pair.particle];
  const auto local = local_contact(prop.geometry, frame.start_local(x_prev), frame.end.to_local(x),
                                   t.was_held(pair.particle));
  if (!local) return;
  const SurfaceContact c{frame.end.rotate(local->normal), local->depth};
  const double t_end = ctx.time + ctx.h;
  const Vec2 surface_velocity = prop.point_velocity(x, t_end);
  double normal_share = 1.0, tangent_share = 1.0;
  const double w = t.particles.w[pair.particle];
  // A dynamic prop pushed into what holds it up (the ground under a crate) cannot give way that way
  // this tick: its inverse mass along the push is scaled by its mobility (0 straight into a
  // support), and the impulse still reaches it, where Box2D hands it to the support (shock
  // propagation, one level deep).
  if (prop.is_dynamic()) {
    const Vec2 r = x - prop.center_at(t_end);
    const double rn = cross(r, c.normal), rt = dot(r, c.normal);  // r × n and r × t, t = perp(n)
    const double mob_n = prop.mobility(-c.normal),
                 mob_t = std::min(prop.mobility(perp(c.normal)), prop.mobility(-perp(c.normal)));
    normal_share = w / (w + mob_n * (prop.inverse_mass + rn * rn * prop.inverse_inertia));
    tangent_share = w / (w + mob_t * (prop.inverse_mass + rt * rt * prop.inverse_inertia));
  }
  ContactRecord& rec = t.touch_contact(pair.particle);
  const Vec2 before = x;
  resolve_contact(x, x_prev, c, pair.mu_static, pair.mu_kinetic, rec, surface_velocity * ctx.h, normal_share,
                  tangent_share);
  rec.surface_velocity = surface_velocity;
  rec.prop = static_cast<std::int32_t>(frame.prop);
  if (prop.is_dynamic())
    t.prop_impulses.push_back({frame.prop, (before - x) * (t.particle_mass() / ctx.h), x, t_end, ctx.time});
}

void solve_contacts(Tire& t, const SubstepContext& ctx) {
  Particles& p = t.particles;
  const std::vector<Obstacle>& obstacles = ctx.rigid->obstacles();
  for (const ContactPair& pair : t.pairs) {
    const std::uint32_t i = pair.particle;
    if (pair.is_prop) {
      resolve_prop_contact(t, pair, ctx);
    } else if (const auto c = swept_box_contact(p.x_prev[i], p.x[i], obstacles[pair.index].box)) {
      ContactRecord& rec = t.touch_contact(i);
      resolve_contact(p.x[i], p.x_prev[i], *c, pair.mu_static, pair.mu_kinetic, rec);
      rec.surface_velocity = {};
      rec.prop = -1;
    }
  }
}

// Gauss–Seidel (tire_method.h): the constraints one by one, then the contacts.
class GaussSeidelMethod final : public TireMethod {
 public:
  bool couples_tires_in_solve() const override { return false; }
  bool steps_props_with_substeps() const override { return false; }
  bool refines_substeps() const override { return false; }
  bool needs_solver_pool() const override { return false; }

  // The distance constraints' α̃ and damping for this tick's substep (distance_constraint.h).
  void begin_tick(Tire& t, double h) const override {
    t.distance.prepare(t.particles.w.data(), h, t.spec.material_damping);
  }
  // The plain step: v as the last substep derived it.
  void carry_velocities(Tire&, double) const override {}

  void solve_constraints(Tire& t, const SubstepContext& ctx, bool last) const override {
    Particles& p = t.particles;
    const double inv_h2 = 1.0 / (ctx.h * ctx.h);
    if (t.grabbed) solve_grab(t, inv_h2);
    t.distance.solve(p.x.data());
    solve_area_constraint(t.area_constraint, t.area_lambda, p.x.data(), p.w.data(), inv_h2);
    // The rim's area, once per substep (in its last iteration): it is there so that a heavy load
    // cannot fold the rim, and a load builds over substeps, not within one. Its ring's edges, solved
    // every iteration, keep its shape in between. (With one iteration, the default, that is every
    // iteration anyway.)
    if (last) solve_area_constraint(t.rim_area_constraint, t.rim_area_lambda, p.x.data(), p.w.data(), inv_h2);
  }
  void solve_surface_contacts(Tire& t, const SubstepContext& ctx) const override { solve_contacts(t, ctx); }

  // Kinetic friction per particle (Müller et al. 2020, eq. 30). Against another tire friction is
  // static only, in the position solve (soft_contact.h): the other tire could not take a kinetic
  // impulse back here.
  void apply_friction(Tire& t, const SubstepContext& ctx) const override {
    Particles& p = t.particles;
    t.for_each_contact([&](std::uint32_t i) {
      const ContactRecord& c = t.contacts[i];
      const Vec2 dv = c.tire >= 0 ? Vec2{} : apply_kinetic_friction(p.v[i], c, ctx.h);
      if (c.prop >= 0 && dv != Vec2{} && ctx.rigid->props()[static_cast<std::size_t>(c.prop)].is_dynamic())
        t.prop_impulses.push_back({static_cast<std::uint32_t>(c.prop), dv * -t.particle_mass(), p.x[i],
                                   ctx.time + ctx.h, ctx.time + ctx.h});
    });
  }
  // The material's dashpots (XPBD eq. 26 applied to the velocities, distance_constraint.h).
  void damp_material(Tire& t, double h) const override {
    const double tau = t.spec.material_damping;
    if (!(tau > 0.0)) return;
    Particles& p = t.particles;
    t.distance.damp(p.x.data(), p.v.data());
    damp_area_constraint(t.area_constraint, p.x.data(), p.v.data(), p.w.data(), tau, h);
  }
};

}  // namespace

const TireMethod& gauss_seidel_method() {
  static const GaussSeidelMethod method;
  return method;
}

}  // namespace tire

#include "tire/tire/tire_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tire/math/check.h"
#include "tire/math/exp.h"
#include "tire/tire/soft_contact.h"
#include "tire/tire/tire_method.h"

namespace tire {

namespace {

// Angular acceleration (rad/s², CCW positive) that steering asks for this substep: the tread is
// driven at drive_acceleration·|steer| until its speed reaches max_speed·|steer|.
double drive_angular_acceleration(const Tire& t, const RigidMotion& motion) {
  const double steer = std::clamp(t.control.steer, -1.0, 1.0);
  if (steer == 0.0) return 0.0;
  const double tread_speed = -motion.omega * t.spec.outer_radius;  // > 0 rolling to +x
  const double target = steer * t.spec.max_speed;
  if (steer > 0.0 ? tread_speed >= target : tread_speed <= target) return 0.0;
  return -steer * t.spec.drive_acceleration / t.spec.outer_radius;
}

// The anti-tunnelling clamp: no particle faster than v_max. Scaling each particle's velocity on its
// own would change the tire's momentum: a tire spun fast in the air (drive_acceleration 1000,
// max_speed 100) has its tread's downward-moving side cut more than its upward side, and the cut
// held it up (it fell 0.5 m in 2 s instead of 19.7). So the tire's velocity is split into its
// mean V (its momentum / mass) and each particle's u_i about it; V is clamped to v_max, and the
// u_i are scaled down together, just enough that |V + u_i| ≤ v_max by the triangle inequality.
// Momentum changes only when the hub itself is too fast, and then along V.
void clamp_velocities(Tire& t, double v_max) {
  // Pinned particles (w = 0) neither move nor count.
  Particles& p = t.particles;
  double fastest2 = 0.0;
  Vec2 mean;
  std::size_t free = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.w[i] == 0.0) continue;
    fastest2 = std::max(fastest2, length_squared(p.v[i]));
    mean += p.v[i];
    ++free;
  }
  if (fastest2 <= v_max * v_max) return;
  mean = mean / static_cast<double>(free);  // every particle weighs the same
  double widest = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.w[i] != 0.0) widest = std::max(widest, length(p.v[i] - mean));
  const double speed = length(mean);
  const Vec2 clamped = speed > v_max ? mean * (v_max / speed) : mean;
  const double room = v_max - std::min(speed, v_max);
  const double scale = widest > room ? room / widest : 1.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.w[i] != 0.0) p.v[i] = clamped + (p.v[i] - mean) * scale;
}

// Semi-implicit Euler velocity step (Small Steps, Alg. 1 line 4) with steering as a uniform
// angular acceleration about the hub (a pure torque: no net force, so the tire moves only by
// traction), then the anti-tunneling clamp, then the position prediction.
void predict(Tire& t, const SubstepContext& ctx) {
  Particles& p = t.particles;
  const double h = ctx.h;
  // What neighbours anchoring to this tire's predicted tread leave out (TireNeighbours::capture):
  // their own pushes coming back, and this substep's fall under gravity, which the tire's supports
  // will take back. Followed by static friction, a tire resting on two others that were not yet
  // solved was dragged down their sides by g h² a substep (0.7 mm at two substeps) and turned in
  // place for ever, and level 08's pile never slept (docs/at-rest.md).
  t.predicted_push = t.late_push;
  t.predicted_push.add(ctx.gravity * h, 0.0, t.predicted_push.any ? t.predicted_push.centre : Vec2{});
  if (t.late_push.any) {  // what neighbours pushed after the tire's last solve (tire_neighbours.h)
    const Tire::LatePush& k = t.late_push;
    for (std::size_t i = 0; i < p.size(); ++i) p.v[i] += k.velocity + perp(p.x[i] - k.centre) * k.spin;
    t.late_push = {};
  }
  tire_method(ctx.config->method).carry_velocities(t, h);
  t.spin_as_built = false;
  const RigidMotion motion = t.control.steer != 0.0 ? t.rigid_motion() : RigidMotion{};
  const double alpha = drive_angular_acceleration(t, motion);
  const Vec2 hub = motion.centroid;
  const double v_max = ctx.config->tunnel_clamp * t.segment_length / h;
  double work = 0.0;  // the drive's: Σ ½ m (|v + Δv|² − |v|²), per unit particle mass
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.w[i] == 0.0) continue;
    Vec2 v = p.v[i] + ctx.gravity * h;
    if (alpha != 0.0) {
      const Vec2 dv = perp(p.x[i] - hub) * (alpha * h);
      work += dot(v, dv) + 0.5 * length_squared(dv);
      v += dv;
    }
    p.v[i] = v;
  }
  t.control_work += t.particle_mass() * work;
  clamp_velocities(t, v_max);
  predict_positions(p, h);
}

bool path_near(Vec2 a, Vec2 b, const Aabb& box) {
  return !(std::max(a.x, b.x) < box.min.x || std::min(a.x, b.x) > box.max.x ||
           std::max(a.y, b.y) < box.min.y || std::min(a.y, b.y) > box.max.y);
}

// Narrow phase, once per substep after prediction: the particles whose path this substep passes
// within one segment length of a nearby obstacle or prop. Only these are tested in the iterations
// (the margin covers what the constraints move a particle within one substep).
void find_contact_pairs(Tire& t, const SubstepContext& ctx) {
  const Particles& p = t.particles;
  const RigidWorld& rigid = *ctx.rigid;
  t.pairs.clear();
  for (const std::uint32_t k : t.candidates) {
    const Obstacle& o = rigid.obstacles()[k];
    const Aabb near = o.box.expanded(t.segment_length);
    const double mu_s = mix_friction(t.spec.friction, o.friction);
    const double mu_k = mix_friction(t.spec.kinetic_friction, o.friction);
    for (std::uint32_t i = 0; i < p.size(); ++i)
      if (path_near(p.x_prev[i], p.x[i], near)) t.pairs.push_back({i, k, false, mu_s, mu_k});
  }
  t.prop_frames.clear();
  for (const std::uint32_t k : t.prop_candidates) {
    const Prop& prop = rigid.props()[k];
    if (!prop.alive || static_cast<std::int32_t>(k) == t.chassis) continue;
    const auto frame = static_cast<std::uint32_t>(t.prop_frames.size());
    t.prop_frames.push_back({k, prop.pose_at(ctx.time), prop.pose_at(ctx.time + ctx.h),
                             prop.geometry.shape == PropShape::circle});
    const Aabb local = prop.geometry.local_bounds();
    Aabb near = t.prop_frames.back().start.to_world(local);
    const Aabb end = t.prop_frames.back().end.to_world(local);
    near = Aabb{{std::min(near.min.x, end.min.x), std::min(near.min.y, end.min.y)},
                {std::max(near.max.x, end.max.x), std::max(near.max.y, end.max.y)}}
               .expanded(t.segment_length);
    const double mu_s = mix_friction(t.spec.friction, prop.spec.friction);
    const double mu_k = mix_friction(t.spec.kinetic_friction, prop.spec.friction);
    for (std::uint32_t i = 0; i < p.size(); ++i)
      if (path_near(p.x_prev[i], p.x[i], near)) t.pairs.push_back({i, frame, true, mu_s, mu_k});
  }
}

// Momentum-conserving damping (Müller et al. 2007, "Position Based Dynamics", Sec. 3.5): only the
// deviation from the tire's rigid motion decays, at rate `damping` per second. Leaves `m` as is.
void damp_deviation(Tire& t, const RigidMotion& m, double damping, double h) {
  const double k = 1.0 - tire::exp(-damping * h);
  Particles& p = t.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 rigid = m.velocity + perp(p.x[i] - m.centroid) * m.omega;
    p.v[i] += (rigid - p.v[i]) * k;
  }
}

// Rolling resistance: a moment M_r = C_rr·N·R against the spin while grounded, with N the total
// contact normal force, Σ m·λ_n/h² (λ_n kept as a distance, see contact.h). Applied as a change
// of the rigid angular velocity about the hub, Δv_i = Δω × r_i: a pure moment, no net force; the
// ground's friction then passes it on to the tire's motion, as it does for a real tire.
// When the moment stops the spin within the substep, the tire is held (Tire::rolling_held): the
// global method's next position solve keeps its roll there too, up to the same moment.
void apply_rolling_resistance(Tire& t, RigidMotion& m, double h) {
  t.rolling_held = false;
  if (t.spec.rolling_resistance <= 0.0 || m.inertia <= 0.0) return;
  // Σ over the tread, in particle order; the records not written this substep hold λ_n = 0.
  double lambda_sum = 0.0;
  t.for_each_contact([&](std::uint32_t i) {
    if (i < t.n) lambda_sum += t.contacts[i].lambda_n;
  });
  if (lambda_sum <= 0.0) return;
  const double normal_force = t.particle_mass() * lambda_sum / (h * h);
  const double max_change = t.spec.rolling_resistance * normal_force * t.spec.outer_radius * h / m.inertia;
  t.rolling_held = std::abs(m.omega) <= max_change;
  const double change = t.rolling_held ? -m.omega : -std::copysign(max_change, m.omega);
  for (std::size_t i = 0; i < t.particles.size(); ++i)
    t.particles.v[i] += perp(t.particles.x[i] - m.centroid) * change;
  m.omega += change;
}

// Caps the hub's horizontal speed by shifting every particle alike (spin and shape untouched).
void cap_horizontal_speed(Tire& t, RigidMotion& m) {
  const double vx = m.velocity.x;
  if (std::abs(vx) <= t.spec.max_speed) return;
  const double shift = std::copysign(t.spec.max_speed, vx) - vx;
  for (Vec2& v : t.particles.v) v.x += shift;
  m.velocity.x += shift;
}

// The hub's velocity: the mean of the particles' (they all weigh the same).
Vec2 hub_velocity(const Particles& p) {
  Vec2 sum;
  for (const Vec2& v : p.v) sum += v;
  return sum / static_cast<double>(p.size());
}

// Restitution (TireSpec::restitution), once the solve has made the substep's velocities: the
// coefficient of restitution of an impact, e = v_out/v_in along its normal (Newton's experimental
// law; Müller et al. 2020, "Detailed Rigid Body Simulation with Extended Position Based Dynamics",
// eq. 34, applies it per contact on the velocity before the solve). A tire's bounce comes from its
// whole body, not one particle, so it is applied to the hub's motion over the whole landing: v_in is
// the hub's speed into the surface before the substep it first touched, the normal is that of the
// landing's summed contact impulses, and in the substep the tire lets go, its hub's speed away along
// that normal is set to e·v_in (the spin and the shape are left as the impact made them). Only
// surfaces that take no momentum back count (ground, obstacles, static and kinematic props): a
// dynamic prop or a tire gets its share through the contacts. `before` is the hub's velocity the
// substep was predicted with.
void apply_restitution(Tire& t, const SubstepContext& ctx, Vec2 before) {
  Landing& l = t.landing;
  const auto& props = ctx.rigid->props();
  Vec2 impulse;
  t.for_each_contact([&](std::uint32_t i) {
    const ContactRecord& c = t.contacts[i];
    if (c.active && c.tire < 0 && (c.prop < 0 || !props[static_cast<std::size_t>(c.prop)].is_dynamic()))
      impulse += c.normal * c.lambda_n;
  });
  if (impulse != Vec2{}) {
    if (!l.touching) {
      const double approach = -dot(before, impulse / length(impulse));
      l = Landing{true, approach > ctx.config->restitution_threshold ? approach : 0.0, 0.0, {}};
    }
    l.impulse += impulse;
    l.time += ctx.h;
    return;
  }
  if (!l.touching) return;
  const Landing landing = l;
  l = Landing{};
  if (landing.approach <= 0.0 || landing.time > ctx.config->restitution_time) return;
  const Vec2 n = landing.impulse / length(landing.impulse);
  const double away = dot(hub_velocity(t.particles), n);
  if (away < 0.0) return;  // not leaving it: let go without a push
  const Vec2 change = n * (t.spec.restitution * landing.approach - away);
  for (Vec2& v : t.particles.v) v += change;
}

// Adds this substep's contact impulses and slides to the tick's figures (TickContacts): read only,
// before the velocity pass (which derives the velocities from the positions and applies friction),
// while the records still hold what the positions solve found.
void record_tick_contacts(Tire& t, const SubstepContext& ctx) {
  TickContacts& sum = t.tick_contacts;
  const Particles& p = t.particles;
  const double impulse_per_lambda = t.particle_mass() / ctx.h;  // J = m·λ_n/h
  const auto& props = ctx.rigid->props();
  bool moving = false;  // the rigid motion below is made on the first sliding contact
  RigidMotion motion;
  t.for_each_contact([&](std::uint32_t i) {
    const ContactRecord& c = t.contacts[i];
    if (!c.active) return;
    const double j = c.lambda_n * impulse_per_lambda;
    if (c.tire >= 0)
      sum.tire += j;
    else if (c.prop >= 0 && props[static_cast<std::size_t>(c.prop)].spec.type != PropType::static_body)
      sum.prop += j;
    else
      sum.ground += j;
    if (c.tire >= 0 || c.stuck) return;
    // The slide of the tire as a rigid body at the contact (its hub's velocity and its spin there),
    // not of the particle: a straight landing spreads the tread sideways, which is no skid.
    if (!moving) {
      moving = true;
      motion = t.substep_motion(ctx.h);
    }
    const Vec2 v = motion.velocity + perp(p.x[i] - motion.centroid) * motion.omega - c.surface_velocity;
    sum.slip_speed = std::max(sum.slip_speed, length(v - c.normal * dot(v, c.normal)));
  });
  // Gauss–Seidel's contacts between treads: λ per tread particle, already m·distance.
  double soft = 0.0;
  for (const double l : t.soft_lambda) soft += l;
  sum.tire += soft / ctx.h;
}

void update_velocities(Tire& t, const SubstepContext& ctx) {
  Particles& p = t.particles;
  const bool bounces = t.spec.restitution > 0.0;
  const Vec2 before = bounces ? hub_velocity(p) : Vec2{};
  derive_velocities(p, ctx.h);
  std::copy(t.on_tire.begin(), t.on_tire.end(), t.grounded_flags.begin());
  const TireMethod& method = tire_method(ctx.config->method);
  method.apply_friction(t, ctx);
  t.for_each_contact([&](std::uint32_t i) {
    const ContactRecord& c = t.contacts[i];
    if (c.active && c.normal.y >= ctx.config->ground_normal_y) t.grounded_flags[i] = 1;
  });
  if (bounces) apply_restitution(t, ctx, before);
  t.air_time = t.grounded() ? 0.0 : t.air_time + ctx.h;
  method.damp_material(t, ctx.h);
  RigidMotion motion = t.rigid_motion();
  if (ctx.config->damping > 0.0) damp_deviation(t, motion, ctx.config->damping, ctx.h);
  apply_rolling_resistance(t, motion, ctx.h);
  if (t.wheel < 0) cap_horizontal_speed(t, motion);  // a wheel's speed is its vehicle's motor's
}

}  // namespace

void begin_tick(Tire& t, const SolverConfig& config, const RigidWorld& rigid) {
  TIRE_ASSERT(config.substeps >= 1 && config.iterations >= 1, "fewer than one substep or iteration a tick");
  TIRE_ASSERT(config.dt > 0.0 && std::isfinite(config.dt), "the tick is not a positive length of time");
  TIRE_ASSERT(t.sizes_consistent(), "a tire's arrays no longer match its particle count");
  const double h = config.dt / config.substeps;
  tire_method(config.method).begin_tick(t, h);
  // The farthest any particle can get this tick: the clamp bounds each substep's travel; the
  // tire's radius covers what the constraints can move a particle on top of that.
  const double reach = config.substeps * config.tunnel_clamp * t.segment_length + t.spec.outer_radius;
  rigid.query(bounds_of(t.particles.x).expanded(reach), t.candidates, t.prop_candidates);
  if (t.control.jump && t.touched_ground_within(config.jump_grace)) {
    const double j = t.spec.jump_speed;
    double work = 0.0;  // Σ ½ m ((v_y + j)² − v_y²), per unit particle mass
    for (Vec2& v : t.particles.v) {
      work += v.y * j + 0.5 * j * j;
      v.y += j;
    }
    t.control_work += t.particle_mass() * work;
    t.air_time = std::numeric_limits<double>::infinity();  // one jump until the tread lands again
  }
  t.control.jump = false;
  if (t.control.inflate != 0.0) {  // the target area moves at inflate_rate towards its bounds
    const TireSpec& s = t.spec;
    const double pressure = s.pressure + t.control.inflate * s.inflate_rate * config.dt;
    // A pressure already outside the bounds (a level's or a script's) is not pulled into them.
    const double low = std::min(s.min_pressure, s.pressure), high = std::max(s.max_pressure, s.pressure);
    const double area = t.area();
    const double before = t.area_constraint.energy(area);  // the pump's work: the air's energy it adds
    t.spec.pressure = t.area_constraint.pressure = std::clamp(pressure, low, high);
    t.control_work += t.area_constraint.energy(area) - before;
  }
  t.tick_contacts = TickContacts{};
  t.newton_turn = 0.0;
  t.global_work = {};
}

void begin_substep(Tire& t, const SubstepContext& ctx) {
  predict(t, ctx);
  find_contact_pairs(t, ctx);
  t.distance.reset_lambda();
  t.area_lambda = 0.0;
  t.rim_area_lambda = 0.0;
  t.clear_contacts();
  std::fill(t.soft_lambda.begin(), t.soft_lambda.end(), 0.0);
  std::fill(t.on_tire.begin(), t.on_tire.end(), std::uint8_t{0});
  t.grab_lambda = 0.0;
}

void solve_iteration(Tire& t, const SubstepContext& ctx, bool last) {
  Particles& p = t.particles;
  const TireMethod& method = tire_method(ctx.config->method);
  method.solve_constraints(t, ctx, last);
  // Where each ring is now: for the tread–rim contact, and for the contacts between tires that
  // follow this iteration.
  const auto bounds_of = [&](std::uint32_t first, Vec2& hub, double& reach) {
    hub = {};
    for (std::uint32_t i = first; i < first + t.n; ++i) hub += p.x[i];
    hub = hub / static_cast<double>(t.n);
    double reach2 = 0.0;
    for (std::uint32_t i = first; i < first + t.n; ++i)
      reach2 = std::max(reach2, length_squared(p.x[i] - hub));
    reach = std::sqrt(reach2);
  };
  // The tread against its own rim, once per substep: it only matters when a load crushes the tire,
  // which builds over substeps, not within one.
  if (last && rim_can_hold_tread(t)) {
    bounds_of(t.n, t.rim_hub, t.rim_reach);
    keep_tread_outside_rim(t);
  }
  method.solve_surface_contacts(t, ctx);
  if (ctx.tire_pairs) bounds_of(0, t.tread_hub, t.tread_reach);
}

void end_substep(Tire& t, const SubstepContext& ctx) {
  record_tick_contacts(t, ctx);
  update_velocities(t, ctx);
  // A tire that started the substep finite ends it finite. (One that did not, say a NaN put in
  // from outside, is the world's divergence guard's to reset after the tick.)
  TIRE_ASSERT(t.is_finite() || !std::all_of(t.particles.x_prev.begin(), t.particles.x_prev.end(),
                                            [](Vec2 x) { return is_finite(x); }),
              "a substep turned finite positions into NaN or Inf");
}

void apply_prop_impulses(Tire& t, RigidWorld& rigid) {
  for (const PropImpulse& p : t.prop_impulses) rigid.add_impulse(p.prop, p.impulse, p.point, p.time, p.since);
  t.prop_impulses.clear();
}

void substep(Tire& t, const SubstepContext& ctx, RigidWorld& rigid) {
  begin_substep(t, ctx);
  for (int it = 0; it < ctx.config->iterations; ++it) {
    solve_iteration(t, ctx, it + 1 == ctx.config->iterations);
    apply_prop_impulses(t, rigid);
  }
  end_substep(t, ctx);
  apply_prop_impulses(t, rigid);
}

}  // namespace tire

#include "tire/tire/vehicle_joints.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tire/math/check.h"
#include "tire/math/dense_solve.h"
#include "tire/math/trig.h"
#include "tire/rigid/rigid_world.h"
#include "tire/tire/tire.h"
#include "tire/tire/tire_solver.h"

namespace tire {

namespace {

constexpr std::size_t kRows = VehicleJoints::kRowsPerWheel;
constexpr std::size_t kMaxWheels = VehicleJoints::kMaxWheels;
constexpr std::size_t kMaxRows = kRows * kMaxWheels;
enum Row : std::size_t { across = 0, along = 1, motor = 2, limit = 3 };
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The chassis where the substep's prediction puts it, and one axle on it.
struct AxleFrame {
  Vec2 point;  // the axle point, world
  Vec2 arm;    // from the chassis' centre of mass to it
  Vec2 axis;   // the suspension's axis, world (unit)
};
AxleFrame axle_frame(const Prop& chassis, const AxleSpec& axle, double t) {
  const Pose pose = chassis.pose_at(t);
  const Vec2 point = pose.to_world(axle.point);
  return {point, point - chassis.center_at(t), pose.rotate(axle.axis)};
}

// Moves a wheel's particles by dx (block order), its rigid turn about the centroid made a rotation:
// dx's linear turn φ = Σ rᵢ × dxᵢ / Σ |rᵢ|² moves each particle along perp(rᵢ), off its circle by
// |rᵢ| φ²/2, which stretches the rings; the tension then resists the next substep's turn (the
// transverse stiffness of a link under tension, global_solver.cpp): a motor spinning a wheel up at
// one substep lost 40 % of a tick's torque so. Here φ turns the particles exactly; the rest of dx
// (translation, deformation) is added as it is.
void move_wheel(Tire& t, const double* dx) {
  Particles& p = t.particles;
  const std::uint32_t n = t.n;
  Vec2 c;
  for (const Vec2& x : p.x) c += x;
  c = c / static_cast<double>(p.size());
  double turn = 0.0, spread = 0.0;
  for (std::uint32_t i = 0; i < 2 * n; ++i) {
    const std::size_t d = GlobalSolver::dof(i, n);
    const Vec2 r = p.x[i] - c;
    turn += cross(r, Vec2{dx[d], dx[d + 1]});
    spread += length_squared(r);
  }
  turn /= spread;
  const CosSin cs = cos_sin(turn);
  for (std::uint32_t i = 0; i < 2 * n; ++i) {
    const std::size_t d = GlobalSolver::dof(i, n);
    const Vec2 r = p.x[i] - c;
    const Vec2 turned{cs.cos * r.x - cs.sin * r.y, cs.sin * r.x + cs.cos * r.y};
    p.x[i] += Vec2{dx[d], dx[d + 1]} - perp(r) * turn + (turned - r);
  }
}

// An angular impulse L (N·m·s) on a wheel: its particles' velocities about their centroid change by
// perp(rᵢ) L / Σ m|rᵢ|², which sums to no force and to exactly L about any point.
void spin_up(Tire& t, double impulse) {
  Particles& p = t.particles;
  Vec2 c;
  for (const Vec2& x : p.x) c += x;
  c = c / static_cast<double>(p.size());
  double inertia = 0.0;
  for (const Vec2& x : p.x) inertia += length_squared(x - c);
  inertia *= t.particle_mass();
  const double dw = impulse / inertia;
  for (std::size_t i = 0; i < p.size(); ++i) p.v[i] += perp(p.x[i] - c) * dw;
}

}  // namespace

namespace vehicle_rows {

Vec2 rim_hub(const Particles& p, std::uint32_t n, bool at_start) {
  Vec2 sum;
  for (std::uint32_t i = n; i < 2 * n; ++i) sum += at_start ? p.x_prev[i] : p.x[i];
  return sum / static_cast<double>(n);
}

void hub_gradient(std::uint32_t n, Vec2 direction, double* g) {
  std::fill(g, g + CyclicBlockCholesky::kBlock * n, 0.0);
  for (std::uint32_t i = n; i < 2 * n; ++i) {
    const std::size_t d = GlobalSolver::dof(i, n);
    g[d] = direction.x / n;
    g[d + 1] = direction.y / n;
  }
}

double stroke(const Particles& p, std::uint32_t n, const Pose& chassis, const AxleSpec& axle) {
  return dot(rim_hub(p, n, false) - chassis.to_world(axle.point), chassis.rotate(axle.axis));
}

TurnFrame turn_frame(const Particles& p) {
  Vec2 c;
  for (const Vec2& x : p.x_prev) c += x;
  return {c / static_cast<double>(p.size())};
}

namespace {
// X = Σ r⁰ᵢ·rᵢ and Y = Σ r⁰ᵢ × rᵢ, rᵢ about the particles' centroid now.
struct TurnSums {
  Vec2 centroid;
  double x = 0.0, y = 0.0;
};
TurnSums turn_sums(const Particles& p, const TurnFrame& f) {
  TurnSums s;
  for (const Vec2& x : p.x) s.centroid += x;
  s.centroid = s.centroid / static_cast<double>(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 r0 = p.x_prev[i] - f.centroid, r = p.x[i] - s.centroid;
    s.x += dot(r0, r);
    s.y += cross(r0, r);
  }
  return s;
}
}  // namespace

double wheel_turn(const Particles& p, const TurnFrame& f) {
  const TurnSums s = turn_sums(p, f);
  return tire::atan2(s.y, s.x);
}

double turn_gradient(const Particles& p, const TurnFrame& f, std::uint32_t n, double* g) {
  const TurnSums s = turn_sums(p, f);
  const double scale = 1.0 / (s.x * s.x + s.y * s.y);
  for (std::uint32_t i = 0; i < 2 * n; ++i) {
    const Vec2 r0 = p.x_prev[i] - f.centroid;
    const Vec2 gi = (perp(r0) * s.x - r0 * s.y) * scale;
    const std::size_t d = GlobalSolver::dof(i, n);
    g[d] = gi.x;
    g[d + 1] = gi.y;
  }
  return tire::atan2(s.y, s.x);
}

}  // namespace vehicle_rows

using namespace vehicle_rows;

std::uint32_t VehicleJoints::add(std::uint32_t chassis, std::span<const std::uint32_t> wheels,
                                 std::span<const AxleSpec> axles, const Drivetrain& drivetrain,
                                 std::uint32_t segments) {
  TIRE_ASSERT(wheels.size() == axles.size() && wheels.size() >= 1 && wheels.size() <= kMaxWheels,
              "a vehicle has one axle a wheel, at most VehicleJoints::kMaxWheels");
  Vehicle v;
  v.chassis = chassis;
  v.drivetrain = drivetrain;
  const std::size_t unknowns = CyclicBlockCholesky::kBlock * segments;
  for (std::size_t k = 0; k < wheels.size(); ++k) {
    Wheel w;
    w.tire = wheels[k];
    w.axle = axles[k];
    w.solver = static_cast<std::int32_t>(wheel_solvers_.size());
    wheel_solvers_.push_back(std::make_unique<GlobalSolver>());
    wheel_solvers_.back()->reserve(segments);
    w.load.assign(unknowns, 0.0);
    for (std::size_t r = 0; r < kRows; ++r) {
      w.response[r].assign(unknowns, 0.0);
      w.gradient[r].assign(unknowns, 0.0);
    }
    v.wheels.push_back(std::move(w));
  }
  vehicles_.push_back(std::move(v));
  return static_cast<std::uint32_t>(vehicles_.size() - 1);
}

void VehicleJoints::hash_into(StateHash& h) const {
  for (const Vehicle& v : vehicles_) {
    h.add(v.chassis);
    h.add(v.control.throttle);
    h.add(v.control.brake);
    h.add(v.control.lean);
    for (const Wheel& w : v.wheels) {
      h.add(w.tire);
      h.add(w.hub_force);
      h.add(w.torque);
      if (w.axle.travel > 0.0) h.add(w.limit_force);
    }
  }
}

void VehicleJoints::tire_removed(std::uint32_t removed) {
  for (Vehicle& v : vehicles_)
    for (Wheel& w : v.wheels)
      if (w.tire > removed) --w.tire;
}

Vec2 VehicleJoints::axle_force(std::uint32_t vehicle, std::size_t w) const {
  return vehicles_[vehicle].wheels[w].hub_force;
}

double VehicleJoints::wheel_torque(std::uint32_t vehicle, std::size_t w) const {
  return vehicles_[vehicle].wheels[w].torque;
}

void VehicleJoints::begin_substep(std::vector<Tire>& tires, RigidWorld& rigid, const SubstepContext& ctx) {
  const double h = ctx.h, t_end = ctx.time + ctx.h;
  for (Vehicle& v : vehicles_) {
    const Prop& chassis = rigid.props()[v.chassis];
    if (!chassis.alive || !chassis.is_dynamic() || asleep(v, tires)) continue;
    // The joints' last forces act on the chassis from the substep's start (their impulse F h); the
    // wheels take them as a load in their solves (load_wheels).
    turn_orbits(v, tires, rigid, h, t_end);
    Vec2 total;
    double angular = 0.0;
    for (Wheel& w : v.wheels) {
      // J_c = −(d, r × d) for the axle's rows along d: −hub_force, its moment taken at the hub as the
      // substep starts (solve_vehicle says why); −1 on θ for the motor's.
      const Tire& t = tires[w.tire];
      const Vec2 impulse = w.hub_force * -h;
      total += impulse;
      angular +=
          cross(rim_hub(t.particles, t.n, false) - chassis.center_at(ctx.time), impulse) - w.torque * h;
      // The motor's torque on the wheel as the change of spin it makes over the substep, τh/I about
      // the wheel's centroid (as the player's drive turns a tire in its prediction): carried as a
      // turn, where a load in the wheel's solve would move it along its tangents, off its circle.
      if (w.torque != 0.0) spin_up(tires[w.tire], w.torque * h);
    }
    const double lean = std::clamp(v.control.lean, -1.0, 1.0) * v.drivetrain.lean_torque;
    angular += lean * h;
    work_ += lean * chassis.omega * h;  // the lean's power, τ ω, over the substep
    if (total != Vec2{}) rigid.add_impulse(v.chassis, total, chassis.center_at(t_end), t_end, ctx.time);
    if (angular != 0.0) rigid.add_angular_impulse(v.chassis, angular, ctx.time);
  }
}

// The vehicle's bodies (the chassis, each wheel) go round their common centre of mass along chords,
// their velocities (x − xₙ)/h, and a chord turned by the joints back onto the arc loses the part of
// the turn it cut: a vehicle spinning freely in the air lost 2.5 % of its spin a second at one
// substep. So, as the global method turns a tire's particles (global_method.cpp, turn_velocities),
// each body's velocity about the vehicle's, u, is turned by the angle θ the vehicle turned through,
// sin θ = h Σ m r × u / Σ m |r|² (exact for a rigid turn; Müller et al. 2020 advance a rigid body by
// its angular velocity, not along a chord). It keeps the momentum (Σ m u = 0 turns into 0) and the
// energy (each |u|); the chassis' own spin is Box2D's and exact already.
void VehicleJoints::turn_orbits(Vehicle& v, std::vector<Tire>& tires, RigidWorld& rigid, double h,
                                double t_end) {
  const Prop& chassis = rigid.props()[v.chassis];
  if (chassis.support_count > 0) return;  // Box2D holds it: its velocity is not the tick's to turn
  struct Body {
    double mass;
    Vec2 x, v;
  };
  Body bodies[kMaxWheels + 1];
  const std::size_t count = v.wheels.size() + 1;
  bodies[0] = {1.0 / chassis.inverse_mass, chassis.center_at(t_end - h), chassis.velocity};
  for (std::size_t k = 0; k < v.wheels.size(); ++k) {
    const Tire& t = tires[v.wheels[k].tire];
    Vec2 x, u;
    for (std::size_t i = 0; i < t.particles.size(); ++i) {
      x += t.particles.x[i];
      u += t.particles.v[i];
    }
    const double n = static_cast<double>(t.particles.size());
    bodies[k + 1] = {t.total_mass(), x / n, u / n};
  }
  double mass = 0.0;
  Vec2 centre, velocity;
  for (std::size_t b = 0; b < count; ++b) {
    mass += bodies[b].mass;
    centre += bodies[b].x * bodies[b].mass;
    velocity += bodies[b].v * bodies[b].mass;
  }
  centre = centre / mass;
  velocity = velocity / mass;
  double moment = 0.0, inertia = 0.0;
  for (std::size_t b = 0; b < count; ++b) {
    const Vec2 r = bodies[b].x - centre;
    moment += bodies[b].mass * cross(r, bodies[b].v - velocity);
    inertia += bodies[b].mass * length_squared(r);
  }
  if (!(inertia > 0.0)) return;
  const double sin_theta = std::clamp(moment / inertia * h, -1.0, 1.0);
  if (sin_theta == 0.0) return;
  const double cos_theta = std::sqrt(1.0 - sin_theta * sin_theta);
  const auto turned = [&](Vec2 u) { return rotate(u, cos_theta, sin_theta); };
  for (std::size_t b = 0; b < count; ++b) {
    const Vec2 u = bodies[b].v - velocity;
    const Vec2 dv = turned(u) - u;
    if (b == 0) {
      rigid.add_impulse(v.chassis, dv * bodies[0].mass, chassis.center_at(t_end), t_end, t_end - h);
    } else {
      for (Vec2& pv : tires[v.wheels[b - 1].tire].particles.v) pv += dv;
    }
  }
}

void VehicleJoints::load_wheels(std::vector<Tire>& tires, const SubstepContext& ctx) {
  const double h2 = ctx.h * ctx.h;
  for (Vehicle& v : vehicles_)
    for (Wheel& w : v.wheels) {
      Tire& t = tires[w.tire];
      const std::uint32_t n = t.n;
      const std::size_t size = CyclicBlockCholesky::kBlock * n;
      std::fill(w.load.begin(), w.load.begin() + static_cast<std::ptrdiff_t>(size), 0.0);
      const Prop& chassis = ctx.rigid->props()[v.chassis];
      if (!chassis.alive || t.asleep) continue;
      const Vec2 per_rim = w.hub_force * (h2 / n);  // hub_gradient's, times λ
      for (std::uint32_t i = n; i < 2 * n; ++i) {
        const std::size_t d = GlobalSolver::dof(i, n);
        w.load[d] += per_rim.x;
        w.load[d + 1] += per_rim.y;
      }
      solver(w.solver).load_next_solve(w.load.data());
    }
}

void VehicleJoints::solve(std::vector<Tire>& tires, RigidWorld& rigid, const SubstepContext& ctx, bool last) {
  for (Vehicle& v : vehicles_) solve_vehicle(v, tires, rigid, ctx, last);
}

void VehicleJoints::solve_vehicle(Vehicle& v, std::vector<Tire>& tires, RigidWorld& rigid,
                                  const SubstepContext& ctx, bool last) {
  const Prop& chassis = rigid.props()[v.chassis];
  if (!chassis.alive || !chassis.is_dynamic() || asleep(v, tires)) return;
  const double h = ctx.h, h2 = h * h, t_start = ctx.time, t_end = ctx.time + ctx.h;
  const double rigid_alpha = ctx.config->rigid_compliance / h2;
  const VehicleControl& control = v.control;
  const double throttle = std::clamp(control.throttle, -1.0, 1.0);

  // The rows: per wheel, across and along its axis, and its motor's or brake's when either acts.
  struct RowInfo {
    std::size_t wheel = 0;
    std::size_t kind = 0;
    double c = 0.0;                          // C now
    double change = 0.0;                     // C − C⁰ over the substep (the suspension's damper)
    double alpha = 0.0;                      // α̃
    double gamma = 0.0;                      // XPBD eq. 26's γ
    double lo = -kInfinity, hi = kInfinity;  // lo ≤ λ ≤ hi (kg·m)
    double jc[3] = {};                       // J_c
    double lambda = 0.0;                     // the total so far (kg·m)
    bool fixed = false;                      // at its bound
  };
  RowInfo rows[kMaxRows];
  Vec2 dirs_of[kMaxRows];  // an axle row's direction
  std::size_t m = 0;
  const Pose start = chassis.pose_at(t_start), end = chassis.pose_at(t_end);
  const double chassis_turn = end.angle - start.angle;
  for (std::size_t k = 0; k < v.wheels.size(); ++k) {
    Wheel& w = v.wheels[k];
    Tire& t = tires[w.tire];
    const std::uint32_t n = t.n;
    const AxleFrame f = axle_frame(chassis, w.axle, t_end);
    const Vec2 b = perp(f.axis);
    const Vec2 hub = rim_hub(t.particles, n, false);
    const Vec2 hub0 = rim_hub(t.particles, n, true);
    const Vec2 point0 = start.to_world(w.axle.point);
    const Vec2 d = hub - f.point, d0 = hub0 - point0;
    const Vec2 dirs[2] = {b, f.axis};
    for (std::size_t r = across; r <= along; ++r) {
      dirs_of[m] = dirs[r];
      RowInfo& row = rows[m++];
      row.wheel = k;
      row.kind = r;
      row.c = dot(dirs[r], d);
      row.change = row.c - dot(dirs[r], d0);
      row.alpha = rigid_alpha;
      if (r == along && w.axle.stiffness > 0.0) {
        row.alpha = 1.0 / (w.axle.stiffness * h2);
        row.gamma = w.axle.damping / (w.axle.stiffness * h);
      }
      row.jc[0] = -dirs[r].x;
      row.jc[1] = -dirs[r].y;
      row.jc[2] = -cross(f.arm, dirs[r]);
      row.lambda = (dot(dirs[r], w.hub_force) - (r == along ? w.limit_force : 0.0)) * h2;
      hub_gradient(n, dirs[r], w.gradient[r].data());
    }
    if (w.axle.stiffness > 0.0 && w.axle.travel > 0.0) {
      // The travel: past the top (C > travel) or the bottom (C < −travel), or still held at one by
      // its last force, a rigid row on C ∓ travel that only pushes back.
      const RowInfo& spring = rows[m - 1];
      const double travel = w.axle.travel;
      const bool past = spring.c > travel || spring.c < -travel;
      if (past || w.limit_force != 0.0) {
        const bool top = past ? spring.c > travel : w.limit_force < 0.0;
        dirs_of[m] = f.axis;
        RowInfo& row = rows[m++];
        row = spring;
        row.kind = limit;
        row.c = top ? spring.c - travel : spring.c + travel;
        row.change = 0.0;
        row.alpha = rigid_alpha;
        row.gamma = 0.0;
        row.lo = top ? -kInfinity : 0.0;
        row.hi = top ? 0.0 : kInfinity;
        row.lambda = w.limit_force * h2;
        std::copy(w.gradient[along].begin(), w.gradient[along].end(), w.gradient[limit].begin());
      }
    }
    const bool driven = w.axle.driven && throttle != 0.0;
    const double torque = control.brake ? v.drivetrain.brake_torque
                          : driven      ? std::abs(throttle) * v.drivetrain.motor_torque
                                        : 0.0;
    if (torque > 0.0) {
      // Forward (to +x with the chassis level) is a clockwise spin: ω* = −throttle · motor_speed.
      const double target = control.brake ? 0.0 : -throttle * v.drivetrain.motor_speed;
      const TurnFrame tf = turn_frame(t.particles);
      RowInfo& row = rows[m++];
      row.wheel = k;
      row.kind = motor;
      row.c = turn_gradient(t.particles, tf, n, w.gradient[motor].data()) - chassis_turn - target * h;
      row.alpha = 0.0;
      row.hi = torque * h2;
      row.lo = -row.hi;
      row.jc[2] = -1.0;
      row.lambda = w.torque * h2;
      // At its bound since the last substep and still short of its speed (−C, the way its force
      // would go, the way it already pushes): it stays there, Δλ = 0, and needs no response.
      row.fixed = std::abs(row.lambda) >= row.hi * (1.0 - 1e-9) && -row.c * row.lambda > 0.0;
    } else {
      w.torque = 0.0;
    }
  }

  // Each wheel's response to its rows, K̂_w⁻¹ J_wᵀ, and D = Σ J_w K̂_w⁻¹ J_wᵀ + J_c M_c⁻¹ J_cᵀ. From
  // the wheel's last solve, its half-responses and J_w K̂_w⁻¹ J_wᵀ (GlobalSolver::respond_forward):
  // the move below sums them and sweeps up the factor once.
  double a[kMaxRows][kMaxRows + 1];
  for (std::size_t i = 0; i < m; ++i) std::fill_n(a[i], m + 1, 0.0);
  bool exact[kMaxWheels] = {};
  for (std::size_t k = 0; k < v.wheels.size(); ++k) {
    Wheel& w = v.wheels[k];
    const Tire& t = tires[w.tire];
    const std::size_t size = CyclicBlockCholesky::kBlock * t.n;
    GlobalSolver& s = solver(w.solver);
    exact[k] = s.prepare_solve_response();
    std::size_t live[kRows];
    std::size_t count = 0;
    for (std::size_t i = 0; i < m; ++i)
      if (rows[i].wheel == k && !rows[i].fixed) live[count++] = i;
    if (count == 0) continue;
    if (exact[k]) {
      double* loads[kRows];
      for (std::size_t r = 0; r < count; ++r) {
        const RowInfo& row = rows[live[r]];
        std::copy_n(w.gradient[row.kind].begin(), size, w.response[row.kind].begin());
        loads[r] = w.response[row.kind].data();
      }
      GlobalSolver::Gram gram;
      s.respond_forward(loads, count, &gram);
      for (std::size_t r = 0; r < count; ++r)
        for (std::size_t q = 0; q < count; ++q) a[live[r]][live[q]] = gram[r][q];
      continue;
    }
    // A wheel whose system holds a free prop has no symmetric response: the wheel taken as a rigid
    // body instead (its mass and inertia about the hub), its response whole.
    const RigidMotion motion = t.rigid_motion();
    for (std::size_t r = 0; r < count; ++r) {
      const RowInfo& row = rows[live[r]];
      const std::vector<double>& g = w.gradient[row.kind];
      std::vector<double>& out = w.response[row.kind];
      Vec2 force;
      double moment = 0.0;
      for (std::uint32_t p = 0; p < 2 * t.n; ++p) {
        const std::size_t dof = GlobalSolver::dof(p, t.n);
        const Vec2 gp{g[dof], g[dof + 1]};
        force += gp;
        moment += cross(t.particles.x[p] - motion.centroid, gp);
      }
      const Vec2 dv = force / t.total_mass();
      const double dw = motion.inertia > 0.0 ? moment / motion.inertia : 0.0;
      for (std::uint32_t p = 0; p < 2 * t.n; ++p) {
        const std::size_t dof = GlobalSolver::dof(p, t.n);
        const Vec2 dp = dv + perp(t.particles.x[p] - motion.centroid) * dw;
        out[dof] = dp.x;
        out[dof + 1] = dp.y;
      }
    }
    // J_i K̂⁻¹ J_jᵀ, symmetric: each pair once.
    for (std::size_t r = 0; r < count; ++r)
      for (std::size_t q = 0; q <= r; ++q) {
        const std::vector<double>& gi = w.gradient[rows[live[r]].kind];
        const std::vector<double>& wj = w.response[rows[live[q]].kind];
        double s2 = 0.0;
        for (std::size_t d = 0; d < size; ++d) s2 += gi[d] * wj[d];
        a[live[r]][live[q]] = a[live[q]][live[r]] = s2;
      }
  }
  const double inverse[3] = {chassis.inverse_mass, chassis.inverse_mass, chassis.inverse_inertia};
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < m; ++j) {
      double s2 = 0.0;
      for (std::size_t q = 0; q < 3; ++q) s2 += rows[i].jc[q] * inverse[q] * rows[j].jc[q];
      a[i][j] = (1.0 + rows[i].gamma) * (a[i][j] + s2);
    }
    a[i][i] += rows[i].alpha;
    a[i][m] = -rows[i].c - rows[i].alpha * rows[i].lambda - rows[i].gamma * rows[i].change;
  }

  // Solved with the bounds of the motors, brakes and travel limits: a row past its bound is held at
  // it and the rest solved again (at most once per such row).
  double delta[kMaxRows] = {};
  for (std::size_t pass = 0; pass <= m; ++pass) {
    double sys[kMaxRows][kMaxRows + 1];
    std::size_t index[kMaxRows];
    std::size_t free = 0;
    for (std::size_t i = 0; i < m; ++i)
      if (!rows[i].fixed) index[free++] = i;
    for (std::size_t r = 0; r < free; ++r) {
      const std::size_t i = index[r];
      double rhs = a[i][m];
      for (std::size_t j = 0; j < m; ++j)
        if (rows[j].fixed) rhs -= a[i][j] * delta[j];
      for (std::size_t q = 0; q < free; ++q) sys[r][q] = a[i][index[q]];
      sys[r][free] = rhs;
    }
    if (free > 0 && !solve_augmented(sys, free)) return;  // nothing moved: the wheels' own solves stand
    for (std::size_t r = 0; r < free; ++r) delta[index[r]] = sys[r][free];
    bool clamped = false;
    for (std::size_t i = 0; i < m; ++i) {
      if (rows[i].fixed) continue;
      const double total = rows[i].lambda + delta[i];
      if (total > rows[i].hi || total < rows[i].lo) {
        delta[i] = (total > rows[i].hi ? rows[i].hi : rows[i].lo) - rows[i].lambda;
        rows[i].fixed = true;
        clamped = true;
      }
    }
    if (!clamped) break;
  }

  // Wheels move by K̂⁻¹ J_wᵀ Δλ (move_wheel), and the chassis takes the opposite of the joints'
  // impulses, so that the vehicle keeps its momentum and angular momentum exactly. Velocities here
  // are chords, (x − x⁰)/h (the wheels' particles, and Box2D's symplectic step), and in that measure
  // an impulse J on a body changes its angular momentum about the origin by x⁰ × J, x⁰ where the
  // body was at the substep's start: so an axle's impulse is reacted at its wheel's hub as the
  // substep started (taken at the axle point or the hub where it ends, a car spinning freely in
  // the air lost up to 13 % of its spin a second at one substep), and the motor's as what its row
  // gave the wheel, (λ/h) Σ x⁰ᵢ × gᵢ = λ X Σ|r⁰|² / (X² + Y²) = λ cos θ_w, not λ (reacted as λ, a
  // motor reaching its speed at one substep gave the vehicle 4 % of the angular momentum it spun).
  for (Wheel& w : v.wheels)  // the load was read by the wheel's solve: its room sums the move now
    std::fill(w.load.begin(), w.load.end(), 0.0);
  Vec2 impulses[kMaxWheels];
  double angular = 0.0;
  for (std::size_t i = 0; i < m; ++i) {
    if (delta[i] == 0.0) continue;  // a row held at its bound, whose response was not needed
    Wheel& w = v.wheels[rows[i].wheel];
    const std::vector<double>& resp = w.response[rows[i].kind];
    for (std::size_t d = 0; d < w.load.size(); ++d) w.load[d] += resp[d] * delta[i];
    if (rows[i].kind == motor) {
      const Tire& t = tires[w.tire];
      const std::vector<double>& g = w.gradient[motor];
      double moment = 0.0;
      for (std::uint32_t q = 0; q < 2 * t.n; ++q) {
        const std::size_t d = GlobalSolver::dof(q, t.n);
        moment += cross(t.particles.x_prev[q], Vec2{g[d], g[d + 1]});
      }
      angular -= moment * delta[i] / h;
    } else {
      impulses[rows[i].wheel] += Vec2{rows[i].jc[0], rows[i].jc[1]} * (delta[i] / h);
    }
  }
  for (std::size_t k = 0; k < v.wheels.size(); ++k) {
    Wheel& w = v.wheels[k];
    if (exact[k]) solver(w.solver).respond_backward(w.load.data());  // the half-responses' sum, swept up
    move_wheel(tires[w.tire], w.load.data());
  }
  Vec2 total;
  for (std::size_t k = 0; k < v.wheels.size(); ++k) {
    const Tire& t = tires[v.wheels[k].tire];
    total += impulses[k];
    angular += cross(rim_hub(t.particles, t.n, true) - chassis.center_at(t_start), impulses[k]);
  }
  if (total != Vec2{}) rigid.add_impulse(v.chassis, total, chassis.center_at(t_end), t_end, t_start);
  // The totals, for the next substep's first guess (the axle's as a world force, whatever the
  // chassis turns meanwhile).
  for (Wheel& w : v.wheels) {
    w.hub_force = {};
    w.limit_force = 0.0;
  }
  for (std::size_t i = 0; i < m; ++i) {
    Wheel& w = v.wheels[rows[i].wheel];
    const double force = (rows[i].lambda + delta[i]) / h2;
    if (rows[i].kind == motor) {
      w.torque = force;
    } else {
      w.hub_force += dirs_of[i] * force;
      if (rows[i].kind == limit) w.limit_force = force;
    }
  }
  if (angular != 0.0) rigid.add_angular_impulse(v.chassis, angular, t_start);

  // The motor's and brake's work over the substep: their torque times the wheel's turn relative to
  // the chassis (the energy watch books it as the controls').
  if (!last) return;
  const double turned = chassis.pose_at(t_end).angle - start.angle;
  for (std::size_t i = 0; i < m; ++i) {
    if (rows[i].kind != motor) continue;
    const Tire& t = tires[v.wheels[rows[i].wheel].tire];
    work_ += v.wheels[rows[i].wheel].torque * (wheel_turn(t.particles, turn_frame(t.particles)) - turned);
  }
}

}  // namespace tire

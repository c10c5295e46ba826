// Vehicles (issue 37): a chassis, a dynamic Box2D prop, on two or more tires, each held at an axle
// point of the chassis by a joint, with a motor and a brake between them.
//
// The joints are solved as the contacts of an island are (island_contacts.h): each wheel is first
// solved alone by its own GlobalSolver (its constraints and its contacts with the world), loaded with
// the joints' last multipliers as a force; the joints' rows then solve
//     (D + α̃) Δλ = −C − α̃ λ,   D = Σ_wheels J_w K̂_w⁻¹ J_wᵀ + J_c M_c⁻¹ J_cᵀ,
// with K̂_w the wheel's last system (GlobalSolver::respond: its ground contacts held, their static
// friction too, so that a push at the axle rolls the wheel about its contact patch rather than
// sliding it) and M_c the chassis' mass and inertia (XPBD, Macklin et al. 2016, eq. 9–10, for the
// rows of one small system). The wheel moves by K̂_w⁻¹ J_wᵀ Δλ, the chassis by M_c⁻¹ J_cᵀ Δλ, handed
// to Box2D as the impulse Δλ/h on it. The chassis thus feels every force its wheels do, in the
// substep they do.
//
// The rows of a wheel, on its particles x and the chassis' displacement q = (u, θ):
// - the axle, C = hub(x) − X(q) along the chassis' suspension axis a and across it, with the hub
//   the mean of the rim's particles ("its hub as the rim defines it") and X the axle point on the
//   chassis: J_w = a/N at each rim particle, J_c = −(a, r × a) for r from the chassis' centre to the
//   axle point. Rigid (SolverConfig::rigid_compliance) across the axis; along it the suspension's
//   spring (compliance 1/k) and damper (XPBD eq. 26, γ = c/(k h)), or rigid without one;
// - the suspension's travel, a one-sided limit on the same C along the axis, |C| ≤ travel: a rigid
//   row, added while the hub is past either end or the limit's force from the last substep still
//   holds it, whose multiplier only pushes the hub back inside (λ ≤ 0 at the top, ≥ 0 at the bottom,
//   clamped in the rows' solve as a contact's is; a joint limit as Box2D's, Catto);
// - the motor (or the brake), on the wheel's turn relative to the chassis over the substep,
//   C = θ_w(x) − θ_c(q) − ω* h, with θ_w = Σ r⁰ᵢ × (xᵢ − xᵢ⁰) / Σ |r⁰ᵢ|² the mean turn of the
//   wheel's particles about their centroid at the substep's start (linear in x, its force a pure
//   torque: Σ J_w = 0): a velocity motor with a bounded torque, |λ| ≤ τ h², as Box2D's revolute
//   joint's motor (Catto). The brake is the same row with ω* = 0 and the brake's torque. The
//   reaction is the chassis' −1 on θ: the motor's torque and its reaction sum to nothing.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "tire/math/geometry.h"
#include "tire/math/state_hash.h"
#include "tire/rigid/bodies.h"
#include "tire/tire/global_solver.h"
#include "tire/tire/tire_spec.h"
#include "tire/xpbd/particles.h"

namespace tire {

struct SubstepContext;
class RigidWorld;
struct Tire;

// One wheel of a vehicle: where its axle is on the chassis and how it hangs there.
struct AxleSpec {
  Vec2 point;              // on the chassis, in its body frame (m)
  Vec2 axis{0.0, 1.0};     // the suspension's axis in the chassis' frame (unit; chassis up)
  double stiffness = 0.0;  // the suspension's spring along the axis (N/m); 0: a rigid axle
  double damping = 0.0;    // its damper (N·s/m)
  double travel = 0.0;     // the most a sprung hub moves along the axis either side (m); 0: no limit
  bool driven = true;      // the motor turns this wheel
};

// A wheel: a tire (its spawn position and velocity are the axle's) on an axle.
struct WheelSpec {
  TireSpec tire;
  AxleSpec axle;
};

// What the driver asks of a vehicle this tick.
struct VehicleControl {
  double throttle = 0.0;  // −1 … 1: full reverse … full forward (to +x when the chassis is level)
  bool brake = false;
  double lean = 0.0;  // −1 … 1: clockwise … counter-clockwise torque on the chassis
};

// The motor, brake and lean of a vehicle.
struct Drivetrain {
  double motor_torque = 60.0;   // most torque a driven wheel's motor gives (N·m)
  double motor_speed = 40.0;    // the wheel's spin relative to the chassis at full throttle (rad/s)
  double brake_torque = 200.0;  // most torque a brake holds (N·m), on every wheel
  double lean_torque = 80.0;    // torque on the chassis at full lean (N·m)
};

// The driver's head, a circle fixed to a chassis: what a level session watches (a head that touches
// the ground loses the level); the joints do not use it.
struct VehicleHead {
  Vec2 position;  // its centre in the chassis' frame (m)
  double radius = 0.0;
};

// A vehicle as built: a chassis (a dynamic prop, placed by its spec's position and angle) on its
// wheels, with a drivetrain.
struct VehicleSpec {
  PropSpec chassis;
  std::vector<WheelSpec> wheels;
  Drivetrain drivetrain;
};

// The joints' rows as VehicleJoints::solve builds them, on a wheel's particles (block order, as
// GlobalSolver::dof): tests check each gradient against the value's finite differences.
namespace vehicle_rows {
// The hub: the mean of the rim's particles (n … 2n − 1), at x or, `at_start`, at the substep's start.
Vec2 rim_hub(const Particles& p, std::uint32_t n, bool at_start);
// ∂(d·hub)/∂x: d/n at each rim particle.
void hub_gradient(std::uint32_t n, Vec2 direction, double* g);
// The hub's offset from its axle point along the suspension's axis, the chassis at `chassis` (m; +
// along the axis): the C of the spring and of the travel.
double stroke(const Particles& p, std::uint32_t n, const Pose& chassis, const AxleSpec& axle);
// The particles' centroid at the substep's start.
struct TurnFrame {
  Vec2 centroid;
};
TurnFrame turn_frame(const Particles& p);
// θ_w, the wheel's turn since the substep's start: the angle of the rotation that best maps the
// particles' offsets from their centroid then, r⁰ᵢ, onto those now, rᵢ (2-D Procrustes),
// θ_w = atan2(Y, X), X = Σ r⁰ᵢ·rᵢ, Y = Σ r⁰ᵢ × rᵢ; and its gradient (X perp(r⁰ᵢ) − Y r⁰ᵢ)/(X² + Y²).
// A force λ along that gradient is a pure torque of exactly λ in any configuration: it sums to no
// force and Σ rᵢ × ∇ᵢθ_w = (X² + Y²)/(X² + Y²) = 1, so the motor's torque on the wheel and its
// reaction on the chassis cancel (a gradient linear in x, perp(r⁰ᵢ)/Σ|r⁰ᵢ|², gave the wheel only
// cos θ_w of it: a vehicle in the air at one substep gained angular momentum).
double wheel_turn(const Particles& p, const TurnFrame& f);
// Writes the gradient into g (in the global solver's block order) and returns θ_w, from one pass.
double turn_gradient(const Particles& p, const TurnFrame& f, std::uint32_t n, double* g);
}  // namespace vehicle_rows

class VehicleJoints {
 public:
  // A vehicle on `wheels` (tire indices in the world, with their axles) under chassis prop
  // `chassis`; allocates each wheel's solver (outside the step). Its index.
  std::uint32_t add(std::uint32_t chassis, std::span<const std::uint32_t> wheels,
                    std::span<const AxleSpec> axles, const Drivetrain& drivetrain, std::uint32_t segments);
  std::size_t count() const { return vehicles_.size(); }
  std::size_t solver_count() const { return wheel_solvers_.size(); }  // the next wheel's slot is this
  void set_control(std::uint32_t vehicle, const VehicleControl& control) {
    Vehicle& v = vehicles_[vehicle];
    v.control_changed = v.control_changed || control.throttle != v.control.throttle ||
                        control.brake != v.control.brake || control.lean != v.control.lean;
    v.control = control;
  }
  // Whether its control changed since the last call (a sleeping vehicle wakes to it: a brake let go).
  bool take_control_change(std::uint32_t vehicle) {
    return std::exchange(vehicles_[vehicle].control_changed, false);
  }
  const VehicleControl& control(std::uint32_t vehicle) const { return vehicles_[vehicle].control; }
  const Drivetrain& drivetrain(std::uint32_t vehicle) const { return vehicles_[vehicle].drivetrain; }
  std::uint32_t chassis(std::uint32_t vehicle) const { return vehicles_[vehicle].chassis; }
  std::size_t wheel_count(std::uint32_t vehicle) const { return vehicles_[vehicle].wheels.size(); }
  std::uint32_t wheel_tire(std::uint32_t vehicle, std::size_t w) const {
    return vehicles_[vehicle].wheels[w].tire;
  }
  const AxleSpec& axle(std::uint32_t vehicle, std::size_t w) const {
    return vehicles_[vehicle].wheels[w].axle;
  }
  // Forgets the joints' last forces and the control (a vehicle put back at rest).
  void clear(std::uint32_t vehicle) {
    Vehicle& v = vehicles_[vehicle];
    v.control = {};
    for (Wheel& w : v.wheels) {
      w.hub_force = {};
      w.torque = 0.0;
      w.limit_force = 0.0;
    }
  }
  // The world's tire indices moved (a tire was removed before `removed`): the wheels after it follow.
  void tire_removed(std::uint32_t removed);

  // The solver kept for a wheel (Tire::wheel), from its solve to the joints' in the same iteration.
  GlobalSolver& solver(std::int32_t wheel) { return *wheel_solvers_[static_cast<std::size_t>(wheel)]; }

  // At each substep's prediction, before the tires': the chassis given the joints' last forces and
  // the lean's torque over the substep (they act on it from the substep's start), each wheel its
  // motor's last torque as a change of spin, and the lean's work booked.
  void begin_substep(std::vector<Tire>& tires, RigidWorld& rigid, const SubstepContext& ctx);
  // Before each iteration's solves: each wheel loaded with its axle's force so far.
  void load_wheels(std::vector<Tire>& tires, const SubstepContext& ctx);
  // After each iteration's solves: the joints solved (the header's system), wheels and chassis moved;
  // `last`: the substep's last iteration, which books the motors' work.
  void solve(std::vector<Tire>& tires, RigidWorld& rigid, const SubstepContext& ctx, bool last);

  // The joints' forces on wheel w of a vehicle, from the last substep: the axle's on the wheel's hub
  // (N, world) and the motor's or brake's torque on it (N·m).
  Vec2 axle_force(std::uint32_t vehicle, std::size_t w) const;
  double wheel_torque(std::uint32_t vehicle, std::size_t w) const;
  // The joints' state that the next step reads (their last forces, the controls).
  void hash_into(StateHash& h) const;
  // Energy the motors and the lean gave the world since last taken (J), for World::energy_in.
  double take_work() {
    const double w = work_;
    work_ = 0.0;
    return w;
  }

  static constexpr std::size_t kRowsPerWheel = 4;  // across the axis, along it, the motor/brake, the travel
  static constexpr std::size_t kMaxWheels = 8;

 private:
  struct Wheel {
    std::uint32_t tire = 0;
    AxleSpec axle;
    std::int32_t solver = -1;
    // The multipliers' totals as forces, kept from substep to substep as the next one's first
    // guess: the axle's on the hub (N, world) and the motor's or brake's torque on the wheel (N·m).
    Vec2 hub_force;
    double torque = 0.0;
    double limit_force = 0.0;                     // the travel's part of hub_force, along the axis (N)
    std::vector<double> load;                     // J_wᵀ λ in the solver's block order (kg·m)
    std::vector<double> response[kRowsPerWheel];  // K̂_w⁻¹ J_wᵀ of each row
    std::vector<double> gradient[kRowsPerWheel];  // J_w of each row
  };
  struct Vehicle {
    std::uint32_t chassis = 0;
    bool control_changed = false;  // set_control's, until take_control_change()
    std::vector<Wheel> wheels;
    Drivetrain drivetrain;
    VehicleControl control;
  };
  // Its wheels sleep, and with them its chassis: a vehicle sleeps and wakes whole (its island,
  // world/sleep_islands.h), and the joints of a sleeping one rest.
  static bool asleep(const Vehicle& v, const std::vector<Tire>& tires) {
    return tires[v.wheels.front().tire].asleep;
  }
  void turn_orbits(Vehicle& v, std::vector<Tire>& tires, RigidWorld& rigid, double h, double t_end);
  void solve_vehicle(Vehicle& v, std::vector<Tire>& tires, RigidWorld& rigid, const SubstepContext& ctx,
                     bool last);

  std::vector<Vehicle> vehicles_;
  std::vector<std::unique_ptr<GlobalSolver>> wheel_solvers_;
  double work_ = 0.0;
};

}  // namespace tire

// What a world shows of its tires and props between ticks: read-only views, copied out or pointing
// into the world's own arrays (valid until the next step, add or remove); and what the player gives
// it each tick.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "tire/math/geometry.h"
#include "tire/rigid/bodies.h"
#include "tire/tire/tick_contacts.h"
#include "tire/tire/tire_spec.h"

namespace tire {

// How near a tread particle a mouse press must be to grab its tire (m).
inline constexpr double kGrabRadius = 0.3;

// The player's input for one tick.
struct TickInput {
  double steer = 0.0;  // [-1, 1]; a player vehicle's throttle (+1 full forward, −1 full reverse)
  bool jump = false;
  double inflate = 0.0;  // [-1, 1]: +1 inflates the player at its inflate_rate, −1 deflates it
  double lean = 0.0;     // [-1, 1]: a player vehicle's lean, +1 counter-clockwise (nose up going right)
  bool brake = false;    // a player vehicle's brakes, held
};

// A tread particle pulled towards a target every substep (a mouse drag: Simulation::grab).
struct TireGrab {
  std::uint32_t particle = 0;  // 0 .. segments − 1
  Vec2 target;
};

struct TireView {
  TireId id = 0;
  bool player = false;
  bool asleep = false;
  bool grounded = false;  // a tread particle touched ground in the last substep
  // The tread touched ground within SolverConfig::jump_grace: a jump now would leave the ground.
  bool may_jump = false;
  Vec2 centroid;              // of all particles: the hub (m)
  Vec2 velocity;              // of the centroid (m/s)
  double spin = 0.0;          // angular velocity about the hub (rad/s, counter-clockwise)
  double area_ratio = 0.0;    // the tread's area over its rest area
  double pressure = 0.0;      // the pressure in force (TireSpec::pressure, moved by inflating)
  double outer_radius = 0.0;  // m, as built (TireSpec)
  double inner_radius = 0.0;  // m, the rim's
  double mass = 0.0;          // kg, the whole tire's
  std::uint32_t segments = 0;
  // The particles' positions: the tread's `segments` counter-clockwise, then the rim's.
  std::span<const Vec2> positions;
  TickContacts contacts;         // what its contacts did over the last tick
  std::optional<TireGrab> grab;  // while a particle of it is grabbed
};

// The most wheels a vehicle has (VehicleJoints::kMaxWheels).
inline constexpr std::size_t kMaxVehicleWheels = 8;

// A vehicle (levels/README.md, "Vehicles"): its chassis, a dynamic prop, on its wheels, tires.
struct VehicleView {
  std::size_t index = 0;  // in the order the vehicles were added
  PropId chassis = 0;     // its prop (Simulation::prop)
  bool player = false;    // the player's input drives it
  Pose pose;              // the chassis' origin and angle (rad, counter-clockwise)
  Vec2 center;            // the chassis' centre of mass (m): the player's position for a player vehicle
  Vec2 velocity;          // of the centre of mass (m/s)
  double angular_velocity = 0.0;  // rad/s, counter-clockwise
  std::array<TireId, kMaxVehicleWheels> wheel_ids{};
  std::size_t wheel_count = 0;
  std::span<const TireId> wheels() const { return {wheel_ids.data(), wheel_count}; }
  std::array<bool, kMaxVehicleWheels> wheel_driven{};  // the motor turns wheel w (its `driven` key)
  double motor_speed = 0.0;  // a driven wheel's spin relative to the chassis at full throttle (rad/s)
  // What drives it now: throttle and lean in [-1, 1] (the player's steer and lean), the brakes.
  double throttle = 0.0;
  double lean = 0.0;
  bool brake = false;
  // The driver's head in the world, if it has one: centre (m) and radius (m).
  std::optional<Vec2> head_center;
  double head_radius = 0.0;
};

// The world's mechanical energy between ticks, and what was brought into it from outside since it
// was made: the bodies added (less those removed), the commands that changed its energy, and the
// work of the tires' drives, jumps and inflating. The energy less what came in rises only by what
// nothing brought: a contact making energy, or the work of kinematic props and grabs, which are
// not counted (docs/at-rest.md, "The energy watch's books").
struct EnergyView {
  double kinetic = 0.0;        // J
  double gravitational = 0.0;  // J, zero at the origin
  double elastic = 0.0;        // J, held by the tires' compliant constraints
  double brought_in = 0.0;     // J
  double total() const { return kinetic + gravitational + elastic; }
};

// How far tires are inside each other: the deepest tread particle of one tire inside another's
// tread polygon (docs/at-rest.md).
struct TireOverlap {
  double depth = 0.0;  // how far the particle is from the other's tread, inside it (m); 0 for none
  TireId tire = 0;     // the tire whose particle it is
  TireId inside = 0;   // the tire it is inside
};

struct PropView {
  PropId id = 0;
  PropType type = PropType::static_body;
  PropShape shape = PropShape::box;
  bool alive = false;     // a removed prop stays, dead
  std::string_view name;  // as the level names it; "" for none
  PropState state;        // a dead prop's is all zero
  // Its shape in its own frame (state.pose places it in the world): a box's or polygon's corners
  // counter-clockwise, a chain's points in order (closed when `loop`), none for a circle.
  std::span<const Vec2> vertices;
  std::span<const Vec2> normals;  // of edge i (vertex i to i + 1), out of the solid
  double radius = 0.0;            // a circle's (m)
  double thickness = 0.0;         // a chain's: how far behind its line still counts as inside (m)
  bool loop = false;              // a chain's: closed
  Aabb local_bounds;              // its box in its frame (a chain's widened by its thickness)
  std::span<const Vec2> path;     // a kinematic prop's waypoints, in the world; empty for none
};

}  // namespace tire

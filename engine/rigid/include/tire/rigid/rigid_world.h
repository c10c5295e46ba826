// The rigid side of the world, in one Box2D world: the static box obstacles and the props (static,
// dynamic and kinematic bodies). Box2D's broad phase answers which of them are near a tire; Box2D
// integrates the props and their contacts with each other; the tire's solver handles particle
// contacts itself and hands the reaction impulses back (two-way coupling).
//
// Within a tick the tire sees each prop at a predicted pose: its pose at the start of the tick
// moved on with its velocity, and that velocity includes the impulses the tires gave it so far this
// tick, so a crate gives way as it is pushed. At the end of the tick the impulses go to Box2D and
// Box2D steps (only if something can move).
//
// With substep motion (begin_tick's `substep_motion`, which the world asks for when its method says
// so), Box2D steps once per substep instead (World::step: end_tick(h), then begin_tick(h, …, time)
// for the next): the props meet the tires at the substeps' rate, as the tires' own constraints do,
// and a tire pushing a crate does to it what it does at any substep count (a crate standing still
// for a whole tick took every substep's push as a collision: driven into a 6 kg crate, the tire
// pushed it 2.45 m at 2 substeps and 8.62 m at 8 on average over ten starts, against 2.07 and
// 2.11 m with substep motion; docs/physics.md, "What the default does differently").
//
// With substep motion a prop that touches nothing in Box2D moves
// within the tick as the tire's particles do (Macklin et al. 2019, Algorithm 1): gravity each
// substep, and a push from the substep in which it acted, not from the tick's start. Box2D then
// starts its step from where that motion leaves the prop less a step at its final velocity, so it
// ends the tick where the tires last saw it. (Without it a crate lying on a tire feels its weight
// once a tick and each push as if made at the tick's start: at 8 substeps it bounced on the tire
// by 4 cm for ever.) Without it the props keep the tick-long motion (the Gauss–Seidel method's).
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "tire/math/state_hash.h"
#include "tire/rigid/bodies.h"
#include "tire/rigid/prop_geometry.h"

class b2World;
class b2Body;
class b2ContactListener;

namespace tire {

struct Prop {
  PropSpec spec;
  PropGeometry geometry;  // the shape the tires collide with; its Box2D body is RigidWorld's own
  bool alive = true;

  // Tick state (doubles, read from Box2D at the start of the tick; with substep motion, at the
  // start of each substep, begin_tick's `time`).
  double start_time = 0.0;       // when it was read (s into the tick)
  Pose start_pose;               // body origin at the start of the tick
  Vec2 start_center;             // centre of mass, world, at the start of the tick
  Vec2 local_center;             // centre of mass in the body frame
  Vec2 velocity;                 // of the centre of mass, including this tick's impulses so far
  double omega = 0.0;            // angular velocity, including this tick's impulses so far
  double inverse_mass = 0.0;     // 0: static or kinematic (infinite mass for the tire)
  double inverse_inertia = 0.0;  // about the centre of mass
  Vec2 impulse;                  // this tick's impulses from tires (N·s)
  double angular_impulse = 0.0;  // their moment about the centre of mass (N·m·s)
  // What `velocity` and `omega` times the time into the tick overstate of the way travelled, the
  // changes of velocity this tick having acted only from when they were made: Σ Δv·t_from.
  Vec2 untravelled;
  double untravelled_angle = 0.0;
  bool airborne = false;  // substep motion: awake, and touching nothing in Box2D this tick
  bool awake = false;     // Box2D simulates it this tick (a dynamic prop not asleep)
  // Its velocity as Box2D had it before the tires' impulses of this step were handed over
  // (end_tick): the approach velocity its restitution may act on (RestitutionRule, rigid_world.cpp).
  Vec2 velocity_before_push;
  double omega_before_push = 0.0;
  bool pushed = false;  // the tires handed it an impulse in this step

  // What holds a dynamic prop up (shock propagation, one level deep): the normals, pointing into
  // the prop, of its Box2D contacts with static and kinematic bodies at the start of the tick. A
  // push into a support cannot move the prop this tick; the support (in Box2D) takes it.
  static constexpr int kMaxSupports = 4;
  Vec2 supports[kMaxSupports];
  int support_count = 0;
  // How freely the prop moves when pushed along unit vector `push`: 1 when nothing holds it that
  // way, 0 straight into a support, 1 − (push·s)² in between (only the part of the push along the
  // support's surface can move it). Scales the prop's inverse mass for the tire's contacts.
  double mobility(Vec2 push) const {
    double m = 1.0;
    for (int i = 0; i < support_count; ++i)
      if (const double into = -dot(push, supports[i]); into > 0.0) m = std::min(m, 1.0 - into * into);
    return m;
  }

  // Kinematic path state.
  std::size_t next_waypoint = 0;
  int direction = 1;  // +1 forward along the waypoints, −1 back

  // The predicted pose and centre at time t (s) into the tick.
  Pose pose_at(double t) const;
  Vec2 center_at(double t) const { return start_center + velocity * (t - start_time) - untravelled; }
  // Velocity of the body's material point at world position p, time t.
  Vec2 point_velocity(Vec2 p, double t) const { return velocity + perp(p - center_at(t)) * omega; }
  bool is_dynamic() const { return inverse_mass > 0.0; }
};

class RigidWorld {
 public:
  explicit RigidWorld(Vec2 gravity);
  ~RigidWorld();
  RigidWorld(const RigidWorld&) = delete;
  RigidWorld& operator=(const RigidWorld&) = delete;
  RigidWorld(RigidWorld&&) noexcept;
  RigidWorld& operator=(RigidWorld&&) noexcept;

  std::uint32_t add_obstacle(const Obstacle& obstacle);
  const std::vector<Obstacle>& obstacles() const { return obstacles_; }

  // Props keep their index for the life of the world; a removed prop stays as a dead slot.
  std::uint32_t add_prop(const PropSpec& spec);
  bool remove_prop(std::string_view name);
  std::optional<std::uint32_t> find_prop(std::string_view name) const;
  const std::vector<Prop>& props() const { return props_; }
  Prop& prop(std::uint32_t i) { return props_[i]; }
  // A live prop's pose and velocity now (Box2D's, between ticks).
  Pose current_pose(std::uint32_t i) const;
  Vec2 current_velocity(std::uint32_t i) const;
  // All of a live prop's state now (between ticks).
  PropState prop_state(std::uint32_t i) const;
  bool path_command(std::string_view name, PathCommand command);

  void set_gravity(Vec2 gravity);
  // Moves a live prop's origin to `position` at `angle`, at rest and awake (between ticks: a respawn).
  void place_prop(std::uint32_t i, Vec2 position, double angle);
  // An impulse (N·s) at a live prop's centre of mass, now (between ticks); ignored for a name not
  // in the world or a prop that cannot move.
  void apply_impulse_now(std::string_view name, Vec2 impulse);
  void apply_impulse_now(std::uint32_t i, Vec2 impulse);  // the same, prop i

  // Replaces `obstacles` and `props` with the indices of those whose (fattened) bounds overlap
  // `region`, ascending, each once (a chain's edges are Box2D proxies of their own). Does not
  // allocate once the vectors have grown to the largest answer.
  void query(const Aabb& region, std::vector<std::uint32_t>& obstacles,
             std::vector<std::uint32_t>& props) const;

  // Start of a tick, or of a step of Box2D's within it that starts `time` into the tick and lasts
  // dt: read every prop's state, steer kinematic props along their paths. With `substep_motion`,
  // airborne props move within the tick as the tires' particles do (above).
  void begin_tick(double dt, bool substep_motion = false, double time = 0.0);
  // Start of the substep at `time` into the tick, of length h: substep motion's gravity.
  void begin_substep(double time, double h);
  // A tire's contact pushed prop i with impulse P at world point p (at time t into the tick); the
  // change of velocity acts from time `since` (the substep's start for a correction of positions,
  // its end for one of velocities) where substep motion is on.
  void add_impulse(std::uint32_t i, Vec2 impulse, Vec2 point, double t, double since);
  // An angular impulse (N·m·s) on prop i, felt from `since` as add_impulse's (a vehicle's joints).
  void add_angular_impulse(std::uint32_t i, double angular, double since);
  // End of a tick: hand the impulses to Box2D and step it, if anything can move.
  void end_tick(double dt);

  // Whether Box2D has anything to integrate (a dynamic or kinematic prop): otherwise it is never
  // stepped.
  bool needs_stepping() const { return moving_props_ > 0; }
  // Whether a tire can push anything (a live dynamic prop): otherwise add_impulse never happens.
  bool takes_impulses() const { return dynamic_props_ > 0; }

  void hash_into(StateHash& h) const;

  // Sleeping (world/sleep_islands.h).
  // Props removed so far: a change tells that something under a sleeping tire may be gone.
  std::uint64_t removals() const { return removals_; }
  // Whether live prop i moves this tick: a kinematic prop with a velocity, a dynamic one awake.
  bool moving(std::uint32_t i) const;
  // The world box around live prop i at the start of the tick, widened by its travel over dt.
  Aabb swept_bounds(std::uint32_t i, double dt) const;
  // The dynamic props among `props` and every dynamic body joined to them through touching Box2D
  // contacts (props resting on each other sleep together, as Box2D's islands do): whether all of
  // them are slower than `speed` (their centre, and their outline about it); sleep_group puts them
  // all to sleep, wake_group wakes them.
  bool group_still(std::span<const std::uint32_t> props, double speed);
  void sleep_group(std::span<const std::uint32_t> props);
  void wake_group(std::span<const std::uint32_t> props);
  // Whether Box2D may put dynamic prop i to sleep on its own (not while it touches an awake tire,
  // which Box2D does not see: the tire's pushes would keep waking it).
  void set_sleeping_allowed(std::uint32_t i, bool allowed);

 private:
  // Breadth-first over touching Box2D contacts from the dynamic props among `props`: fills group_.
  void gather_group(std::span<const std::uint32_t> props);
  void steer_along_path(std::uint32_t i, double dt);

  // Box2D stays behind this wall (the layer links it privately): its types are only named here.
  // The contact listener first, so that it outlives the world that calls it.
  std::unique_ptr<b2ContactListener> restitution_rule_;  // rigid_world.cpp: RestitutionRule
  std::unique_ptr<b2World> world_;
  b2Body* ground_ = nullptr;  // carries every obstacle fixture
  std::vector<Obstacle> obstacles_;
  std::vector<Prop> props_;
  std::vector<b2Body*> bodies_;  // props_[i]'s Box2D body; null once the prop is removed
  std::size_t moving_props_ = 0;
  std::size_t dynamic_props_ = 0;
  std::uint64_t removals_ = 0;
  std::vector<std::uint32_t> group_;   // gather_group's answer (scratch, one entry a prop at most)
  std::vector<std::uint8_t> grouped_;  // per prop: in group_ (scratch)
  Vec2 gravity_;
  bool substep_motion_ = false;  // this tick's
};

}  // namespace tire

// A soft tire: two concentric rings of N particles (outer = tread, inner = rim), distance
// constraints along both rings and on the spokes between them, and one area constraint on the
// outer ring. The hub is derived (the mass-weighted centroid), never a free particle.
//
// Particle layout: outer ring at [0, N), inner ring at [N, 2N), both counter-clockwise.
//
// Storage (issue 12): what the tires of one shape share (the constraint pairs, their cut into SIMD
// batches) is the TireTopology. Everything of the tire's own whose size its particle and constraint
// counts fix (the particles, the distance constraints' rest lengths, λ and compliances, contact
// records and flags) lives in one heap block, `arrays`, allocated once when the tire is built; the
// arrays are views into it. A Tire is move-only: a move hands the block over without moving it, so
// every view stays valid (World keeps a std::vector<Tire>). The broad-phase lists (candidates,
// prop_candidates, prop_frames, pairs, prop_impulses) are growable vectors: their length is the
// scene's, not the tire's. Each is reserved once when the tire is built, for a usual scene, and
// grows past that only during the first ticks of a crowded one, before the step stops allocating.
#pragma once

#include <bit>
#include <cstdint>
#include <limits>
#include <vector>

#include "tire/rigid/prop_geometry.h"
#include "tire/tire/tick_contacts.h"
#include "tire/tire/tire_spec.h"
#include "tire/tire/tire_topology.h"
#include "tire/xpbd/area_constraint.h"
#include "tire/xpbd/contact.h"
#include "tire/xpbd/distance_constraint.h"
#include "tire/xpbd/particles.h"

namespace tire {

// What drives a tire during one tick.
struct TireControl {
  double steer = 0.0;    // [-1, 1]; +1 drives towards +x
  bool jump = false;     // a jump request; consumed at the start of the tick
  double inflate = 0.0;  // [-1, 1]; moves the pressure at the start of each tick (TireSpec::inflate_rate)
};

// A landing, for restitution (TireSpec::restitution; tire_solver.cpp): from the first substep
// touching a surface to the first that touches none.
struct Landing {
  bool touching = false;
  double approach = 0.0;  // the hub's speed into the surface when it touched (m/s); 0: no bounce owed
  double time = 0.0;      // how long it has touched (s)
  Vec2 impulse;           // Σ of its contacts' normal impulses (its direction is the bounce's)
};

// A particle that may touch an obstacle or a prop during this substep (narrow-phase candidate),
// with the friction of the pair already mixed.
struct ContactPair {
  std::uint32_t particle;
  std::uint32_t index;  // into the obstacles, or into prop_frames when is_prop
  bool is_prop;
  double mu_static;
  double mu_kinetic;
};

// A reaction impulse a tire's contact owes a dynamic prop. Collected per tire while tires are
// solved (possibly in parallel) and handed to the props afterwards in tire order, so the result
// never depends on which thread solved what.
struct PropImpulse {
  std::uint32_t prop;
  Vec2 impulse;  // N·s
  Vec2 point;    // where it acts (world)
  double time;   // into the tick (s)
  double since;  // when the change of velocity it makes acts from (RigidWorld::add_impulse)
};

// A nearby prop's predicted pose at the start and end of the current substep.
struct PropFrame {
  std::uint32_t prop;
  Pose start;
  Pose end;
  bool round = false;  // a circle: the same however it turns

  // Where a particle that starts the substep at `world` starts its path in the prop's frame. The
  // path is taken as a straight line from there to where it ends, end.to_local(x). A turn of the
  // prop over the substep bends the particle's true path in that frame into an arc about the
  // prop's origin, whose chord may cross a prop the particle never came near (a tread particle
  // above a ball spinning at 100 rad/s crossed it and was thrown out of it): a circle, the same
  // however it turns, is met in a frame that only moves.
  Vec2 start_local(Vec2 world) const {
    return round ? end.to_local(world - start.position + end.position) : start.to_local(world);
  }
};

// The tire's motion as a rigid body: what the hub does. Every particle has the same mass m.
struct RigidMotion {
  Vec2 centroid;         // hub (m)
  Vec2 velocity;         // of the hub (m/s)
  double omega = 0.0;    // angular velocity about the hub (rad/s, CCW): L / I
  double inertia = 0.0;  // I = Σ m |r|² about the hub (kg m²)
};

struct Tire {
  // `topology`: the shared one of the spec's shape (World::add_tire passes its own); null builds one
  // for this tire alone.
  Tire(TireId id, const TireSpec& spec, std::shared_ptr<const TireTopology> topology = nullptr);
  // Moves keep the arrays where they are; a copy would have to re-point every view into a block of
  // its own, and nothing needs one.
  Tire(Tire&&) noexcept = default;
  Tire& operator=(Tire&&) noexcept = default;
  Tire(const Tire&) = delete;
  Tire& operator=(const Tire&) = delete;

  // Puts every particle back where the spec builds it, at rest; forgets contacts and λ.
  void reset();

  // Live tuning: new compliances (to every constraint of each kind) and a new total mass.
  void set_compliance(const TireCompliance& compliance);
  void set_mass(double mass);

  // The constraints of each kind, as ranges of `distance` (rings first, then spokes).
  std::size_t outer_ring_first() const { return 0; }
  std::size_t inner_ring_first() const { return n; }
  std::size_t spokes_first() const { return 2 * n; }

  std::uint32_t segments() const { return n; }
  std::uint32_t particle_count() const { return 2 * n; }
  double total_mass() const { return spec.mass; }
  double particle_mass() const { return spec.mass / (2.0 * n); }  // every particle weighs the same

  // Every particle has the same mass, so mass-weighted means are plain means.
  Vec2 centroid() const;  // mass-weighted centroid of all particles (the hub)
  Vec2 velocity() const;  // mass-weighted mean velocity
  double angular_velocity() const { return rigid_motion().omega; }
  RigidMotion rigid_motion() const;
  // The same, of the tire's motion over its last substep of length h, from positions: (x − x_prev)/h.
  // Not from its velocities, which the velocity pass has changed since (friction, damping).
  RigidMotion substep_motion(double h) const;
  double area() const;  // current area of the outer ring (m²)
  double area_ratio() const { return area() / area_constraint.rest_area; }
  bool grounded() const;  // an outer particle touched ground in the last substep
  // The tread touched ground at most `grace` seconds ago (0: in the last substep). The jump asks
  // this with SolverConfig::jump_grace; so do the HUD and the tread's sound, which then agree with it.
  bool touched_ground_within(double grace) const { return air_time <= grace; }
  // Particles in contact in the last substep: with a surface, or with another tire (pushed by it or
  // carrying it).
  std::size_t touching_particles() const;
  bool is_finite() const;  // no NaN/Inf in positions or velocities
  // Every per-particle array holds 2N entries (soft_lambda N, contact_mask one bit each) and every
  // constraint names particles of this tire: what the solver indexes by without checking
  // (TIRE_ASSERT in debug builds).
  bool sizes_consistent() const;
  double max_abs_coordinate() const;
  // The contact record of particle i, marked as written this substep.
  ContactRecord& touch_contact(std::uint32_t i) {
    contact_mask[i >> 6] |= std::uint64_t{1} << (i & 63);
    return contacts[i];
  }
  // f(i) for each particle i whose record was written this substep, ascending.
  template <typename F>
  void for_each_contact(F&& f) const {
    for (std::size_t word = 0; word < contact_mask.size(); ++word)
      for (std::uint64_t bits = contact_mask[word]; bits != 0; bits &= bits - 1)
        f(static_cast<std::uint32_t>(word * 64 + static_cast<std::size_t>(std::countr_zero(bits))));
  }
  // Whether particle i was held by a surface (its record written) in the substep before this one.
  bool was_held(std::uint32_t i) const { return (held_mask[i >> 6] >> (i & 63)) & 1u; }
  // Puts the written records back to default and clears the mask, keeping it as held_mask.
  void clear_contacts();

  // Asks the CPU to start loading what a substep reads (a hint; changes nothing): the world calls
  // it for the next tire while it solves this one.
  void prefetch() const;

  TireId id;
  TireSpec spec;
  // A vehicle's wheel (vehicle_joints.h): its solver's slot there, and the chassis prop it does not
  // collide with (it hangs on it); −1 for a tire on its own.
  std::int32_t wheel = -1;
  std::int32_t chassis = -1;
  double spawn_mass;      // the mass it was built with: "mass_scale" scales this
  std::uint32_t n;        // particles per ring
  double segment_length;  // rest length of one outer-ring segment (m)

  std::shared_ptr<const TireTopology> topology;  // shared by the tires of this shape
  // The one heap block of the arrays below (all but the broad-phase lists): particles, the distance
  // set's lanes, contacts and flags, each starting on a cache line.
  ArrayBlock arrays;
  Particles particles;
  // On topology->distance(): this tire's rest lengths, λ and compliance per kind.
  DistanceConstraintSet distance;  // rings, then spokes; ordered so neighbours rarely share a particle
  AreaConstraint area_constraint;
  double area_lambda = 0.0;
  // The rim (inner ring) keeps its area as stiffly as its edges keep their lengths: a wheel's rim is
  // rigid metal, and without this the ring of fixed edge lengths could fold flat under a heavy load.
  AreaConstraint rim_area_constraint;
  double rim_area_lambda = 0.0;

  ArrayView<ContactRecord> contacts;  // per particle, this substep (default where untouched)
  // Bit i set: contacts[i] was written this substep. Only those are visited and cleared, so a
  // substep costs nothing for the particles nowhere near a surface.
  ArrayView<std::uint64_t> contact_mask;
  // The mask of the substep before (clear_contacts keeps it): a one-sided chain pushes out a
  // particle it finds inside only if a surface held it then (prop_geometry.h, local_contact).
  ArrayView<std::uint64_t> held_mask;
  ArrayView<std::uint8_t> grounded_flags;  // per particle, last substep
  // How long since the tread last touched ground (s): 0 while it does; infinite after a jump and at
  // spawn, until it lands. A jump is honoured while it is at most SolverConfig::jump_grace.
  double air_time = std::numeric_limits<double>::infinity();
  // Whether the particles' velocities about the hub are still the spin they were built with,
  // V + ω × r, a tangent; the global method's first prediction makes them the chords of a turn by ωh
  // (global_method.cpp, chord_spin) and every prediction clears it.
  bool spin_as_built = false;
  // Whether rolling resistance held the tire's spin at the last velocity pass (the moment needed to
  // stop it was within C_rr·N·R): the global method then holds its roll in the next position solve
  // too, up to that moment (GlobalSolver, the rolling row), as a real tire stays put on a slope
  // gentler than C_rr.
  bool rolling_held = false;
  std::vector<std::uint32_t> candidates;       // obstacles near the tire this tick (broad phase)
  std::vector<std::uint32_t> prop_candidates;  // props near the tire this tick (broad phase)
  std::vector<PropFrame> prop_frames;          // their poses this substep
  std::vector<ContactPair> pairs;              // particles near any of them this substep
  std::vector<PropImpulse> prop_impulses;      // owed to props since they were last handed over
  ArrayView<double> soft_lambda;  // per outer particle: normal λ against other tires, this substep
  // Pushes from neighbours that came after the tire's own solve in a substep (the global method's
  // contacts between tires, TireNeighbours::apply_reactions): a rigid change of velocity,
  // v += velocity + perp(x − centre)·spin, owed to the next prediction, which adds it and clears
  // it. Kept apart until then, so that the tire's velocity between ticks is its motion's (a tire at
  // the bottom of a pile owes the weight of those above it every substep).
  struct LatePush {
    Vec2 velocity;
    double spin = 0.0;
    Vec2 centre;
    bool any = false;
    // Adds a rigid change of velocity about `about`, re-expressed about this one's centre.
    void add(Vec2 v, double w, Vec2 about) {
      if (!any) centre = about;
      velocity += v + perp(centre - about) * w;
      spin += w;
      any = true;
    }
  };
  LatePush late_push;
  // The late push this substep's prediction took, and its gravity's h g, until the tire's first
  // solve of the substep: neighbours anchoring their static friction to its predicted tread
  // (TireNeighbours::capture) leave it out, as their own reactions coming back and a fall its
  // supports will take back.
  LatePush predicted_push;
  Vec2 tread_hub;            // mean of the tread particles, after this iteration's own solve
  double tread_reach = 0.0;  // largest distance of a tread particle from tread_hub
  Vec2 rim_hub;              // the same for the rim, for the tread–rim contact
  double rim_reach = 0.0;
  ArrayView<std::uint8_t> on_tire;  // per particle: resting on another tire, this substep
  // Per particle: where its static friction stuck, while it holds (GlobalSolver: the friction
  // takes the particle back to it), and on what (anchor_code). On a surface, the point in the
  // surface's frame; on a neighbour's tread, x = k + s, the point s along its edge (k, k + 1).
  ArrayView<Vec2> friction_anchor;
  ArrayView<std::int32_t> anchor_on;
  // What an anchor is on: the prop, the world for an obstacle (a point of the world stays put from
  // one obstacle to the next), or a neighbour tire (its index in the world); kNoAnchor while the
  // particle's friction does not hold.
  static constexpr std::int32_t kNoAnchor = -1;
  static constexpr std::int32_t anchor_code(std::int32_t prop, std::int32_t tire = -1) {
    return tire >= 0 ? -3 - tire : prop >= 0 ? prop : -2;
  }
  TireControl control;
  Landing landing;
  TickContacts tick_contacts;  // the last tick's, for listeners (sound); reset by begin_tick
  // The global method: the most one of its solves turned one of its constraints this tick (rad), for
  // the refinement (SolverConfig::refine_turn); reset by begin_tick.
  double newton_turn = 0.0;
  // The energy its controls gave it since the World last collected it (J): the kinetic energy of
  // its drive and its jumps, and the air's energy inflating changed. For the energy watch
  // (World::energy_in); not state.
  double control_work = 0.0;
  // The global method's work this tick (GlobalSolver): its solves, the factorisations of K they
  // made, the active-set passes they solved on a factor already made, the searches for contacts
  // (one a solve and one a pass) and the tests of a tread particle against a neighbour's tread in
  // them; reset by begin_tick.
  struct GlobalWork {
    std::uint32_t solves = 0;
    std::uint32_t factorisations = 0;
    std::uint32_t updates = 0;
    std::uint32_t searches = 0;
    std::uint64_t tread_tests = 0;
    std::uint32_t failed_solves = 0;  // factorisations or solves that were not finite (World counts them)
    GlobalWork& operator+=(const GlobalWork& o) {
      solves += o.solves;
      factorisations += o.factorisations;
      updates += o.updates;
      searches += o.searches;
      tread_tests += o.tread_tests;
      failed_solves += o.failed_solves;
      return *this;
    }
  };
  GlobalWork global_work;

  // A mouse grab: particle `grab_particle` pulled towards `grab_target` by a compliant XPBD
  // constraint C = |x − target| (compliance grab_compliance), while grabbed.
  bool grabbed = false;
  std::uint32_t grab_particle = 0;
  Vec2 grab_target;
  double grab_compliance = 1e-4;  // m/N: 10 kg hangs 1 cm below the mouse
  double grab_lambda = 0.0;

  // Sleeping (world/sleep_islands.h): an asleep tire is not simulated until its island is woken; still_time
  // is how long it has been still (SolverConfig::sleep_speed), counted while it is awake.
  bool asleep = false;
  double still_time = 0.0;
  Vec2 still_anchor;            // its hub when it last became still
  ArrayView<Vec2> still_shape;  // and each particle's offset from that hub then
  TireId island = 0;            // while asleep: the island it sleeps in (the id of one of its tires)
  // A vehicle's wheel whose motor or lean is at work this tick: not resting, however slowly it moves.
  bool driven = false;
};

}  // namespace tire

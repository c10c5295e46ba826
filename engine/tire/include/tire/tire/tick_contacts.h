// What contacts did: a tire's over one tick, summed over its substeps, and the island solve's work
// since the world began.
#pragma once

#include <cstdint>

namespace tire {

// What a tire's contacts did over its last tick, for whoever listens between ticks (the game's
// sound): filled while the tire is solved, never read by the solver, so it changes no result. The
// normal impulses are the contacts' XPBD multipliers turned into N·s and summed over the tick's
// substeps: J = m·λ_n/h for a surface contact (λ_n kept as a distance, contact.h) and λ/h for the
// contact between treads (soft_contact.h, whose λ is already m·distance). A tire resting on the
// ground reports its weight times dt; a landing, its change of momentum. A sleeping tire is not
// solved and keeps the figures of its last awake tick.
struct TickContacts {
  double ground = 0.0;  // obstacles and static props (N·s)
  double prop = 0.0;    // dynamic and kinematic props (N·s)
  double tire = 0.0;    // other tires (N·s)
  // The fastest slide of a contact with a surface under kinetic friction (static friction did not
  // hold it): the tangential speed, relative to the surface, of the tire's rigid motion (hub and
  // spin) at that contact, before friction acts (m/s); 0 when every contact held.
  double slip_speed = 0.0;
};

// The work of solving piles of touching tires as one problem each (docs/at-rest.md), counted since
// the world began; all zero when solver.island_tires is 0.
struct IslandWork {
  std::uint64_t solves = 0;      // islands solved
  std::uint64_t rows = 0;        // contact rows
  std::uint64_t passes = 0;      // active-set passes
  std::uint64_t iterations = 0;  // conjugate-gradient iterations
  std::uint64_t breakdowns = 0;  // passes whose incomplete Cholesky factor broke down (then shifted)
  std::uint64_t overflows = 0;   // islands left to block Gauss–Seidel for want of room
  std::uint64_t failures = 0;    // solves given up (not positive definite, not finite, not converged)
  std::uint64_t unsettled = 0;   // solves whose active set still changed when the passes ran out
};

}  // namespace tire

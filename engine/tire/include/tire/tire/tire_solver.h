// One XPBD substep for one tire (Macklin et al. 2019, "Small Steps in Physics Simulation",
// Algorithm 1): predict, solve every constraint with λ reset to zero, then derive velocities.
#pragma once

#include "tire/rigid/rigid_world.h"
#include "tire/tire/global_solver.h"
#include "tire/tire/solver_config.h"
#include "tire/tire/tire.h"
#include "tire/tire/tire_neighbours.h"

namespace tire {

class IslandContacts;
class VehicleJoints;

struct SubstepContext {
  double h = 0.0;     // substep (s)
  double time = 0.0;  // of the substep's start, from the start of the tick (s)
  Vec2 gravity;
  const SolverConfig* config = nullptr;
  const RigidWorld* rigid = nullptr;   // obstacles and props, read only while tires are solved
  bool tire_pairs = false;             // contacts between tires follow each iteration: keep tread bounds
  GlobalSolverPool* global = nullptr;  // the global method's solvers (SolverMethod::global only)
  // The global method's contacts between tires: the neighbours' treads (null: none, a lone tire).
  const TireNeighbours* neighbours = nullptr;
  // The island's solve of the contacts between tires (island_contacts.h): each tire solved alone by
  // its own solver, kept for it (null: solved by the pool's).
  IslandContacts* island = nullptr;
  // The vehicles' joints (vehicle_joints.h): a wheel (Tire::wheel) is solved by the solver they keep
  // for it, whose system their solve reads after (null: no vehicles).
  VehicleJoints* vehicles = nullptr;
};

// Start of a tick: broad-phase query for obstacles near the tire and the jump, if asked for and
// the tread touched ground within SolverConfig::jump_grace.
void begin_tick(Tire& tire, const SolverConfig& config, const RigidWorld& rigid);

// A substep in three phases, so that a world can solve contacts between tires inside each iteration:
// begin (predict, find contact candidates, reset λ), iterations, end (velocities, friction,
// damping). Each touches only its own tire, so tires can be solved in parallel; impulses owed to
// props wait in the tire until apply_prop_impulses. substep() runs the three for a tire on its own.
void begin_substep(Tire& tire, const SubstepContext& ctx);
// `last`: the substep's last iteration, where the tread–rim contact is solved (once per substep).
void solve_iteration(Tire& tire, const SubstepContext& ctx, bool last);
void end_substep(Tire& tire, const SubstepContext& ctx);
void substep(Tire& tire, const SubstepContext& ctx, RigidWorld& rigid);

// Hands the reaction impulses a tire's contacts owe to props over to them (and forgets them).
void apply_prop_impulses(Tire& tire, RigidWorld& rigid);

}  // namespace tire

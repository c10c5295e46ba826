// The two ways a tire's positions are solved (SolverMethod), each its own unit behind this one
// interface, so that the substep (tire_solver.cpp) and the world's tick (world.cpp) read as the
// algorithm with either:
// - Gauss–Seidel (gauss_seidel_method.cpp): XPBD's constraint by constraint projection (Macklin
//   et al. 2016, "XPBD", eq. 18), contacts projected after the constraints, kinetic friction and
//   dashpot damping per particle in the velocity pass; tires meet tires by projecting the pairs'
//   treads (soft_contact.h).
// - global (global_method.cpp): one linear system a substep for all of a tire's constraints and
//   its surface contacts (global_solver.h), damping inside the solve (XPBD eq. 26), kinetic
//   friction on the tire's rigid motion, a prediction that carries the spin on as a rotation; tires
//   meet tires inside each other's systems by colour (tire_neighbours.h), Box2D steps with the
//   substeps, and a tick refines its substeps where the linearisation would not hold
//   (SolverConfig::refine_turn).
#pragma once

#include "tire/tire/solver_config.h"
#include "tire/tire/tire.h"

namespace tire {

struct SubstepContext;

class TireMethod {
 public:
  virtual ~TireMethod() = default;

  // What the world's tick does with the method.
  // Tires in contact are solved inside each other's systems (World::solve_by_tire_colour), not as
  // pairs after the iterations (World::solve_tire_pairs).
  virtual bool couples_tires_in_solve() const = 0;
  // Box2D steps once a substep rather than once a tick, so props meet the tires at the substeps'
  // rate (rigid_world.h).
  virtual bool steps_props_with_substeps() const = 0;
  // The tick may take more substeps than the config's (World::update_refinement).
  virtual bool refines_substeps() const = 0;
  // Its solves borrow scratch from the world's GlobalSolverPool (SubstepContext::global).
  virtual bool needs_solver_pool() const = 0;

  // What a tire's substep does with it (tire_solver.h), in the order the substep calls them.
  // Once a tick, before the substeps, with the tick's substep h.
  virtual void begin_tick(Tire& t, double h) const = 0;
  // In the prediction, before gravity and steering: what becomes of the velocities the last
  // substep left.
  virtual void carry_velocities(Tire& t, double h) const = 0;
  // One iteration of the position solve: the tire's constraints (with its surface contacts, where
  // the method solves them together). `last`: the substep's last iteration.
  virtual void solve_constraints(Tire& t, const SubstepContext& ctx, bool last) const = 0;
  // Then its contacts with obstacles and props, where the method projects them after the
  // constraints.
  virtual void solve_surface_contacts(Tire& t, const SubstepContext& ctx) const = 0;
  // The velocity pass, after v ← (x − xₙ)/h: kinetic friction against the surfaces and the
  // neighbours the tire touched (impulses owed to dynamic props recorded), then the material's
  // damping where the solve did not damp.
  virtual void apply_friction(Tire& t, const SubstepContext& ctx) const = 0;
  virtual void damp_material(Tire& t, double h) const = 0;
};

// Each method's one instance (it holds no state), and the one a config names.
const TireMethod& gauss_seidel_method();
const TireMethod& global_method();
inline const TireMethod& tire_method(SolverMethod method) {
  return method == SolverMethod::global ? global_method() : gauss_seidel_method();
}

}  // namespace tire

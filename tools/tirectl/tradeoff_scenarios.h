// The scenes `tirectl tradeoff` measures, built in code through the engine's façade (Simulation,
// TireSpec, PropSpec, Obstacle), and one measured run of a scene: what the tire did, tick by tick,
// with the peak strain, area error and energy that the error columns are made of.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tire/engine.h"

namespace tirectl {

// The solver settings one run is made with: what the sweep varies.
struct SolverSettings {
  int substeps = 8;
  int iterations = 1;
  int segments = 28;
  double tunnel_clamp = 1.0;
  tire::SolverMethod method = tire::SolverMethod::gauss_seidel;
  // The tire's material damping τ (s), not a solver setting: the same for every run of a sweep
  // (see tirectl tradeoff --material-damping).
  double material_damping = 1e-4;
};

struct TradeoffScenario {
  std::string name;
  std::string what;  // one line for the summary and docs/accuracy.md
  int ticks = 180;   // at dt = 1/60
  // Builds the scene into an empty world (gravity and solver already set); `base` is the tire to
  // use (TireSpec{} with the run's segments and material damping), placed by the scene.
  std::function<void(tire::Simulation&, const tire::TireSpec& base)> populate;
  // Height (m) the scene's potential energy is measured from: its lowest ground.
  double datum_y = 0.0;
  // For static scenes: how far the load has pushed the tire down (m), read from the world at the
  // end, and the load (N). Empty for dynamic scenes.
  std::function<double(const tire::Simulation&)> deflection;
  double load = 0.0;
  // Whether the scene has dynamic Box2D props. Box2D counts its TOI and GJK calls in unguarded
  // globals, so runs of such scenes are never measured at the same time.
  bool dynamic_props = false;
  // Whether its error bound helps choose the recommended settings. Not for bounces: no affordable
  // setting gets a bounce's restitution within the bounds (it converges at first order in h).
  bool decides = true;
  // The converged reference: substeps × iterations (checked against half the substeps).
  int ref_substeps = 2048;
  int ref_iterations = 2;
};

// rest, rest-soft, drop, slope, crush, impact.
const std::vector<TradeoffScenario>& tradeoff_scenarios();

// What one run of a scenario measured (the timing is taken separately).
struct RunMeasure {
  std::vector<tire::Vec2> centroid;  // the tire's centroid at tick 0, 1, ..., ticks
  double peak_strain = 0.0;          // max over ticks and distance constraints of |len/rest − 1|
  double area_error = 0.0;           // max over ticks of |area_ratio − pressure|
  double energy_start = 0.0;         // kinetic + gravitational of the tire and the dynamic props (J)
  double energy_end = 0.0;
  double deflection = 0.0;   // averaged over the last half second; NaN for dynamic scenes
  int resets = 0;            // the engine's divergence guard fired this often
  double us_per_step = 0.0;  // this run's mean cost of Simulation::step alone (one run, informative)
};

tire::Simulation build_world(const TradeoffScenario& scenario, const SolverSettings& settings);

// Steps the scenario and measures it after every tick.
RunMeasure measure_run(const TradeoffScenario& scenario, const SolverSettings& settings);

// Steps the scenario, timing each Simulation::step alone (steady clock, less the clock's own cost):
// µs of every tick, in order.
std::vector<double> time_run(const TradeoffScenario& scenario, const SolverSettings& settings);

// Kinetic + gravitational energy (J) of the tires and the dynamic props, potential from datum_y.
double mechanical_energy(const tire::Simulation& world, double datum_y);

}  // namespace tirectl

// The engine as a program that embeds it sees it: a Simulation made from a level file or built in
// code, stepped at its fixed tick, read through ids and views, and driven by commands that wake
// what they move. The solver, its contacts and Box2D stay inside the engine's libraries; these
// headers are all that `cmake --install` puts out (docs/engine.md, "Using the engine").
//
// One error style: what can fail returns its result with `errors`, each a line naming the file,
// the JSON path and what was expected, empty on success; a command the simulation may refuse
// returns false and changes nothing.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tire/level.h"
#include "tire/math/geometry.h"
#include "tire/replay/replay_file.h"
#include "tire/rigid/bodies.h"
#include "tire/script/script_status.h"
#include "tire/tire/solver_config.h"
#include "tire/tire/tire_spec.h"
#include "tire/world/debug_draw.h"
#include "tire/world/views.h"

namespace tire {

class LevelSession;
class Simulation;
struct SimulationInternals;  // the engine's own tests reach the world through it

struct SimulationLoad {
  std::unique_ptr<Simulation> simulation;  // null when `errors` is not empty
  std::vector<std::string> errors;
};

// What the solver did, read between ticks by tools that measure it (tirectl run).
struct SolverReport {
  // The last tick's substeps: the level's, or more where the global method refined the tick
  // (SolverConfig::refine_turn).
  int tick_substeps = 0;
  std::uint64_t failed_solves = 0;  // solves that failed (not finite) since the start
  IslandWork islands;               // the island solve's work since the start (tick_contacts.h)
  // A run budget (levels/README.md, "budgets") the level reached: when first, and what it dropped.
  struct Budget {
    std::string key;  // "budgets.tires", ...
    double limit = 0.0;
    std::uint64_t first_tick = 0;
    std::uint64_t dropped = 0;
  };
  std::vector<Budget> budgets_reached;
  // The last tick's contacts: particles touching a surface or another tire, summed over the tires,
  // and the broad phase's candidate pairs of tires.
  std::size_t touching_particles = 0;
  std::size_t tire_pairs = 0;
};

struct ReplayCheck {
  bool passed = false;
  std::string status;  // how the run ended: "running", "won" or "lost"
  std::uint64_t ticks = 0;
  std::vector<std::string> errors;  // the files' problems, or every expectation that broke
};

class Simulation {
 public:
  // An empty world with no script: status() stays running.
  Simulation(const SolverConfig& config, Vec2 gravity);
  // A level file (levels/README.md), validated, with its script: goal, triggers, time limit, bounds.
  static SimulationLoad load(const std::filesystem::path& level_file);
  // A level already read (tire/level.h), ready to play; it is kept for restarts.
  explicit Simulation(std::shared_ptr<const Level> level);
  ~Simulation();
  Simulation(Simulation&&) noexcept;
  Simulation& operator=(Simulation&&) noexcept;

  // Building, between ticks. The first tire, or one whose spec says player, becomes the player.
  TireId add_tire(const TireSpec& spec);
  // A tire added while the level runs (a click in the game): within the level's budgets
  // (levels/README.md, "budgets"); nullopt, and a warning, past them.
  std::optional<TireId> spawn_tire(const TireSpec& spec);
  PropId add_prop(const PropSpec& spec);
  void add_obstacle(const Obstacle& obstacle);
  bool remove_tire(TireId id);

  // One fixed tick of config().dt, `input` driving the player; then the level's script.
  void step(const TickInput& input = {});
  // One tick driven by a replay's inputs: the feed's inputs for this tick applied (as apply()
  // does), then the step.
  void step(InputFeed& feed);

  // Reading, between ticks.
  std::uint64_t tick() const;
  double time() const;  // s
  ScriptStatus status() const;
  EndReason end_reason() const;
  std::optional<std::uint64_t> end_tick() const;  // the tick the level ended on; nullopt while running
  // The box the player must stay in (levels/README.md, "bounds"); an open side is infinite.
  std::optional<Aabb> bounds() const;
  int respawns() const;  // times the player left the bounds and was put back at a checkpoint
  // The exact state's digest: the same binary and inputs give the same hash (docs/determinism.md).
  std::uint64_t state_hash() const;
  const SolverConfig& config() const;
  Vec2 gravity() const;
  std::optional<TireId> player() const;  // nullopt when the player is a vehicle (vehicle_at's `player`)
  std::vector<TireId> tires() const;     // in the order they were added
  std::optional<TireView> tire(TireId id) const;
  // The tires without building a list, for what reads them every frame: by index from 0, in the
  // order they were added (an index moves when a tire before it is removed); nullopt past the
  // last, so that a walk reads
  //   for (std::size_t i = 0; const std::optional<TireView> t = simulation.tire_at(i); ++i)
  std::size_t tire_count() const;
  std::optional<TireView> tire_at(std::size_t index) const;
  // The vehicles (levels/README.md, "Vehicles"), by index from 0 in the order they were added;
  // nullopt past the last, walked as tire_at is.
  std::size_t vehicle_count() const;
  std::optional<VehicleView> vehicle_at(std::size_t index) const;
  std::size_t prop_count() const;  // ids 0 .. prop_count() − 1
  std::optional<PropView> prop(PropId id) const;
  std::span<const Obstacle> obstacles() const;
  // The script's regions (empty without a script), which of them is the goal, the messages it has
  // on screen, the last checkpoint it set and whether it asked for the next level.
  std::span<const Region> regions() const;
  std::optional<std::size_t> goal() const;  // an index into regions()
  std::span<const ScriptMessage> messages() const;
  std::optional<Vec2> checkpoint() const;
  bool next_level_requested() const;
  std::size_t asleep_count() const;
  // Solves that failed (not finite) since the start; each is also a warning, and the tire is reset.
  std::uint64_t solver_failures() const;
  // The energy watch: the world's energy and what came in from outside (views.h).
  EnergyView energy() const;
  // The deepest a tread particle of one tire is inside another tire, asleep or not (views.h).
  TireOverlap deepest_overlap() const;
  // The most any of a tire's distance constraints (tread, rim, spokes) is stretched or squeezed
  // now: max |length / rest length − 1|; nullopt for no such tire.
  std::optional<double> tire_strain(TireId id) const;
  SolverReport solver_report() const;
  // The last tick's substeps alone (SolverReport::tick_substeps), cheap enough to read every tick.
  int tick_substeps() const;
  // What the world reported while stepping (a tire reset after diverging, a budget reached),
  // oldest first; take_warnings() hands them over and forgets them.
  std::vector<std::string> take_warnings();

  // Commands, between ticks; each wakes what it moves.
  // One replay input (tire/replay/replay_file.h) as replays play it: its steer and inflate set in
  // `held` and its jump for this tick (the caller steps with `held`), a spawn, grab, drag, release,
  // parameter or gravity applied now; a restart rebuilds the simulation from its level (one built
  // in code: an empty world with its solver settings and gravity).
  void apply(const ReplayInput& input, TickInput& held);
  bool apply_impulse(TireId id, Vec2 impulse);  // N·s, spread over the tire's particles
  // Puts a tire back where it was added, at rest and in the shape it was built with (a respawn).
  bool reset_tire(TireId id);
  // A row of the parameter table that may change while the world runs (levels/README.md):
  // "tires.<key>" on every tire, "player.<key>" on the player, "solver.<key>". False for a key not
  // in the table or a value its row does not accept.
  bool set_parameter(std::string_view key, double value);
  std::optional<double> parameter(std::string_view key) const;
  // Pulls one particle of a tire's tread (0 .. segments − 1) towards `target` every substep until
  // released (a mouse drag).
  bool grab(TireId id, std::uint32_t particle, Vec2 target);
  bool move_grab(TireId id, Vec2 target);
  bool release(TireId id);
  // The mouse's grab, as a replay's grab, drag and release inputs play it: the tire under `point`
  // (within `radius` of its tread) pulled by its nearest tread particle until released. Returns
  // the tire grabbed.
  std::optional<TireId> grab_at(Vec2 point, double radius);
  void move_grab(Vec2 target);
  void release_grab();
  // Sleeping on or off (SolverConfig::sleep), then every tire woken; wake_all() wakes them alone.
  // No sleeping island can tell whether it still rests after a change of the rules.
  void set_sleep(bool on);
  // Rolling resistance held in the position solve on or off (SolverConfig::rolling_hold), then
  // every tire woken, as set_sleep does.
  void set_rolling_hold(bool on);
  void wake_all();
  // Threads for scenes of many tires; the results are the same for any count.
  void set_threads(unsigned threads);
  // The threads a step of the current scene uses: one while it has too few tires to share them.
  unsigned threads() const;
  // The order of the step's phases over the tires (solver_config.h): the same bits either way;
  // what `tirectl bench --schedule` compares.
  void set_schedule(StepSchedule schedule);

  // Walks the tires, props and obstacles and calls `draw` back with what its flags ask for.
  void debug_draw(DebugDraw& draw) const;

 private:
  friend struct SimulationInternals;
  std::shared_ptr<const Level> level_;  // what a restart rebuilds
  std::unique_ptr<LevelSession> session_;
};

// One tire on a ground box stepped by the tire's substep alone, with no world around it: no level,
// no divergence guard, no Box2D stepping, no refinement of the tick, no sleeping, no threads. The
// floor under a tick's cost, which `tirectl bench`'s bare-tire scene times; not for playing.
class BareTire {
 public:
  BareTire(const SolverConfig& config, Vec2 gravity, const TireSpec& spec, const Obstacle& ground);
  ~BareTire();
  BareTire(BareTire&&) noexcept;
  BareTire& operator=(BareTire&&) noexcept;

  // One fixed tick of config().dt: the tire's substeps, steered and jumping as `input` says.
  void step(const TickInput& input = {});
  const SolverConfig& config() const;
  std::uint32_t segments() const;
  std::size_t particle_count() const;
  std::size_t touching_particles() const;  // after the last tick, as SolverReport counts them
  bool asleep() const;

 private:
  struct Parts;
  std::unique_ptr<Parts> parts_;
};

// Runs a replay file (docs/formats.md) headless against the level it names and checks every
// expectation, as `tirectl replay` does.
ReplayCheck check_replay(const std::filesystem::path& replay_file);

}  // namespace tire

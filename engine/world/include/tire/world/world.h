// The simulated world: tires, obstacles and props, and the fixed tick that advances them. Physics
// only: it knows nothing of windows, files, input devices or level scripts (a LevelSession,
// session/, adds those around it). The game, tirectl and the tests all drive it through step().
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tire/math/state_hash.h"
#include "tire/math/worker_pool.h"
#include "tire/rigid/rigid_world.h"
#include "tire/tire/global_solver.h"
#include "tire/tire/island_contacts.h"
#include "tire/tire/parameters.h"
#include "tire/tire/run_budgets.h"
#include "tire/tire/soft_contact.h"
#include "tire/tire/solver_config.h"
#include "tire/tire/tire.h"
#include "tire/tire/tire_neighbours.h"
#include "tire/tire/vehicle_joints.h"
#include "tire/world/sleep_islands.h"
#include "tire/world/views.h"

namespace tire {

class DebugDraw;
struct SubstepContext;  // tire/tire/tire_solver.h

class World {
 public:
  World(const SolverConfig& config, Vec2 gravity);
  ~World();
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;

  // Adds a tire between ticks. The first tire, or one whose spec says player, becomes the player.
  TireId add_tire(const TireSpec& spec);
  bool remove_tire(TireId id);
  void add_obstacle(const Obstacle& obstacle) { rigid_.add_obstacle(obstacle); }
  std::uint32_t add_prop(const PropSpec& spec);

  // Adds a vehicle between ticks (vehicle_joints.h): its chassis as a dynamic prop, its wheels as
  // tires on their axles. Only the global method solves its joints: nullopt, changing nothing,
  // under another, or for a spec without wheels or with more than VehicleJoints::kMaxWheels.
  std::optional<std::uint32_t> add_vehicle(const VehicleSpec& spec);
  // What the driver asks of vehicle v from the next tick on; false for no such vehicle.
  bool set_vehicle_control(std::uint32_t v, const VehicleControl& control);
  const VehicleJoints& vehicles() const { return vehicles_; }
  // The vehicle step()'s input drives (its steer the throttle, its lean and brake), if any: a level
  // whose player is a vehicle. No tire is the player from then on, unless its spec says player.
  // False for no such vehicle.
  bool set_player_vehicle(std::uint32_t v);
  // Puts vehicle v back at rest: its chassis' origin at `position` (its spawn position when
  // nullopt), upright (angle 0), its wheels rebuilt on their axle points in the shape they were built
  // with, the joints' forces and its control cleared (a respawn). False for no such vehicle.
  bool reset_vehicle(std::uint32_t v, std::optional<Vec2> position = std::nullopt);
  std::optional<std::uint32_t> player_vehicle() const { return player_vehicle_; }

  // The run's budgets (run_budgets.h): what spawn_tire, spawn_prop and the level session may add.
  void set_budgets(const RunBudgets& budgets) { budgets_ = budgets; }
  const RunBudgets& budgets() const { return budgets_; }
  // add_tire and add_prop for what arrives while the world runs (a script, a replay, the player):
  // nothing, and the budget reported (budget_reached), when it would pass the live tires, their
  // particles, the props or the spawns of this tick.
  std::optional<TireId> spawn_tire(const TireSpec& spec);
  std::optional<std::uint32_t> spawn_prop(const PropSpec& spec);
  // Counts one thing a budget (a "budgets.*" row) dropped at this tick; the first is reported.
  void budget_reached(ParamId budget);
  // Each budget reached so far, in the order first reached: when, and how much it dropped since.
  struct BudgetReached {
    ParamId budget;
    std::uint64_t first_tick;
    std::uint64_t dropped;
  };
  const std::vector<BudgetReached>& budgets_reached() const { return budgets_reached_; }

  // What scripts (and the game's tuning panel) can do between ticks. The commands on a tire return
  // false, changing nothing, when there is no such tire (or nothing grabbed to move or release).
  bool apply_impulse_to_tire(TireId id, Vec2 impulse);  // N·s, spread over the tire's particles
  // N·s on vehicle v as a whole: each of its bodies (chassis, wheels) changes velocity by
  // impulse / the vehicle's mass, so that its momentum changes by the impulse and nothing turns.
  // False for no such vehicle or a chassis that cannot move.
  bool apply_impulse_to_vehicle(std::uint32_t v, Vec2 impulse);
  // Sets a parameter of the table (tire/parameters.h) that may change while the world runs (a
  // script, replay or panel key): "tires.<key>" on every tire, and on every tire added after it
  // (spawned by a script, a replay or the player), "player.<key>" on the player's.
  // False, changing nothing, for a key not in the table, one only a level file sets, or a value
  // the table's row does not accept (outside its range, not finite, a fraction for an integer).
  bool set_parameter(std::string_view key, double value);
  // The value in force: "tires.<key>" reads the player's tire (or the first tire); nullopt for
  // an unknown key or when there is no such tire.
  std::optional<double> parameter(std::string_view key) const;
  // Puts a tire back at rest in its spawn shape, at `position` from now on if given.
  void reset_tire(TireId id, std::optional<Vec2> position = std::nullopt);

  // A grabbed particle of the tread (0 .. segments − 1) is pulled towards its target every substep
  // (tire_solver), until released.
  bool grab_particle(TireId id, std::uint32_t particle, Vec2 target);
  bool move_grabbed_particle(TireId id, Vec2 target);
  bool release_particle(TireId id);

  // Advances one fixed tick of config().dt, `input` driving the player.
  void step(const TickInput& input);

  // The order of the step's phases (default fused, the faster; plain for tests and benchmarks).
  // Results are identical for either.
  void set_schedule(StepSchedule schedule) { schedule_ = schedule; }
  StepSchedule schedule() const { return schedule_; }

  // Threads used for scenes of many tires (default: the hardware's). Results are identical for
  // any count: tires are solved independently, shared effects are applied in a fixed order.
  void set_threads(unsigned threads);
  unsigned threads() const { return threads_; }
  // Threads a step of the current scene actually uses: one below kParallelMinTires tires.
  unsigned threads_in_use() const;

  // Walks the tires, props and obstacles and calls `draw` back with what its flags ask for, as
  // b2World::DebugDraw does (debug_draw.h; defined in debug_draw.cpp). Between ticks.
  void debug_draw(DebugDraw& draw) const;

  const std::vector<Tire>& tires() const { return tires_; }
  // Tires asleep now (SolverConfig::sleep; sleep_islands.h).
  std::size_t asleep_count() const { return sleep_.asleep_count(); }
  // Wakes every sleeping tire and prop: what a change of the world's rules (live tuning, gravity)
  // does, as no island can tell whether it still rests under the new ones. A caller that changes
  // config() itself calls it; set_parameter and set_gravity do.
  void wake_all();
  // Wakes the island of tire `id` (a script's impulse, a grab, a reset do it themselves).
  void wake_tire(TireId id);
  std::size_t tire_pair_count() const { return tire_pairs_.size(); }    // broad-phase pairs, last tick
  std::span<const TirePair> tire_pairs() const { return tire_pairs_; }  // and which they are
  Tire* find_tire(TireId id);
  const Tire* player() const;
  // What a library's user reads (views.h): the tire or prop with this id, nullopt for none.
  std::optional<TireView> tire_view(TireId id) const;
  std::optional<PropView> prop_view(PropId id) const;
  TireView view_of(const Tire& t) const;  // tire_view's, and debug_draw's for each tire
  std::optional<TireId> player_id() const { return player_; }
  const RigidWorld& rigid() const { return rigid_; }
  RigidWorld& rigid() { return rigid_; }
  const SolverConfig& config() const { return config_; }
  SolverConfig& config() { return config_; }
  Vec2 gravity() const { return gravity_; }
  void set_gravity(Vec2 g);

  // The substeps the last tick took: the config's, times the global method's refinement
  // (SolverConfig::refine_turn).
  int tick_substeps() const { return tick_config_.substeps; }

  // The island solve's counts (island_contacts.h), since the start.
  const IslandContacts::Work& island_work() const { return island_.work(); }
  std::uint64_t tick() const { return tick_; }
  double time() const { return static_cast<double>(tick_) * config_.dt; }

  // Digest of the exact state: tick, every tire's id, particle positions, velocities and grounded
  // flags, every prop's transform, velocity and path state. Same binary and same inputs give the
  // same hash. hash_into adds the same to a digest a caller goes on with (LevelSession: the script).
  std::uint64_t state_hash() const;
  void hash_into(StateHash& h) const;

  // Warnings raised while stepping (a diverged tire that was reset, ...); the caller drains them.
  std::vector<std::string>& warnings() { return warnings_; }
  // Global solves that failed (a factorisation or solve not finite) since the world was made; each
  // is also a warning, and the tire's divergence guard resets it.
  std::uint64_t failed_solves() const { return failed_solves_; }
  // The energy brought into the world from outside since it was made (J), booked where it comes in:
  // the bodies added and removed, and every command between ticks that changes its energy (a tire
  // reset or pushed, gravity or a parameter set), at their energy (tire/world/energy.h); the work
  // of the tires' controls as they step (Tire::control_work: drive, jumps, inflating). The world's
  // energy less this rises only by what is not booked: a contact making energy, and the work of
  // kinematic props, grabs and what scripts do to props through rigid(). The energy watch reads
  // it (tirectl run).
  double energy_in() const { return energy_in_; }

 private:
  // The phases of a substep (world.cpp), each over every tire: the plain schedule, one by one.
  void predict(const SubstepContext& ctx);
  void solve_positions(const SubstepContext& ctx, int iteration);
  void update_velocities(const SubstepContext& ctx);
  // The same substeps in the fused schedule's sweeps.
  void fused_substeps(SubstepContext ctx);
  // Between sweeps: the reaction impulses the tires owe props, and the contacts between tires.
  void hand_over_impulses();
  void solve_tire_pairs();
  void solve_by_tire_colour(const SubstepContext& ctx, bool last);
  void note_failed_solves(const Tire& t);
  // The world's mechanical energy now (world_energy), for booking a command's change in energy_in_;
  // the commands themselves, unbooked, for the booked ones that call them.
  double energy_now() const;
  bool set_parameter_unbooked(std::string_view key, double value);
  void set_gravity_unbooked(Vec2 g);
  void guard_divergence(Tire& t);
  // After a tick: refine_ from how far the awake tires' solves turned their constraints.
  void update_refinement();
  // The broad phase between the awake tires into tire_pairs_; a sleeping island that an awake tire
  // may reach this tick is woken first (and its tires begin their tick).
  void find_tire_pairs();
  // Wakes the sleeping islands a moving prop may reach this tick, and those a removed prop held.
  void wake_for_props();
  std::uint32_t index_of(const Tire& t) const { return static_cast<std::uint32_t>(&t - tires_.data()); }
  void wake_island_of(const Tire& t) { sleep_.wake(tires_, index_of(t), rigid_); }
  void color_pairs();
  // Whether no two pairs of one parallel colour share a tire (a check for TIRE_ASSERT: it rebuilds
  // tire_colors_ from colored_pairs_, which leaves that scratch as color_pairs() left it).
  bool colors_share_no_tire();
  // fn(begin, end) over tire indices [0, n): in parallel when the scene is big enough.
  template <typename F>
  void for_tires(std::size_t n, F&& fn);
  // The pool for_tires runs on, made on first need; null when this scene runs on one thread.
  WorkerPool* parallel_pool();
  // fn(tire) for every tire, through for_tires, the next tire's data prefetched meanwhile.
  template <typename F>
  void sweep_tires(F&& fn);

  SolverConfig config_;
  SolverConfig tick_config_;  // this tick's: config_ with the refinement's substeps
  int refine_ = 1;
  Vec2 gravity_;
  RigidWorld rigid_;
  std::vector<Tire> tires_;
  TireTopologies topologies_;  // one per shape of tire added: what tires of a shape share
  TirePairFinder pair_finder_;
  std::vector<TirePair> tire_pairs_;  // this tick's candidate pairs
  // The pairs sorted into colours: no two pairs of a colour share a tire, so a colour's pairs are
  // solved in parallel; colours always go in the same order, whatever the thread count. The last
  // colour, kColors, takes the pairs of a tire with more neighbours than there are colours: its
  // pairs may share a tire, so it is solved in pair order on the calling thread.
  std::vector<TirePair> colored_pairs_;
  std::vector<std::uint32_t> color_begin_;  // colour c is colored_pairs_[color_begin_[c], color_begin_[c+1])
  std::vector<std::uint64_t> tire_colors_;  // per tire: colours its pairs use (scratch)
  std::vector<std::uint8_t> pair_color_;    // per pair (scratch)
  StepSchedule schedule_ = StepSchedule::fused;
  unsigned threads_ = 1;
  std::unique_ptr<WorkerPool> pool_;  // made on first need
  // The global method's scratch, one solver a thread, sized for the largest tire (add_tire).
  GlobalSolverPool global_;
  TireNeighbours neighbours_;  // the global method's contacts between tires
  IslandContacts island_;      // the islands whose contacts between tires are solved as one problem
  VehicleJoints vehicles_;     // the vehicles' axles, motors and brakes
  void solve_islands(const SubstepContext& ctx, bool last);
  SleepIslands sleep_;
  std::uint64_t seen_removals_ = 0;  // RigidWorld::removals() when wake_for_props last looked
  void reserve_global_solvers();
  std::optional<TireId> player_;
  std::optional<std::uint32_t> player_vehicle_;
  TireId next_id_ = 0;
  std::uint64_t tick_ = 0;
  std::vector<std::string> warnings_;
  std::uint64_t failed_solves_ = 0;
  double energy_in_ = 0.0;
  RunBudgets budgets_;
  std::vector<BudgetReached> budgets_reached_;
  // The "tires." keys set while the world runs, each once, in the order last set: add_tire gives
  // them to a new tire in that order (a later tires.mass_scale wins over an earlier tires.mass).
  struct TireSetting {
    ParamId id;
    double value;
  };
  std::array<TireSetting, kParameters.size()> tire_settings_{};
  std::size_t tire_setting_count_ = 0;
  void remember_tire_setting(ParamId id, double value);
  bool take_spawn();
  std::uint64_t spawn_tick_ = 0;  // the tick spawns_this_tick_ counts
  int spawns_this_tick_ = 0;
};

}  // namespace tire

// The simulated world: tires, static obstacles and the fixed tick that advances them. Knows
// nothing of windows, files or input devices: the game, tirectl and the tests all drive it
// through step().
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tire/rigid/rigid_world.h"
#include "tire/script/script_runner.h"
#include "tire/tire/soft_contact.h"
#include "tire/math/worker_pool.h"
#include "tire/tire/solver_config.h"
#include "tire/tire/tire.h"

namespace tire {

// The player's input for one tick.
struct TickInput {
  double steer = 0.0;  // [-1, 1]
  bool jump = false;
};

// How near a tread particle a mouse press must be to grab its tire (m).
inline constexpr double kGrabRadius = 0.3;

// A message a level script put on screen.
struct ScriptMessage {
  std::string text;
  std::uint64_t until_tick;  // shown while tick() < until_tick
};

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
  std::uint32_t add_prop(const PropSpec& spec) { return rigid_.add_prop(spec); }

  // Installs the level's script and runs its tick-0 update at once, so that level-start actions
  // apply before any physics. An empty spec leaves the world unscripted.
  void set_script(const ScriptSpec& spec);
  ScriptStatus status() const { return script_ ? script_->status() : ScriptStatus::running; }
  const ScriptRunner* script() const { return script_.get(); }
  const std::vector<ScriptMessage>& messages() const { return messages_; }
  std::optional<Vec2> checkpoint() const { return checkpoint_; }
  bool next_level_requested() const { return next_level_requested_; }

  // What scripts (and the game's tuning panel) can do between ticks.
  void apply_impulse_to_tire(TireId id, Vec2 impulse);  // N·s, spread over the tire's particles
  // "solver.substeps|iterations|damping", "player.<key>" or "tires.<key>" for the tire keys
  // friction, kinetic_friction, pressure, material_damping, rolling_resistance,
  // drive_acceleration, jump_speed, max_speed, mass, mass_scale (times the tire's spawn mass),
  // compliance.outer|inner|spoke|pressure. False, changing nothing, for an unknown key or a value
  // that is not finite.
  bool set_parameter(std::string_view key, double value);
  void show_message(std::string_view text, double seconds);
  void set_checkpoint(Vec2 position) { checkpoint_ = position; }
  void request_next_level() { next_level_requested_ = true; }
  // Puts the player back at the checkpoint (or its spawn point), at rest.
  void respawn_player();

  // Mouse grab: the tire under `point` (within `radius` of its tread) is pulled by its nearest
  // tread particle towards the target, until released. Returns the tire grabbed.
  std::optional<TireId> grab(Vec2 point, double radius);
  void move_grab(Vec2 target);
  void release_grab();

  // Advances one fixed tick of config().dt: `input` drives the player; then the script runs.
  void step(const TickInput& input);

  // Threads used for scenes of many tires (default: the hardware's). Results are identical for
  // any count: tires are solved independently, shared effects are applied in a fixed order.
  void set_threads(unsigned threads);
  unsigned threads() const { return threads_; }
  // Threads a step of the current scene actually uses: one below kParallelMinTires tires.
  unsigned threads_in_use() const;

  const std::vector<Tire>& tires() const { return tires_; }
  std::size_t tire_pair_count() const { return tire_pairs_.size(); }  // broad-phase pairs, last tick
  Tire* find_tire(TireId id);
  const Tire* player() const;
  const RigidWorld& rigid() const { return rigid_; }
  RigidWorld& rigid() { return rigid_; }
  const SolverConfig& config() const { return config_; }
  SolverConfig& config() { return config_; }
  Vec2 gravity() const { return gravity_; }
  void set_gravity(Vec2 g) {
    gravity_ = g;
    rigid_.set_gravity(g);
  }

  std::uint64_t tick() const { return tick_; }
  double time() const { return static_cast<double>(tick_) * config_.dt; }

  // Digest of the exact state: tick, every tire's id, particle positions, velocities and grounded
  // flags, every prop's transform, velocity and path state, and the script's state. Same binary
  // and same inputs give the same hash.
  std::uint64_t state_hash() const;

  // Warnings raised while stepping (a diverged tire that was reset, ...); the caller drains them.
  std::vector<std::string>& warnings() { return warnings_; }

 private:
  void guard_divergence(Tire& t);
  void color_pairs();
  // Whether no two pairs of one parallel colour share a tire (a check for TIRE_ASSERT: it rebuilds
  // tire_colors_ from colored_pairs_, which leaves that scratch as color_pairs() left it).
  bool colors_share_no_tire();
  // fn(begin, end) over tire indices [0, n): in parallel when the scene is big enough.
  template <typename F>
  void for_tires(std::size_t n, F&& fn);
  // fn(tire) for every tire, through for_tires, the next tire's data prefetched meanwhile.
  template <typename F>
  void sweep_tires(F&& fn);

  SolverConfig config_;
  Vec2 gravity_;
  RigidWorld rigid_;
  std::vector<Tire> tires_;
  TirePairFinder pair_finder_;
  std::vector<TirePair> tire_pairs_;     // this tick's candidate pairs
  // The pairs sorted into colours: no two pairs of a colour share a tire, so a colour's pairs are
  // solved in parallel; colours always go in the same order, whatever the thread count. The last
  // colour, kColors, takes the pairs of a tire with more neighbours than there are colours: its
  // pairs may share a tire, so it is solved in pair order on the calling thread.
  std::vector<TirePair> colored_pairs_;
  std::vector<std::uint32_t> color_begin_;  // colour c is colored_pairs_[color_begin_[c], color_begin_[c+1])
  std::vector<std::uint64_t> tire_colors_;  // per tire: colours its pairs use (scratch)
  std::vector<std::uint8_t> pair_color_;    // per pair (scratch)
  unsigned threads_ = 1;
  std::unique_ptr<WorkerPool> pool_;  // made on first need
  std::optional<TireId> player_;
  TireId next_id_ = 0;
  std::uint64_t tick_ = 0;
  std::vector<std::string> warnings_;
  std::unique_ptr<ScriptRunner> script_;
  std::vector<ScriptMessage> messages_;
  std::optional<Vec2> checkpoint_;
  bool next_level_requested_ = false;
  std::optional<TireId> grabbed_;
};

}  // namespace tire

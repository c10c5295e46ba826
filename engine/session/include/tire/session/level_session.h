// A level being played: the World (physics) and what the level's script adds around it — the
// script itself, its messages, the checkpoint, the request for the next level — the level's bounds
// and how it ended, and the mouse grab.
// The game, tirectl and replays play levels through this; tests and tools that only need physics
// drive a World directly.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tire/math/geometry.h"
#include "tire/script/script_runner.h"
#include "tire/world/world.h"

namespace tire {

class LevelSession {
 public:
  LevelSession(const SolverConfig& config, Vec2 gravity);
  ~LevelSession();
  LevelSession(LevelSession&&) noexcept;
  LevelSession& operator=(LevelSession&&) noexcept;

  World& world() { return world_; }
  const World& world() const { return world_; }

  // Installs the level's script and runs its tick-0 update at once, so that level-start actions
  // apply before any physics. An empty spec leaves the session unscripted.
  void set_script(const ScriptSpec& spec);
  const ScriptRunner* script() const { return script_.get(); }

  // The box the player must stay in (levels/README.md "bounds"). After each tick's script, a
  // player whose centroid is outside it is put back (respawn_player) when the level has
  // checkpoints — a checkpoint action anywhere in its script — and otherwise loses the level
  // (EndReason::out_of_bounds). Without bounds, nothing is checked.
  void set_bounds(const Aabb& box) { bounds_ = box; }
  const std::optional<Aabb>& bounds() const { return bounds_; }
  // Whether leaving the bounds respawns rather than loses.
  bool respawns_out_of_bounds() const { return has_checkpoints_; }
  int respawns() const { return respawns_; }  // times the player left the bounds and was put back

  // Running, won or lost; why it ended and on which tick (nullopt while running).
  ScriptStatus status() const;
  EndReason end_reason() const;
  std::optional<std::uint64_t> end_tick() const { return end_tick_; }

  // One fixed tick: the world steps with `input` driving the player, expired messages go, the
  // script runs, then the bounds are checked.
  void step(const TickInput& input);

  // What the script (and the game) can do between ticks, beyond the world's own API.
  // A message past the budgets of messages on screen or of their text is dropped (reported as the
  // world reports its budgets, World::budgets_reached).
  void show_message(std::string_view text, double seconds);
  // One trigger firing this tick: false, the budget reported, once the tick has had
  // budgets.firings_per_tick.
  bool take_firing();
  const std::vector<ScriptMessage>& messages() const { return messages_; }
  void set_checkpoint(Vec2 position) { checkpoint_ = position; }
  std::optional<Vec2> checkpoint() const { return checkpoint_; }
  void request_next_level() { next_level_requested_ = true; }
  bool next_level_requested() const { return next_level_requested_; }
  // Puts the player back at the checkpoint (or its spawn point), at rest: a player vehicle upright,
  // its wheels on their axles (World::reset_vehicle).
  void respawn_player();
  // Where the player is: a player vehicle's chassis' centre of mass, else the player tire's centroid;
  // nullopt with neither. What the goal, region crossings, the bounds and cameras follow.
  std::optional<Vec2> player_position() const;

  // Vehicle v's driver's head (levels/README.md, "Vehicles"): after each tick, the player vehicle's
  // head touching an obstacle or a static or kinematic prop loses the level (EndReason::head_hit).
  void set_vehicle_head(std::uint32_t v, const VehicleHead& head);
  const std::optional<VehicleHead>& vehicle_head(std::uint32_t v) const;
  // The head's circle in the world now: its centre, and its radius in `radius`; nullopt for none.
  std::optional<Vec2> vehicle_head_center(std::uint32_t v) const;

  // Mouse grab: the tire under `point` (within `radius` of its tread) is pulled by its nearest
  // tread particle towards the target, until released. Returns the tire grabbed.
  std::optional<TireId> grab(Vec2 point, double radius);
  void move_grab(Vec2 target);
  void release_grab();

  // Digest of the exact state: the world's (World::hash_into), then the script's.
  std::uint64_t state_hash() const;

 private:
  void check_bounds();  // after the script: the player outside the bounds respawns or loses
  void check_head();    // then: the player vehicle's head on the ground loses
  void note_end();      // the tick the level ended on, once

  World world_;
  std::unique_ptr<ScriptRunner> script_;
  std::vector<ScriptMessage> messages_;
  std::optional<Vec2> checkpoint_;
  std::optional<Aabb> bounds_;
  bool has_checkpoints_ = false;
  bool out_of_bounds_ = false;  // the level was lost by leaving the bounds
  bool head_hit_ = false;       // the level was lost by the driver's head touching the ground
  std::vector<std::optional<VehicleHead>> heads_;           // by vehicle
  std::vector<std::uint32_t> near_obstacles_, near_props_;  // check_head's query, kept to not allocate
  int respawns_ = 0;
  std::optional<std::uint64_t> end_tick_;
  bool next_level_requested_ = false;
  std::optional<TireId> grabbed_;
  std::size_t message_bytes_ = 0;  // of messages_' texts together
  std::uint64_t firing_tick_ = 0;  // the tick firings_ counts
  int firings_ = 0;
};

}  // namespace tire

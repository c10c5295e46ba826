// A level being played: the World (physics) and what the level's script adds around it — the
// script itself, its messages, the checkpoint, the request for the next level — and the mouse grab.
// The game, tirectl and replays play levels through this; tests and tools that only need physics
// drive a World directly.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tire/script/script_runner.h"
#include "tire/world/world.h"

namespace tire {

// How near a tread particle a mouse press must be to grab its tire (m).
inline constexpr double kGrabRadius = 0.3;

// A message a level script put on screen.
struct ScriptMessage {
  std::string text;
  std::uint64_t until_tick;  // shown while world().tick() < until_tick
};

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
  ScriptStatus status() const { return script_ ? script_->status() : ScriptStatus::running; }

  // One fixed tick: the world steps with `input` driving the player, expired messages go, then
  // the script runs.
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
  // Puts the player back at the checkpoint (or its spawn point), at rest.
  void respawn_player();

  // Mouse grab: the tire under `point` (within `radius` of its tread) is pulled by its nearest
  // tread particle towards the target, until released. Returns the tire grabbed.
  std::optional<TireId> grab(Vec2 point, double radius);
  void move_grab(Vec2 target);
  void release_grab();

  // Digest of the exact state: the world's (World::hash_into), then the script's.
  std::uint64_t state_hash() const;

 private:
  World world_;
  std::unique_ptr<ScriptRunner> script_;
  std::vector<ScriptMessage> messages_;
  std::optional<Vec2> checkpoint_;
  bool next_level_requested_ = false;
  std::optional<TireId> grabbed_;
  std::size_t message_bytes_ = 0;  // of messages_' texts together
  std::uint64_t firing_tick_ = 0;  // the tick firings_ counts
  int firings_ = 0;
};

}  // namespace tire

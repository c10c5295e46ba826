// Replays (format "tire-replay/1", docs/formats.md): the level a session ran, every input that
// reached the world, tick by tick, and what the run must come to. Read, written, recorded, fed back
// into a simulation (Simulation::step(InputFeed&), tire/engine.h) and checked. The game records
// them, tirectl records and checks them, and the replay suite runs them in ctest.
//
// Inputs are changes: steer, inflate, lean and brake hold until the next of theirs; jump, spawn, grab, drag,
// release, set, gravity and restart act once, at their tick, before that tick's step. Several inputs may
// share a tick; they apply in file order, and each acts. So a tick holds at most one steer, inflate, lean,
// brake and jump (a second steer would replace the first unseen, a second jump would do nothing),
// and no steer before a restart on the same tick (the restart drops it): the reader refuses those.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tire/math/geometry.h"
#include "tire/script/script_status.h"
#include "tire/world/views.h"

namespace tire {

struct Level;  // a level read and validated (tire/level.h)

inline constexpr const char* kReplayFormat = "tire-replay/1";

struct ReplayInput {
  std::uint64_t tick = 0;
  std::optional<double> steer;  // [-1, 1], holds
  bool jump = false;
  std::optional<double> inflate;       // [-1, 1], holds: +1 inflates the player, −1 deflates it
  std::optional<double> lean;          // [-1, 1], holds: a player vehicle's lean (TickInput::lean)
  std::optional<bool> brake;           // holds: a player vehicle's brakes on (true) or off (false)
  std::optional<Vec2> spawn;           // a default tire at this point (a mouse click)
  std::optional<Vec2> grab;            // grab the tire at this point (mouse press)
  double grab_radius = kGrabRadius;    // how near a tread particle the press must be (m)
  std::optional<Vec2> drag;            // move the grab (mouse drag)
  bool release = false;                // let go (mouse release)
  std::optional<std::string> set_key;  // a tuning change: Simulation::set_parameter(key, value)
  double set_value = 0.0;
  std::optional<Vec2> gravity;  // a tuning change of gravity
  bool restart = false;         // the level restarted (R)
};

struct ReplayCheckpoint {
  std::uint64_t tick = 0;  // the state after this many ticks
  std::string hash;
};

// A tolerance instead of an exact hash: tire `tire` (index in the world's list) has its centroid
// inside [min, max] after `tick` ticks.
struct ReplayBox {
  std::uint64_t tick = 0;
  std::size_t tire = 0;
  Vec2 min;
  Vec2 max;
};

struct ReplayExpect {
  std::optional<std::string> status;  // running | won | lost, at the end
  std::vector<ReplayCheckpoint> checkpoints;
  std::optional<std::string> hash;  // after the last tick
  std::vector<ReplayBox> boxes;
};

struct Replay {
  std::string level;         // path, relative to the replay file's folder (never absolute)
  std::string level_sha256;  // of the level file's bytes when recorded
  std::uint64_t ticks = 0;
  std::vector<ReplayInput> inputs;
  ReplayExpect expect;
};

struct ReplayLimits {
  static constexpr std::uintmax_t max_file_bytes = 256ull << 20;
  static constexpr std::uint64_t max_ticks = 100'000'000;  // over 19 days at 60 Hz
  static constexpr std::size_t max_inputs = 10'000'000;
  static constexpr std::size_t max_json_values = 2'500'000;
};

// Keys a replay's `set` input may tune: the rows of the parameter table that a replay may set
// (levels/README.md), a tire row also as "player.<key>".
bool is_tunable_key(std::string_view key);

struct ReplayLoad {
  std::optional<Replay> replay;
  std::vector<std::string> errors;  // "FILE: /json/path: what was expected, got what"
};
ReplayLoad load_replay_file(const std::filesystem::path& file);
// The same, from text already in memory; `file` only names it in messages.
ReplayLoad load_replay_text(const std::string& text, const std::string& file);

std::string replay_to_json(const Replay& replay);

// The level a replay names (`replay.level`, from the replay file's folder), read by the level
// reader. Nothing is said of the file until it has loaded as a level: one that does not (any file
// a replay may name, /etc/passwd by a relative path) gets the loader's errors, under the replay's
// /level and without the parser's excerpt of its bytes, and no digest.
struct ReplayLevel {
  std::filesystem::path path;          // the replay's folder / replay.level
  std::shared_ptr<const Level> level;  // null when `errors` is not empty
  std::string sha256;                  // of the level file's bytes, when it loaded
  std::vector<std::string> errors;     // "REPLAY: /level: ..."
};
ReplayLevel load_replay_level(const std::filesystem::path& replay_file, const Replay& replay);
// Why the replay cannot be checked against its level as it is now: the level file changed since
// it was recorded (its SHA-256 differs). Nothing when it is the level the replay was made on.
std::optional<std::string> level_changed(const ReplayLevel& level, const Replay& replay);

// What a replay run came to.
struct ReplayOutcome {
  std::string status;
  std::string hash;
  std::vector<ReplayCheckpoint> checkpoints;          // actual hashes at the expected checkpoint ticks
  std::optional<std::uint64_t> first_divergent_tick;  // first checkpoint whose hash differs
  std::optional<std::uint64_t> last_matching_tick;    // the one before it that agreed (or 0: the start)
  std::vector<std::string> failures;                  // every expectation that broke, in words
  std::size_t box_checks = 0;                         // centroid boxes looked at (once each at most)
};

// Runs the replay's ticks on `level` and checks every expectation. `after_tick`, when given, is
// called with the ticks done after each one (for a progress display; it cannot change the run).
ReplayOutcome run_replay(const Replay& replay, const Level& level,
                         const std::function<void(std::uint64_t)>& after_tick = {});

// Records a run: call input() for each input as it happens and after_step() with the state hash
// after each step; finish() gives the replay with its expectations (status, final hash, a
// checkpoint every `checkpoint_every` ticks).
class ReplayRecorder {
 public:
  ReplayRecorder(std::string level_path, std::string level_sha256, std::uint64_t checkpoint_every = 30);
  void input(const ReplayInput& in) { replay_.inputs.push_back(in); }
  void after_step(std::uint64_t state_hash);
  Replay finish(ScriptStatus status, std::uint64_t state_hash) const;
  std::uint64_t ticks() const { return replay_.ticks; }

 private:
  Replay replay_;
  std::uint64_t checkpoint_every_;
};

// A run's inputs (sorted by tick) played one tick at a time: before each step, the inputs written
// for that tick of the run (counted from its start, across restarts) are applied, and `recorder`,
// when given, records each as it is applied. Simulation::step(InputFeed&) plays one so, as
// run_replay, tirectl run and tirectl course do.
class InputFeed {
 public:
  explicit InputFeed(std::span<const ReplayInput> inputs, ReplayRecorder* recorder = nullptr)
      : inputs_(inputs), recorder_(recorder) {}
  // Calls apply(input, held) for each input of the next tick, in file order, and returns the
  // tick's player input: steer, inflate, lean and brake hold from tick to tick; jump is for its
  // tick only.
  template <typename Apply>
  const TickInput& next_tick(Apply&& apply) {
    held_.jump = false;
    for (; next_ < inputs_.size() && inputs_[next_].tick == tick_; ++next_) {
      if (recorder_) recorder_->input(inputs_[next_]);
      apply(inputs_[next_], held_);
    }
    ++tick_;
    return held_;
  }

 private:
  std::span<const ReplayInput> inputs_;
  ReplayRecorder* recorder_;
  std::size_t next_ = 0;
  std::uint64_t tick_ = 0;
  TickInput held_;
};

}  // namespace tire

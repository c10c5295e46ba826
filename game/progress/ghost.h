// The ghost of the best run: a replay (the existing tire-replay/1 format) played in a Simulation of
// its own, stepped in lockstep with the player's (one tick of the ghost for each tick of the
// player's, from the replay's inputs) and never touching it. Only its player tire is drawn,
// translucent (ghost_draw.h). Replays are bit-exact, so the ghost is exactly the run that was
// recorded.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "play/session_recorder.h"
#include "tire/engine.h"

namespace game {

class Ghost {
 public:
  // Loads the ghost of `level` (whose file's bytes hash to `level_sha256`) from `file`. Returns ""
  // when loaded, or why not: the file is unreadable, or the level changed since it was recorded
  // (then the ghost is dropped). A missing file is no ghost and no message.
  std::string load(const std::filesystem::path& file, std::shared_ptr<const tire::Level> level,
                   const std::string& level_sha256);
  void clear();
  bool loaded() const { return simulation_ != nullptr; }
  const std::filesystem::path& file() const { return file_; }

  // Steps the ghost until it has run `tick` ticks (or its replay is over); a tick behind it (the
  // player restarted) starts it again from the beginning.
  void sync(std::uint64_t tick);
  std::uint64_t tick() const { return tick_; }
  std::uint64_t ticks() const { return replay_.ticks; }

  // The ghost's player tire, or nullopt.
  std::optional<tire::TireView> player() const;
  // Its particles blended between the previous tick and the current one (as GameSession does).
  void interpolated_positions(double alpha, std::vector<tire::Vec2>& out) const;

  bool visible = true;  // G toggles

 private:
  void restart();

  tire::Replay replay_;
  std::shared_ptr<const tire::Level> level_;
  std::unique_ptr<tire::Simulation> simulation_;
  std::filesystem::path file_;
  std::uint64_t tick_ = 0;
  std::size_t next_input_ = 0;
  tire::TickInput held_;              // the replay's steer and inflate, held between its inputs
  std::vector<tire::Vec2> previous_;  // the player tire's particles a tick ago
};

}  // namespace game

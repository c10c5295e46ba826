// The ghost of the best run: a replay (the existing tire-replay/1 format) played in a Simulation of
// its own, stepped in lockstep with the player's (one tick of the ghost for each tick of the
// player's, from the replay's inputs) and never touching it. Only its player is drawn, translucent
// (ghost_draw.h): the player tire, or in a level whose player is a vehicle, that vehicle. Replays are
// bit-exact, so the ghost is exactly the run that was recorded.
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

  // The ghost's player tire, or nullopt (none, or the player is a vehicle).
  std::optional<tire::TireView> player() const;
  // Its particles blended between the previous tick and the current one (as GameSession does).
  void interpolated_positions(double alpha, std::vector<tire::Vec2>& out) const;

  // The ghost's player vehicle, or nullopt (none, or the player is a tire).
  std::optional<tire::VehicleView> vehicle() const;
  // Its chassis' shape (a PropView) and its pose blended between the last two ticks.
  std::optional<tire::PropView> chassis() const;
  tire::Pose interpolated_chassis(double alpha) const;
  // Wheel `w`'s particles blended between the last two ticks.
  void interpolated_wheel(std::size_t w, double alpha, std::vector<tire::Vec2>& out) const;

  // Where the ghost's player is: the tire's hub or the vehicle's centre of mass.
  std::optional<tire::Vec2> position() const;

  bool visible = true;  // G toggles

 private:
  void restart();
  // Keeps what the next tick's drawing blends from: the player tire's or the wheels' particles and
  // the chassis' pose.
  void remember();

  tire::Replay replay_;
  std::shared_ptr<const tire::Level> level_;
  std::unique_ptr<tire::Simulation> simulation_;
  std::filesystem::path file_;
  std::uint64_t tick_ = 0;
  std::size_t next_input_ = 0;
  tire::TickInput held_;              // the replay's steer and inflate, held between its inputs
  std::vector<tire::Vec2> previous_;  // the player tire's (or the wheels' in turn) particles a tick ago
  std::optional<tire::Pose> previous_chassis_;  // a player vehicle's chassis a tick ago
};

}  // namespace game

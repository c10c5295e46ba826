// One level being played: the engine's Simulation (world and script), the level it was built
// from, the tuning in force and what rendering needs to interpolate between ticks. Every input
// reaches the simulation through here (session_input.h): events are queued, then applied between
// ticks by flush(); step() flushes and then calls Simulation::step, the same fixed tick tirectl
// runs.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "input/session_input.h"
#include "play/tuning.h"
#include "tire/engine.h"

namespace game {

class GameSession {
 public:
  // A fresh simulation of `level`, at once (no observer call: use a LoadLevelEvent for that).
  void start(std::string path, std::shared_ptr<const tire::Level> level);

  // Queues an event for the next flush. Consecutive MoveGrabEvents collapse into the last one.
  void queue(SessionEvent event);
  // Applies the queued events now (between ticks) and tells the observer.
  void flush();
  // flush(), remember the positions for interpolation, then Simulation::step(input).
  void step(const tire::TickInput& input);

  void set_observer(SessionObserver* observer) { observer_ = observer; }

  bool loaded() const { return simulation_ != nullptr; }
  tire::Simulation& simulation() { return *simulation_; }
  const tire::Simulation& simulation() const { return *simulation_; }
  const tire::LevelInfo& level() const { return info_; }
  const std::shared_ptr<const tire::Level>& level_ptr() const { return level_; }
  const std::string& path() const { return path_; }
  const Tuning& tuning() const { return tuning_; }
  // Whether the tuning panel changed the world since the level was (re)started: such a run is not
  // the level as written, and its time does not count as a best time.
  bool tuned() const { return tuned_; }
  // Counts level loads: a change tells the app to reset its camera and grab state.
  std::uint64_t generation() const { return generation_; }

  // Particle positions blended between the previous tick and the current one: alpha 0 is the
  // previous tick, 1 the current. A tire with no previous tick (just spawned) is drawn as it is.
  void interpolated_positions(const tire::TireView& tire, double alpha, std::vector<tire::Vec2>& out) const;
  // The same for tire `id`, whose particles are at `now`.
  void interpolated_positions(tire::TireId id, std::span<const tire::Vec2> now, double alpha,
                              std::vector<tire::Vec2>& out) const;
  tire::Vec2 interpolated_centroid(const tire::TireView& tire, double alpha) const;
  // A live prop's pose, blended the same way.
  tire::Pose interpolated_pose(std::uint32_t prop, double alpha) const;

  // Warnings the simulation raised since the last call.
  std::vector<std::string> take_warnings();

 private:
  void apply(const SessionEvent& event);

  std::unique_ptr<tire::Simulation> simulation_;
  std::shared_ptr<const tire::Level> level_;
  tire::LevelInfo info_;
  std::string path_;
  Tuning tuning_;
  bool tuned_ = false;
  std::uint64_t generation_ = 0;
  std::vector<SessionEvent> queue_;
  SessionObserver* observer_ = nullptr;
  std::unordered_map<tire::TireId, std::vector<tire::Vec2>> previous_x_;
  std::vector<tire::Pose> previous_poses_;
};

}  // namespace game

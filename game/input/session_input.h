// Everything that reaches the simulation from the player, in one place: per tick a TickInput
// (steer, jump) and, between ticks, a list of events (spawn a tire, grab/move/release, a tuning
// change, a level (re)load). GameSession applies them, always between two steps, and reports
// each batch to a SessionObserver, so a replay recorder can be attached there and see exactly what
// the simulation saw, tick by tick. Nothing here knows about SDL.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "tire/engine.h"

namespace game {

// A left click on empty space: a default TireSpec (not the player) with its hub at `position`.
struct SpawnTireEvent {
  tire::Vec2 position;
};
// A press on a tire: Simulation::grab_at(point, radius).
struct GrabEvent {
  tire::Vec2 point;
  double radius = 0.0;  // m
};
// Dragging: Simulation::move_grab(target).
struct MoveGrabEvent {
  tire::Vec2 target;
};
// Button released: Simulation::release_grab().
struct ReleaseGrabEvent {};
// A tuning change, key = value. Keys are the parameter table's rows the panel may set
// ("tires.compliance.outer", "tires.pressure", "tires.mass_scale", "solver.substeps", "gravity.x",
// ...; tire/parameters.h), applied through Simulation::set_parameter; "tires.friction" sets the
// static and the kinetic friction together; "solver.sleep" and "solver.rolling_hold" (1 or 0) turn
// sleeping and the rolling hold on or off.
// Applying one wakes every sleeping tire. See tuning.h.
struct TuneEvent {
  std::string key;
  double value = 0.0;
};
// Restart, level change or hot reload: a fresh Simulation of `level` (already validated).
struct LoadLevelEvent {
  std::string path;
  std::shared_ptr<const tire::Level> level;
};

using SessionEvent =
    std::variant<SpawnTireEvent, GrabEvent, MoveGrabEvent, ReleaseGrabEvent, TuneEvent, LoadLevelEvent>;

// Watches every input as it is applied: the hook for a replay recorder.
class SessionObserver {
 public:
  virtual ~SessionObserver() = default;
  // `events` were applied just now, before the step of tick `tick` (the simulation's tick() at the
  // time; a LoadLevelEvent resets it to 0 for the events after it).
  virtual void on_events(std::uint64_t tick, const std::vector<SessionEvent>& events) = 0;
  // Simulation::step(input) is about to advance it from tick `tick` to `tick + 1`.
  virtual void on_step(std::uint64_t tick, const tire::TickInput& input) = 0;
  // ... and has just done so.
  virtual void on_stepped(const tire::Simulation& simulation) = 0;
};

}  // namespace game

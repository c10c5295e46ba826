// What a Simulation keeps inside, for the engine's and the game's tests only: they measure the
// world and the level session behind the façade. Not installed; tools/check-facade keeps the game,
// the tools and the examples off it.
#pragma once

#include "tire/engine.h"
#include "tire/session/level_session.h"

namespace tire {

struct SimulationInternals {
  static LevelSession& session(Simulation& s) { return *s.session_; }
  static const LevelSession& session(const Simulation& s) { return *s.session_; }
  static World& world(Simulation& s) { return s.session_->world(); }
  static const World& world(const Simulation& s) { return s.session_->world(); }
};

}  // namespace tire

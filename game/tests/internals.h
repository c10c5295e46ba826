// The engine's insides behind the game's Simulation, which the game's tests measure (they may
// include what the game itself may not: tools/check-facade).
#pragma once

#include "tire/engine.h"
#include "tire/io/level.h"
#include "tire/session/level_session.h"
#include "tire/simulation_internals.h"
#include "tire/world/world.h"

namespace game {

inline tire::World& world_of(tire::Simulation& s) { return tire::SimulationInternals::world(s); }
inline const tire::World& world_of(const tire::Simulation& s) { return tire::SimulationInternals::world(s); }

// A GameSession's.
template <typename Session>
requires requires(Session& s) { s.simulation(); }
decltype(auto) world_of(Session& s) { return world_of(s.simulation()); }

}  // namespace game

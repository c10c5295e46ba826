// Worlds the tire tests share.
#pragma once

#include <string>

#include "tire/io/level.h"
#include "tire/session/level_session.h"

namespace tire::test {

inline std::string source_path(const std::string& relative) {
  return std::string(TIRE_SOURCE_DIR) + "/" + relative;
}

inline TireSpec tire_at(Vec2 position, bool player = false) {
  TireSpec spec;
  spec.position = position;
  spec.player = player;
  return spec;
}

// The default level, with --set style overrides.
inline Level default_level(const std::vector<std::string>& overrides = {}) {
  LevelLoad load = load_level_file(source_path("levels/01-first-roll.json"), overrides);
  if (!load.level) throw std::runtime_error(load.errors.front());
  return *load.level;
}

// A world with one tire on flat ground (the top of the ground box is y = 0).
inline World flat_world(const TireSpec& spec, const SolverConfig& config = {}, Vec2 gravity = {0, -9.81}) {
  World world(config, gravity);
  world.add_obstacle({{{-1000, -10}, {1000, 0}}});
  world.add_tire(spec);
  return world;
}

inline void run(World& world, int ticks, TickInput input = {}) {
  for (int i = 0; i < ticks; ++i) world.step(input);
}

inline void run(LevelSession& session, int ticks, TickInput input = {}) {
  for (int i = 0; i < ticks; ++i) session.step(input);
}

}  // namespace tire::test

// Worlds the tire tests share.
#pragma once

#include <string>

#include "tire/io/level.h"
#include "tire/session/level_session.h"
#include "tire/tire/parameters.h"
#include "tire/tire/tire_solver.h"

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

// One tick of a tire on its own, by hand: begin_tick, then substep() for each substep, between the
// rigid world's begin_tick and end_tick. tests/test_step_schedule.cpp shows a World of one tire
// steps it to the same bits.
inline void tick_lone_tire(Tire& t, RigidWorld& rigid, const SolverConfig& config, Vec2 gravity,
                           const TickInput& input) {
  t.control.steer = input.steer;
  t.control.jump = input.jump;
  rigid.begin_tick(config.dt);
  begin_tick(t, config, rigid);
  const double h = config.dt / config.substeps;
  GlobalSolverPool global;  // the global method's solver (a test may allocate)
  global.reserve(1, t.n);
  SubstepContext ctx{h, 0.0, gravity, &config, &rigid, false, &global};
  for (int s = 0; s < config.substeps; ++s) {
    ctx.time = s * h;
    substep(t, ctx, rigid);
  }
  rigid.end_tick(config.dt);
}

// Steps the world until every tire sleeps, for at most `most` ticks: the ticks it took.
inline int run_until_asleep(World& world, int most) {
  int ticks = 0;
  while (ticks < most && world.asleep_count() < world.tires().size()) {
    world.step({});
    ++ticks;
  }
  return ticks;
}

// 60 tires dropped in rows of five into a 6 m box (docs/at-rest.md's pile of 60), in a material
// (the default's if null).
inline World pile_of_60(const SolverConfig& config, const Material* material = nullptr) {
  World world(config, {0, -9.81});
  world.add_obstacle({{{-100, -10}, {100, 0}}});
  world.add_obstacle({{{-4, 0}, {-3, 40}}});
  world.add_obstacle({{{3, 0}, {4, 40}}});
  for (int k = 0; k < 60; ++k) {
    TireSpec spec = tire_at({-2.4 + 1.1 * (k % 5) + 0.25 * (k / 5 % 2), 0.5 + 1.2 * (k / 5)});
    if (material) material->apply_to(spec);
    world.add_tire(spec);
  }
  return world;
}

// `tires` default tires in rows of eleven in a 12 m box, and a 0.6 m crate dropped from `crate_y`
// onto them.
inline World pile_under_a_crate(const SolverConfig& config, int tires, double crate_y) {
  World world(config, {0, -9.81});
  world.add_obstacle({{{-1, -1}, {13, 0}}});
  world.add_obstacle({{{-1, 0}, {0, 50}}});
  world.add_obstacle({{{12, 0}, {13, 50}}});
  for (int i = 0; i < tires; ++i)
    world.add_tire(tire_at({0.6 + 1.05 * (i % 11) + 0.2 * ((i / 11) % 2), 0.5 + 1.0 * (i / 11)}));
  PropSpec crate;
  crate.type = PropType::dynamic_body;
  crate.size = {0.6, 0.6};
  crate.position = {5.0, crate_y};
  world.add_prop(crate);
  return world;
}

inline void run(World& world, int ticks, TickInput input = {}) {
  for (int i = 0; i < ticks; ++i) world.step(input);
}

inline void run(LevelSession& session, int ticks, TickInput input = {}) {
  for (int i = 0; i < ticks; ++i) session.step(input);
}

}  // namespace tire::test

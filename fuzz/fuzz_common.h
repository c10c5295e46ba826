// What the fuzz targets do with one input, shared with the regression test
// (tests/test_hostile_input.cpp runs every file of tests/fuzz-regressions/ through these).
// Each returns normally for any input; a broken invariant aborts, which libFuzzer reports as a crash.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>
#include <variant>
#include <vector>

#include "tire/io/level.h"
#include "tire/replay/replay.h"
#include "tire/world/world.h"

namespace tire::fuzz {

inline void require(bool ok, const char* what, const std::string& detail = {}) {
  if (ok) return;
  std::fprintf(stderr, "fuzz invariant broken: %s\n%s\n", what, detail.substr(0, 2000).c_str());
  std::abort();
}

// Every error names the file first; a load gives a level or errors, never both or neither.
template <typename Load, typename Value>
void check_errors(const Load& load, const Value& value, const std::string& file) {
  require(value.has_value() == load.errors.empty(), "a load gives a value exactly when it gives no errors",
          load.errors.empty() ? std::string() : load.errors.front());
  for (const std::string& e : load.errors)
    require(e.rfind(file + ": ", 0) == 0 && e.size() > file.size() + 2, "an error names the file first", e);
}

// Leading lines "--set key=value" are overrides, the rest is the level: the fuzzer reaches
// apply_override as well.
inline void split_overrides(const std::string& input, std::string& text,
                            std::vector<std::string>& overrides) {
  std::size_t at = 0;
  while (input.compare(at, 6, "--set ") == 0 && overrides.size() < 8) {
    const std::size_t end = input.find('\n', at);
    if (end == std::string::npos) break;
    overrides.push_back(input.substr(at + 6, end - at - 6));
    at = end + 1;
  }
  text = input.substr(at);
}

inline LevelLoad fuzz_level(const std::string& input) {
  std::string text;
  std::vector<std::string> overrides;
  split_overrides(input, text, overrides);
  LevelLoad load = load_level_text(text, "fuzz.json", overrides);
  check_errors(load, load.level, "fuzz.json");
  return load;
}

inline void fuzz_replay(const std::string& input) {
  const ReplayLoad load = load_replay_text(input, "fuzz-replay.json");
  check_errors(load, load.replay, "fuzz-replay.json");
  if (!load.replay) return;
  // What the writer writes, the reader reads back to the same replay.
  const std::string once = replay_to_json(*load.replay);
  const ReplayLoad again = load_replay_text(once, "again.json");
  require(again.replay.has_value(), "a written replay reads back",
          again.errors.empty() ? "" : again.errors.front());
  require(replay_to_json(*again.replay) == once, "a replay survives writing and reading unchanged", once);
}

// How much simulation one input may ask for before the target skips it: each execution must stay
// in the milliseconds for the fuzzer to make progress.
struct SimulateBudget {
  std::size_t max_particles = 3000;  // 2 x segments, over the level's tires and spawn actions
  std::size_t max_props = 64;        // with spawned ones
  std::size_t max_points = 2000;     // chain, polygon and path points
  std::size_t max_obstacles = 256;
  double max_particle_sweeps = 300000.0;  // particles x substeps x iterations per tick
  int ticks = 40;
};

// Loads the level; when valid and small enough, builds its world and steps it, with a few inputs,
// checking that every tire stays finite.
inline void fuzz_simulate(const std::string& input, const SimulateBudget& budget = {}) {
  const LevelLoad load = fuzz_level(input);
  if (!load.level) return;
  const Level& level = *load.level;
  std::size_t particles = 0, props = level.props.size(), points = 0, spawn_actions = 0;
  for (const TireSpec& t : level.tires) particles += 2 * static_cast<std::size_t>(t.segments);
  for (const PropSpec& p : level.props) points += p.points.size() + p.path.waypoints.size();
  for (const Trigger& trigger : level.script.triggers)
    for (const Action& a : trigger.actions) {
      if (const auto* s = std::get_if<SpawnTire>(&a)) {
        // A repeating trigger can fire every tick: count it as firing on every one.
        particles += 2 * static_cast<std::size_t>(s->tire.segments) * (trigger.once ? 1 : budget.ticks);
        ++spawn_actions;
      }
      if (const auto* s = std::get_if<SpawnProp>(&a)) {
        props += trigger.once ? 1 : budget.ticks;
        points += (s->prop.points.size() + s->prop.path.waypoints.size()) * (trigger.once ? 1 : budget.ticks);
      }
    }
  particles += 2 * 28 * 2;  // the tires the inputs below spawn
  const double sweeps = static_cast<double>(particles) * level.solver.substeps * level.solver.iterations;
  if (particles > budget.max_particles || props > budget.max_props || points > budget.max_points ||
      level.obstacles.size() > budget.max_obstacles || sweeps > budget.max_particle_sweeps)
    return;

  std::unique_ptr<LevelSession> session = make_session(level);
  World* const world = &session->world();  // the same object after a restart (assigned in place)
  // Inputs from the bytes themselves, so that the fuzzer steers them too.
  std::size_t h = 1469598103934665603ull;
  for (const unsigned char c : input) h = (h ^ c) * 1099511628211ull;
  const double steer = static_cast<double>(h % 5) / 2.0 - 1.0;
  TickInput held{steer, false, static_cast<double>(h % 3) - 1.0};
  for (int tick = 0; tick < budget.ticks; ++tick) {
    held.jump = tick == static_cast<int>(h % 17);
    ReplayInput in;
    in.tick = static_cast<std::uint64_t>(tick);
    if (tick == 5) in.spawn = Vec2{static_cast<double>(h % 7) - 3.0, 3.0};
    if (tick == 8 && !world->tires().empty()) in.grab = world->tires().front().particles.x[0];
    if (tick == 9) in.drag = Vec2{0.0, 4.0};
    if (tick == 15) in.release = true;
    if (tick == 20) in.set_key = "tires.pressure", in.set_value = 1.5;
    if (tick == 25) in.steer = -steer;
    if (tick == 30 && (h & 1)) in.restart = true;
    if (tick == 31) in.spawn = Vec2{0.0, 6.0};
    apply_input(in, *session, level, held);
    session->step(held);
    for (const Tire& t : world->tires()) require(t.is_finite(), "every tire stays finite", level.name);
    world->warnings().clear();
  }
  (void)session->state_hash();
}

}  // namespace tire::fuzz

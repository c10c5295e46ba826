// What fuzz_session does with one input (fuzz/fuzz_session.cpp under libFuzzer, fuzz/session_main.cpp
// in the test suite, tests/test_hostile_input.cpp on the regressions): the level is loaded by the
// loader the game and tirectl use and played as they play it, through a LevelSession (script,
// triggers, actions, spawns, messages), for 600 ticks with player inputs derived from the input's
// bytes. After every tick the run budgets, the divergence guard and the state hash are checked; a
// broken invariant aborts (require, fuzz_common.h), which the fuzzer reports as a crash.
#pragma once

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <variant>

#include "fuzz_common.h"
#include "tire/replay/replay.h"
#include "tire/session/level_session.h"

namespace tire::fuzz {

// What one input may ask for. The target lowers the level's run budgets to `most` (as a level may
// lower its own: levels/README.md "budgets"), so that what a script, the inputs or a restart add
// stays what a fuzzer can step 600 ticks of in well under a second; a level whose own contents or
// solver already cost more is skipped before it runs.
struct SessionBudget {
  int ticks = 600;
  RunBudgets most{.tires = 6,
                  .particles = 6 * 2 * 28,
                  .props = 48,
                  .spawns_per_tick = 4,
                  .messages = RunBudgets{}.messages,
                  .message_bytes = RunBudgets{}.message_bytes,
                  .firings_per_tick = RunBudgets{}.firings_per_tick};
  std::size_t max_points = 2000;  // chain, polygon and path points: the level's and its spawn actions'
  std::size_t max_obstacles = 256;
  // budgets.particles × substeps × iterations × max_refine, with the most substeps and iterations
  // the level or its script sets: particle sweeps in the costliest tick the run can have.
  double max_particle_sweeps = 50000.0;
  // The peak resident set (getrusage) the process may reach, checked every 50 ticks (check_memory);
  // 0 leaves it to the driver (libFuzzer's -rss_limit_mb).
  long max_rss_mb = 0;
};

// The run budgets, rows budget_tires to budget_firings_per_tick of the parameter table.
inline constexpr std::size_t kBudgetCount = static_cast<std::size_t>(ParamId::budget_firings_per_tick) -
                                            static_cast<std::size_t>(ParamId::budget_tires) + 1;

// What the runs came to, for a driver to report and to show that the inputs reach what they
// should (fuzz/session_main.cpp).
struct SessionStats {
  std::uint64_t inputs = 0;
  std::uint64_t levels = 0;   // inputs that loaded as a level
  std::uint64_t skipped = 0;  // levels past SessionBudget
  std::uint64_t runs = 0;     // levels played for every tick
  std::uint64_t ticks = 0;
  std::uint64_t restarts = 0;
  std::uint64_t spawned = 0;   // tires and props added while running
  std::uint64_t messages = 0;  // ticks that ended with a message on screen
  // Runs in which each budget was reached, in ParamId order from budget_tires.
  std::array<std::uint64_t, kBudgetCount> budget_reached{};
  std::uint64_t won = 0, lost = 0;
};

// The budget LLVMFuzzerTestOneInput runs with (fuzz_session.cpp): the defaults under libFuzzer, the
// memory limit added by the test suite's driver (session_main.cpp).
inline SessionBudget& session_budget() {
  static SessionBudget budget;
  return budget;
}

inline SessionStats& session_stats() {
  static SessionStats stats;
  return stats;
}

inline long peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024;  // Linux: kilobytes
}

// Exit 1, naming `where`, once the peak resident set has passed `limit_mb` (0: no limit).
inline void check_memory(long limit_mb, const std::string& where) {
  if (limit_mb <= 0) return;
  if (const long peak = peak_rss_mb(); peak > limit_mb) {
    std::fprintf(stderr, "fuzz memory limit passed: %s: peak RSS %ld MB, more than the limit of %ld MB\n",
                 where.c_str(), peak, limit_mb);
    std::exit(1);
  }
}

namespace session_detail {

// splitmix64 (Steele, Lea & Flood 2014): the player's inputs, from the input's bytes only.
struct Stream {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  bool one_in(std::uint64_t n) { return next() % n == 0; }
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53;
  }
};

// The most a level or its script sets a solver integer to (solver.substeps, solver.iterations).
inline int most_set(const Level& level, int level_value, const char* key) {
  int most = level_value;
  for (const Trigger& trigger : level.script.triggers)
    for (const Action& a : trigger.actions)
      if (const auto* s = std::get_if<SetParameter>(&a); s && s->key == key)
        most = std::max(most, static_cast<int>(s->value));
  return most;
}

inline std::size_t prop_points(const PropSpec& p) { return p.points.size() + p.path.waypoints.size(); }

// Whether the level fits SessionBudget once its budgets are lowered to it.
inline bool affordable(const Level& level, const SessionBudget& budget) {
  std::size_t particles = 0, points = 0, tires = level.tires.size(), props = level.props.size();
  for (const TireSpec& t : level.tires) particles += 2 * static_cast<std::size_t>(t.segments);
  for (const PropSpec& p : level.props) points += prop_points(p);
  for (const LevelVehicle& v : level.vehicles) {  // its wheels are tires, its chassis a prop
    tires += v.spec.wheels.size();
    for (const WheelSpec& w : v.spec.wheels) particles += 2 * static_cast<std::size_t>(w.tire.segments);
    props += 1;
    points += prop_points(v.spec.chassis);
  }
  for (const Trigger& trigger : level.script.triggers)
    for (const Action& a : trigger.actions)
      if (const auto* s = std::get_if<SpawnProp>(&a)) points += prop_points(s->prop);
  if (tires > static_cast<std::size_t>(budget.most.tires) ||
      particles > static_cast<std::size_t>(budget.most.particles) ||
      props > static_cast<std::size_t>(budget.most.props) || points > budget.max_points ||
      level.obstacles.size() > budget.max_obstacles)
    return false;
  const double sweeps =
      static_cast<double>(budget.most.particles) * most_set(level, level.solver.substeps, "solver.substeps") *
      most_set(level, level.solver.iterations, "solver.iterations") * std::max(1, level.solver.max_refine);
  return sweeps <= budget.max_particle_sweeps;
}

inline RunBudgets lowered(const RunBudgets& level, const RunBudgets& most) {
  return {.tires = std::min(level.tires, most.tires),
          .particles = std::min(level.particles, most.particles),
          .props = std::min(level.props, most.props),
          .spawns_per_tick = std::min(level.spawns_per_tick, most.spawns_per_tick),
          .messages = std::min(level.messages, most.messages),
          .message_bytes = std::min(level.message_bytes, most.message_bytes),
          .firings_per_tick = std::min(level.firings_per_tick, most.firings_per_tick)};
}

// The player's input for one tick, as a replay would give it: steer changes, jumps, inflating, and now and
// then a click that spawns a tire, a grab and drag, a live tuning, a gravity change or a restart.
inline ReplayInput input_for(std::uint64_t tick, Stream& s, const World& world, bool& dragging) {
  ReplayInput in;
  in.tick = tick;
  if (s.one_in(40)) in.steer = static_cast<double>(s.next() % 5) * 0.5 - 1.0;
  if (s.one_in(45)) in.jump = true;
  if (s.one_in(60)) in.inflate = static_cast<double>(s.next() % 3) - 1.0;
  if (s.one_in(90)) in.spawn = Vec2{s.uniform(-12.0, 12.0), s.uniform(0.5, 8.0)};
  if (dragging) {
    in.drag = Vec2{s.uniform(-12.0, 12.0), s.uniform(0.0, 8.0)};
    if (s.one_in(20)) in.release = true, dragging = false;
  } else if (s.one_in(120) && !world.tires().empty()) {
    const Tire& t = world.tires()[s.next() % world.tires().size()];
    in.grab = t.particles.x[s.next() % t.n];
    dragging = true;
  }
  if (s.one_in(150)) {
    static constexpr std::array<const char*, 5> keys{"tires.pressure", "tires.friction", "player.mass_scale",
                                                     "tires.material_damping", "solver.damping"};
    static constexpr std::array<double, 5> values{0.1, 0.5, 1.0, 4.0, 10.0};
    in.set_key = keys[s.next() % keys.size()];
    in.set_value = values[s.next() % values.size()];
  }
  if (s.one_in(200)) in.gravity = Vec2{s.uniform(-30.0, 30.0), s.uniform(-30.0, 30.0)};
  if (s.one_in(1500)) {  // alone on its tick, so that the level's start state follows it
    ReplayInput restart;
    restart.tick = tick;
    restart.restart = true;
    dragging = false;
    return restart;
  }
  return in;
}

// What the world holds that a tick may have added to: props (their slots stay when removed) and
// tires (ids grow from 0 in the order added, and scripts remove none).
struct Added {
  std::size_t props = 0;
  TireId next_id = 0;  // above every tire id so far
};

// What a level starts with is added, not spawned: the count starts after it.
inline Added own(const Level& level) { return {level.props.size(), static_cast<TireId>(level.tires.size())}; }

// The i-th budget's key ("budgets.tires", ...), in ParamId order.
inline const char* budget_key(std::size_t i) {
  return tire::parameter(static_cast<ParamId>(static_cast<std::size_t>(ParamId::budget_tires) + i)).key;
}

// The invariants after a tick, against the budgets the world was given.
inline void check_tick(const LevelSession& session, const std::string& name) {
  const World& world = session.world();
  const RunBudgets& b = world.budgets();
  std::size_t particles = 0;
  for (const Tire& t : world.tires()) {
    particles += t.particles.size();
    require(t.is_finite(), "every tire stays finite: NaN or Inf escaped the divergence guard", name);
    require(t.max_abs_coordinate() <= world.config().divergence_limit,
            "every tire stays within solver.divergence_limit of the origin", name);
    require(std::abs(t.area_ratio()) <= world.config().divergence_area,
            "every tire's area stays within solver.divergence_area times its rest area", name);
  }
  require(world.tires().size() <= static_cast<std::size_t>(b.tires), "live tires within budgets.tires", name);
  require(particles <= static_cast<std::size_t>(b.particles), "their particles within budgets.particles",
          name);
  require(world.rigid().props().size() <= static_cast<std::size_t>(b.props), "props within budgets.props",
          name);
  for (std::uint32_t i = 0; i < world.rigid().props().size(); ++i) {
    if (!world.rigid().props()[i].alive) continue;
    const PropState p = world.rigid().prop_state(i);
    require(std::isfinite(p.pose.position.x) && std::isfinite(p.pose.position.y) &&
                std::isfinite(p.pose.angle) && std::isfinite(p.velocity.x) && std::isfinite(p.velocity.y) &&
                std::isfinite(p.angular_velocity),
            "every prop stays finite", name);
  }
  std::size_t bytes = 0;
  for (const ScriptMessage& m : session.messages()) {
    bytes += m.text.size();
    require(m.until_tick > world.tick(), "no expired message stays on screen", name);
  }
  require(session.messages().size() <= static_cast<std::size_t>(b.messages),
          "messages within budgets.messages", name);
  require(bytes <= static_cast<std::size_t>(b.message_bytes), "their text within budgets.message_bytes",
          name);
  for (std::size_t i = 0; i < world.budgets_reached().size(); ++i) {
    const World::BudgetReached& r = world.budgets_reached()[i];
    require(tire::parameter(r.budget).is_budget() && r.dropped > 0 && r.first_tick <= world.tick(),
            "a budget reached names a budget, a tick so far and what it dropped", name);
    for (std::size_t j = 0; j < i; ++j)
      require(world.budgets_reached()[j].budget != r.budget, "each budget is reported once", name);
  }
}

}  // namespace session_detail

// Loads the level; when valid and within `budget`, plays it for budget.ticks ticks, checking the
// invariants after each.
inline void fuzz_session(const std::string& input, const SessionBudget& budget = {}) {
  namespace d = session_detail;
  SessionStats& stats = session_stats();
  ++stats.inputs;
  const LevelLoad load = fuzz_level(input);
  if (!load.level) return;
  ++stats.levels;
  Level level = *load.level;
  if (!d::affordable(level, budget)) {
    ++stats.skipped;
    return;
  }
  level.budgets = d::lowered(level.budgets, budget.most);

  std::uint64_t h = 1469598103934665603ull;  // FNV-1a of the input: the inputs' stream
  for (const unsigned char c : input) h = (h ^ c) * 1099511628211ull;
  d::Stream stream{h};
  std::unique_ptr<LevelSession> session = make_session(level);
  World* const world = &session->world();  // the same object after a restart (assigned in place)
  const std::uint64_t start = session->state_hash();
  d::Added since = d::own(level);
  std::array<bool, kBudgetCount> reached{};
  std::array<int, kBudgetCount> reports{};  // warnings naming each budget, in this world
  TickInput held;
  bool dragging = false;
  for (int tick = 0; tick < budget.ticks; ++tick) {
    const ReplayInput in = d::input_for(static_cast<std::uint64_t>(tick), stream, *world, dragging);
    held.jump = false;
    apply_input(in, *session, level, held);
    if (in.restart) {
      require(session->state_hash() == start, "a restart gives back the state the level started in",
              level.name);
      since = d::own(level), reports = {}, ++stats.restarts;
    }
    // Spawns on the world's current tick: the script's at the end of the last step (or in the
    // tick-0 update) and the player's now.
    std::size_t added = world->rigid().props().size() - since.props;
    since.props = world->rigid().props().size();
    const TireId first_new = since.next_id;
    for (const Tire& t : world->tires())
      if (t.id >= first_new) ++added, since.next_id = std::max<TireId>(since.next_id, t.id + 1);
    require(added <= static_cast<std::size_t>(world->budgets().spawns_per_tick),
            "no tick adds more tires and props than budgets.spawns_per_tick", level.name);
    stats.spawned += added;

    session->step(held);
    d::check_tick(*session, level.name);
    (void)session->state_hash();
    for (const std::string& w : world->warnings())
      for (std::size_t i = 0; i < reports.size(); ++i)
        if (w.starts_with(std::string(d::budget_key(i)) + " (")) {
          require(++reports[i] == 1, "reaching a budget is reported once", w);
          reached[i] = true;
        }
    world->warnings().clear();
    stats.messages += !session->messages().empty();
    ++stats.ticks;
    if (tick % 50 == 0) check_memory(budget.max_rss_mb, level.name + ", tick " + std::to_string(tick));
  }
  ++stats.runs;
  for (std::size_t i = 0; i < reached.size(); ++i) stats.budget_reached[i] += reached[i];
  stats.won += session->status() == ScriptStatus::won;
  stats.lost += session->status() == ScriptStatus::lost;
}

}  // namespace tire::fuzz

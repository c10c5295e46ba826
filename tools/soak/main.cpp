// tire-soak: simulates N minutes of game time on a level with seeded random inputs (steering,
// jumps, tire spawns, mouse grabs and drags), the way a player hammering the sandbox would, and
// checks that
//   - every tire stays finite, every tick, and no divergence warning fires;
//   - no more tires are alive than the level's own and --max-tires: the run budget of live tires
//     it sets (levels/README.md, "budgets") holds, a script spawning on top included;
//   - resident memory stays flat: after the warm-up minutes (the tire count reaches its cap and
//     stays there, since the oldest spawned tire is removed for each new one) RSS may not grow by
//     more than a small bound.
// Prints one line per simulated minute, then a summary; exit 0 pass, 1 fail, 2 bad arguments.
//
//   build/bin/tire-soak [--minutes 60] [--level levels/07-sandbox.json] [--seed 1] [--max-tires 200]
//                       [--warmup 3] [--rss-slack-mib 16]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <random>
#include <string>

#include "cli_numbers.h"
#include "process_memory.h"
#include "tire/engine.h"

namespace {

struct Options {
  double minutes = 60.0;
  std::string level = TIRE_SOURCE_DIR "/levels/07-sandbox.json";
  std::uint64_t seed = 1;
  std::size_t max_tires = 200;
  int warmup_minutes = 3;
  double rss_slack_mib = 16.0;
};

using tire_tools::heap_mib;
using tire_tools::rss_mib;

// The region random inputs aim at: the box around the level's obstacles, shrunk by a margin, upper
// part (spawns fall in from above, as clicks in the sky would).
struct Region {
  tire::Vec2 min{-10, 2}, max{10, 10};
  tire::Vec2 world_min{-1e300, -1e300}, world_max{1e300, 1e300};  // the obstacles' bounding box
};

Region region_of(const tire::Simulation& simulation) {
  if (simulation.obstacles().empty()) return {};
  tire::Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
  for (const tire::Obstacle& o : simulation.obstacles()) {
    lo = {std::min(lo.x, o.box.min.x), std::min(lo.y, o.box.min.y)};
    hi = {std::max(hi.x, o.box.max.x), std::max(hi.y, o.box.max.y)};
  }
  Region r;
  r.world_min = lo;
  r.world_max = hi;
  r.min = {lo.x + 1.5, lo.y + 0.5 * (hi.y - lo.y)};
  r.max = {hi.x - 1.5, hi.y - 3.0};
  if (!(r.min.x < r.max.x) || !(r.min.y < r.max.y)) return {};
  return r;
}

// Every position finite, and the velocities as far as the view shows them: their mean and the spin
// (a particle's infinite or NaN velocity makes both so).
bool finite(const tire::TireView& t) {
  const auto ok = [](tire::Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); };
  return std::all_of(t.positions.begin(), t.positions.end(), ok) && ok(t.velocity) && std::isfinite(t.spin);
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  using tire_tools::integer_in;
  using tire_tools::number_in;
  CLI::App cli{"tire-soak: simulated play with random inputs; fails on NaN or growing memory", "tire-soak"};
  cli.add_option("--minutes", opt.minutes, "simulated minutes to play")
      ->check(number_in({0, 1440, true}))
      ->capture_default_str();
  cli.add_option("--level", opt.level, "level file to play")->capture_default_str();
  cli.add_option("--seed", opt.seed, "seed of the random inputs")
      ->transform(integer_in({0, 1e15}))
      ->capture_default_str();
  cli.add_option("--max-tires", opt.max_tires, "most tires alive at once")
      ->transform(integer_in({1, 10000}))
      ->capture_default_str();
  cli.add_option("--warmup", opt.warmup_minutes, "simulated minutes before memory is watched")
      ->transform(integer_in({0, 1440}))
      ->capture_default_str();
  cli.add_option("--rss-slack-mib", opt.rss_slack_mib, "how much RSS may grow after the warm-up (MiB)")
      ->check(number_in({0, 1e6}))
      ->capture_default_str();
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = cli.exit(e);
    return code == 0 ? 0 : 2;
  }

  const tire::LevelOpen first = tire::open_level_file(opt.level);
  if (!first.level) {
    for (const std::string& e : first.errors) std::fprintf(stderr, "%s\n", e.c_str());
    return 2;
  }
  // --max-tires is the soak's own spawns; the level's run budget of live tires becomes its own
  // tires and those (levels/README.md, "budgets"), so that a script spawning on top is held to it
  // too.
  const auto level_budget =
      static_cast<std::size_t>(tire::Simulation(first.level).parameter("budgets.tires").value_or(0.0));
  const int budget = static_cast<int>(std::min(level_budget, first.info.tires + opt.max_tires));
  const tire::LevelOpen load = tire::open_level_file(opt.level, {"budgets.tires=" + std::to_string(budget)});
  if (!load.level) {
    for (const std::string& e : load.errors) std::fprintf(stderr, "%s\n", e.c_str());
    return 2;
  }
  tire::Simulation simulation(load.level);
  const Region region = region_of(simulation);
  const double dt = load.info.dt;
  const auto ticks_per_minute = static_cast<std::uint64_t>(std::llround(60.0 / dt));
  const auto total_ticks = static_cast<std::uint64_t>(std::llround(opt.minutes * 60.0 / dt));

  std::mt19937_64 rng(opt.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto random_point = [&] {
    return tire::Vec2{region.min.x + unit(rng) * (region.max.x - region.min.x),
                      region.min.y + unit(rng) * (region.max.y - region.min.y)};
  };

  // Tires the soak spawned, oldest first; the level's own tires are never removed.
  std::deque<tire::TireId> spawned;
  std::uint64_t spawns = 0, removals = 0, lost = 0, grabs = 0, jumps = 0, steers = 0;
  std::uint64_t nonfinite = 0, warnings = 0, budget_notes = 0, over_budget = 0;
  std::size_t max_tires_seen = 0;
  tire::TickInput held;
  int grab_ticks_left = 0;
  tire::Vec2 drag_target;

  const double rss_start = rss_mib(), heap_start = heap_mib();
  double rss_baseline = -1.0, rss_max_after = 0.0, heap_baseline = -1.0, heap_max_after = 0.0;
  bool failed = false;
  const auto wall_start = std::chrono::steady_clock::now();
  std::printf(
      "tire-soak: %s, %.0f simulated minutes (%llu ticks), seed %llu, at most %zu spawned tires; "
      "spawn region [%.1f, %.1f]..[%.1f, %.1f]; RSS %.1f MiB\n",
      opt.level.c_str(), opt.minutes, static_cast<unsigned long long>(total_ticks),
      static_cast<unsigned long long>(opt.seed), opt.max_tires, region.min.x, region.min.y, region.max.x,
      region.max.y, rss_start);
  std::fflush(stdout);

  for (std::uint64_t tick = 0; tick < total_ticks; ++tick) {
    held.jump = false;
    // Random inputs, applied as the game's and replays' are.
    tire::ReplayInput in;
    in.tick = tick;
    bool any = false;
    if (unit(rng) < 1.0 / 90.0)
      in.steer = std::round(unit(rng) * 4.0 - 2.0) / 2.0, any = true, ++steers;  // -1..1 in halves
    if (unit(rng) < 1.0 / 150.0) in.jump = true, any = true, ++jumps;
    if (unit(rng) < 1.0 / 120.0) in.inflate = std::round(unit(rng) * 2.0 - 1.0), any = true;  // -1, 0 or 1
    if (unit(rng) < 1.0 / 30.0) in.spawn = random_point(), any = true;
    if (const std::size_t tires = simulation.tire_count();
        grab_ticks_left == 0 && unit(rng) < 1.0 / 240.0 && tires > 0) {
      // Press on a random tire's tread, then drag it about for up to two seconds.
      const std::optional<tire::TireView> t =
          simulation.tire_at(static_cast<std::size_t>(unit(rng) * static_cast<double>(tires)) % tires);
      in.grab = t->positions[0];
      drag_target = *in.grab;
      grab_ticks_left = 1 + static_cast<int>(unit(rng) * 120.0);
      any = true;
      ++grabs;
    } else if (grab_ticks_left > 1) {
      --grab_ticks_left;
      const tire::Vec2 aim = random_point();
      drag_target = drag_target + (aim - drag_target) * 0.02;  // a hand moves smoothly
      in.drag = drag_target;
      any = true;
    } else if (grab_ticks_left == 1) {
      grab_ticks_left = 0;
      in.release = true;
      any = true;
    }
    if (any) {
      if (in.spawn && spawned.size() >= opt.max_tires) {  // room first: the oldest spawned goes
        if (simulation.remove_tire(spawned.front())) ++removals;
        spawned.pop_front();
      }
      const std::size_t before = simulation.tire_count();
      simulation.apply(in, held);
      if (simulation.tire_count() > before) {
        ++spawns;
        spawned.push_back(simulation.tire_at(simulation.tire_count() - 1)->id);
      }
    }
    simulation.step(held);
    // Tires thrown over the level's walls fall for ever: like the game, remove spawned ones once
    // they are well below the level (they count as lost).
    for (auto it = spawned.begin(); it != spawned.end();) {
      const std::optional<tire::TireView> t = simulation.tire(*it);
      if (t && t->centroid.y < region.world_min.y - 20.0) {
        simulation.remove_tire(*it);
        it = spawned.erase(it);
        ++lost;
      } else {
        ++it;
      }
    }

    for (std::size_t i = 0; const std::optional<tire::TireView> t = simulation.tire_at(i); ++i)
      if (!finite(*t)) {
        ++nonfinite;
        if (nonfinite <= 5)
          std::fprintf(stderr, "tire-soak: tick %llu: tire %u is not finite\n",
                       static_cast<unsigned long long>(tick + 1), t->id);
      }
    if (simulation.tire_count() > static_cast<std::size_t>(budget)) {
      ++over_budget;  // a budget passed: the engine let more live than it was given
      if (over_budget == 1)
        std::fprintf(stderr, "tire-soak: tick %llu: %zu tires alive, past budgets.tires (%d)\n",
                     static_cast<unsigned long long>(tick + 1), simulation.tire_count(), budget);
    }
    for (const std::string& w : simulation.take_warnings()) {
      if (w.starts_with("budgets.")) {  // a budget reached and held: reported, not a fault
        if (++budget_notes <= 5) std::fprintf(stderr, "tire-soak: %s\n", w.c_str());
        continue;
      }
      ++warnings;
      if (warnings <= 5) std::fprintf(stderr, "tire-soak: warning: %s\n", w.c_str());
    }
    max_tires_seen = std::max(max_tires_seen, simulation.tire_count());

    if ((tick + 1) % ticks_per_minute == 0 || tick + 1 == total_ticks) {
      const std::uint64_t minute = (tick + 1 + ticks_per_minute - 1) / ticks_per_minute;
      const double rss = rss_mib(), heap = heap_mib();
      if (minute == static_cast<std::uint64_t>(opt.warmup_minutes) ||
          (opt.warmup_minutes == 0 && rss_baseline < 0))
        rss_baseline = rss, heap_baseline = heap;
      if (rss_baseline >= 0)
        rss_max_after = std::max(rss_max_after, rss), heap_max_after = std::max(heap_max_after, heap);
      double max_speed = 0.0;
      std::size_t outside = 0;  // tires whose hub is outside the level's bounding box (thrown out, falling)
      for (std::size_t i = 0; const std::optional<tire::TireView> t = simulation.tire_at(i); ++i) {
        max_speed = std::max(max_speed, tire::length(t->velocity));
        const tire::Vec2 c = t->centroid;
        outside += c.x < region.world_min.x || c.x > region.world_max.x || c.y < region.world_min.y - 1.0;
        if (c.y < region.world_min.y - 1.0 && std::getenv("TIRE_SOAK_DEBUG"))
          std::fprintf(stderr, "  tire %u outside at (%.2f, %.2f) v (%.2f, %.2f)\n", t->id, c.x, c.y,
                       t->velocity.x, t->velocity.y);
      }
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
      std::printf(
          "minute %3llu: tick %8llu  tires %4zu  spawned %6llu  removed %6llu  lost %4llu  grabs %5llu  "
          "jumps %5llu  max speed %6.2f m/s  outside %3zu  status %-7s  non-finite %llu  warnings %llu  RSS "
          "%6.1f MiB  "
          "heap %6.1f MiB  wall %7.1f s\n",
          static_cast<unsigned long long>(minute), static_cast<unsigned long long>(tick + 1),
          simulation.tire_count(), static_cast<unsigned long long>(spawns),
          static_cast<unsigned long long>(removals), static_cast<unsigned long long>(lost),
          static_cast<unsigned long long>(grabs), static_cast<unsigned long long>(jumps), max_speed, outside,
          tire::to_string(simulation.status()), static_cast<unsigned long long>(nonfinite),
          static_cast<unsigned long long>(warnings), rss, heap, wall);
      std::fflush(stdout);
    }
  }

  const double rss_end = rss_mib();
  const double growth = rss_baseline >= 0 ? rss_max_after - rss_baseline : 0.0;
  const double heap_growth = heap_baseline >= 0 ? heap_max_after - heap_baseline : 0.0;
  if (nonfinite > 0 || warnings > 0 || over_budget > 0) failed = true;
  if (rss_baseline >= 0 && (growth > opt.rss_slack_mib || heap_growth > opt.rss_slack_mib)) failed = true;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  std::printf(
      "tire-soak: %s: %.1f simulated minutes in %.1f s wall; tires at end %zu (max %zu), spawned %llu, "
      "removed %llu (and %llu lost over the walls), grabs %llu, jumps %llu, steer changes %llu; non-finite "
      "%llu, "
      "divergence warnings %llu, ticks past budgets.tires %llu; "
      "RSS start %.1f MiB, after warm-up %.1f MiB, max after %.1f MiB, end %.1f MiB (growth %.1f MiB, "
      "allowed %.1f); heap in use start %.1f MiB, after warm-up %.1f MiB, end %.1f MiB (growth %.1f MiB)\n",
      failed ? "FAIL" : "ok", static_cast<double>(total_ticks) * dt / 60.0, wall, simulation.tire_count(),
      max_tires_seen, static_cast<unsigned long long>(spawns), static_cast<unsigned long long>(removals),
      static_cast<unsigned long long>(lost), static_cast<unsigned long long>(grabs),
      static_cast<unsigned long long>(jumps), static_cast<unsigned long long>(steers),
      static_cast<unsigned long long>(nonfinite), static_cast<unsigned long long>(warnings),
      static_cast<unsigned long long>(over_budget), rss_start, rss_baseline, rss_max_after, rss_end, growth,
      opt.rss_slack_mib, heap_start, heap_baseline, heap_mib(), heap_growth);
  return failed ? 1 : 0;
}

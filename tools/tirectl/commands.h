// The tirectl subcommands. Each returns the process exit code: 0 success, 1 a check failed,
// 2 bad input (unreadable or invalid files, bad arguments).
#pragma once

#include <string>
#include <vector>

namespace tirectl {

struct RunOptions {
  std::string level;
  long long ticks = 60;
  std::vector<std::string> overrides;
  double steer = 0.0;
  double lean = 0.0;   // a player vehicle's lean, held for the whole run
  bool brake = false;  // a player vehicle's brakes, held for the whole run
  std::vector<long long> jump_at;
  long long trace_every = 0;  // > 0: a readable line about the player every this many ticks (stderr)
  std::string input;          // a replay whose inputs drive the run
  std::string record;         // write the run as a replay here
  bool progress = true;       // a progress line on stderr, when it is a terminal
};
int run(const RunOptions& options);

struct ReplayOptions {
  std::vector<std::string> files;
  bool update = false;              // rewrite the expectations from this run
  bool allow_level_change = false;  // run even if the level's content hash changed
  bool progress = true;             // a progress line on stderr, when it is a terminal
};
int replay(const ReplayOptions& options);

int validate(const std::vector<std::string>& files);

// The levels of a folder checked as the game's course (course.cpp): exit 1 when a level lacks a time
// limit or medals, when no replay in `replays` wins it, or when more than `max_held_share`
// of the levels are won by holding one input.
struct CourseOptions {
  std::string levels = "levels";
  std::string replays;  // "": not checked
  double max_held_share = 0.25;
  double max_seconds = 120.0;  // how long a level without a time limit is held
};
int course(const CourseOptions& options);

// levels/schema.json from the parameter table: printed (default), checked (exit 1 when the file
// differs) or rewritten in place.
struct SchemaOptions {
  std::string file = "levels/schema.json";
  bool check = false;
  bool write = false;
};
int schema(const SchemaOptions& options);

struct BenchOptions {
  std::vector<std::string> scenes;  // empty: all
  int threads = 0;                  // 0: the world's default (the hardware's)
  int steps = 0;                    // timed steps per scene; 0: at least 30, for `seconds`
  double seconds = 2.0;             // timing budget per scene when `steps` is 0
  int warmup = 120;                 // untimed steps first: the pile settles, caches warm
  int settle = 1800;                // a *-settled scene's most ticks of settling, before the warm-up
  int report_every = 0;             // >0: every this many steps, a progress line on stderr (time, RSS, heap)
  std::string schedule = "fused";   // World::step's schedule: fused (the default) or plain
};
int bench(const BenchOptions& options);

struct TradeoffOptions;  // tradeoff.h
int tradeoff(const TradeoffOptions& options);

}  // namespace tirectl

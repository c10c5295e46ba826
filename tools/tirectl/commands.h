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
  std::vector<long long> jump_at;
  long long trace_every = 0;  // > 0: a readable line about the player every this many ticks (stderr)
  std::string input;          // a replay whose inputs drive the run
  std::string record;         // write the run as a replay here
};
int run(const RunOptions& options);

struct ReplayOptions {
  std::vector<std::string> files;
  bool update = false;               // rewrite the expectations from this run
  bool allow_level_change = false;   // run even if the level's content hash changed
};
int replay(const ReplayOptions& options);

int validate(const std::vector<std::string>& files);

struct BenchOptions {
  std::vector<std::string> scenes;  // empty: all
  int frames = 2000;
  int repeats = 15;
};
int bench(const BenchOptions& options);

struct TradeoffOptions;  // tradeoff.h
int tradeoff(const TradeoffOptions& options);

}  // namespace tirectl

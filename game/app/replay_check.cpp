#include "app/replay_check.h"

#include <chrono>
#include <nlohmann/json.hpp>

#include "tire/replay/replay_file.h"

namespace game {

ReplayCheck check_replay_file(const std::filesystem::path& file) {
  nlohmann::json out;
  out["replay"] = file.stem().string();
  out["file"] = file.string();
  const auto unreadable = [&](const std::vector<std::string>& errors) {
    out["pass"] = false;
    out["errors"] = errors;
    return ReplayCheck{2, out.dump()};
  };
  const tire::ReplayLoad load = tire::load_replay_file(file);
  if (!load.replay) return unreadable(load.errors);
  const tire::Replay& replay = *load.replay;
  // Read as a level before its digest is looked at (tirectl replay does the same).
  const tire::ReplayLevel level = tire::load_replay_level(file, replay);
  if (!level.level) return unreadable(level.errors);
  out["ticks"] = replay.ticks;
  // As `tirectl replay` without --allow-level-change: a replay of another version of its level fails.
  if (const auto changed = tire::level_changed(level, replay)) {
    out["pass"] = false;
    out["failures"] = {*changed};
    return ReplayCheck{1, out.dump()};
  }
  const auto started = std::chrono::steady_clock::now();
  const tire::ReplayOutcome outcome = tire::run_replay(replay, *level.level);
  const std::chrono::duration<double, std::milli> ms = std::chrono::steady_clock::now() - started;
  const bool pass = outcome.failures.empty();
  out["pass"] = pass;
  out["status"] = outcome.status;
  out["hash"] = outcome.hash;
  out["checkpoints"] = replay.expect.checkpoints.size();
  if (outcome.first_divergent_tick) out["first_divergent_tick"] = *outcome.first_divergent_tick;
  out["failures"] = outcome.failures;
  out["ms"] = ms.count();
  return ReplayCheck{pass ? 0 : 1, out.dump()};
}

}  // namespace game

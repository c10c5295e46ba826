// tire-game --replay FILE: runs a replay headless through the engine (tire::run_replay), as
// `tirectl replay` does, and says what it came to in one line of JSON:
//   {"replay": "01-first-roll-goal", "pass": true, "ticks": 600, "status": "won", ...}
// No window is opened. The browser build prints the same line into the page.
#pragma once

#include <filesystem>
#include <string>

namespace game {

struct ReplayCheck {
  int exit_code = 2;  // 0 passed, 1 failed (or the level changed since recording), 2 unreadable
  std::string json;   // the one-line result
};

ReplayCheck check_replay_file(const std::filesystem::path& file);

}  // namespace game

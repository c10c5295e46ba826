// How a level stands: running, won or lost, and what ended it.
#pragma once

#include <cstdint>

namespace tire {

enum class ScriptStatus : std::uint8_t { running, won, lost };

const char* to_string(ScriptStatus status);  // "running", "won", "lost"

// What ended a level. The script ends it by its goal, a win or lose action or the time limit; the
// level session (tire/session/level_session.h) by the player leaving the level's bounds.
enum class EndReason : std::uint8_t { none, goal, win_action, lose_action, time_limit, out_of_bounds };

// "none", "goal", "win_action", "lose_action", "time_limit", "out_of_bounds"
const char* to_string(EndReason reason);

}  // namespace tire

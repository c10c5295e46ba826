// How a level stands: running, won or lost, and what ended it; the tick at which a time (a time
// limit) is reached; and what its script shows: its regions and the messages it put on screen.
#pragma once

#include <cstdint>
#include <string>

#include "tire/math/geometry.h"

namespace tire {

enum class ScriptStatus : std::uint8_t { running, won, lost };

const char* to_string(ScriptStatus status);  // "running", "won", "lost"

// What ended a level. The script ends it by its goal, a win or lose action or the time limit; the
// level session (tire/session/level_session.h) by the player leaving the level's bounds.
enum class EndReason : std::uint8_t {
  none,
  goal,
  win_action,
  lose_action,
  time_limit,
  out_of_bounds,
  head_hit
};

// "none", "goal", "win_action", "lose_action", "time_limit", "out_of_bounds", "head_hit"
const char* to_string(EndReason reason);

// The tick at which a time is reached: the first tick count n with n · dt ≥ seconds, with a
// relative tolerance of 1e-9 so that 5 s at dt = 1/60 is tick 300 despite rounding:
// n = max(0, ceil(seconds/dt − 1e-9 · max(1, seconds/dt))).
std::uint64_t tick_at(double seconds, double dt);

// A named axis-aligned box. A point on the boundary is inside.
struct Region {
  std::string name;
  Aabb box;
  constexpr bool contains(Vec2 p) const {
    return p.x >= box.min.x && p.x <= box.max.x && p.y >= box.min.y && p.y <= box.max.y;
  }
};

// A message a level script put on screen.
struct ScriptMessage {
  std::string text;
  std::uint64_t until_tick;  // shown while the tick is before until_tick
};

}  // namespace tire

// What a level may add while it runs (issue 34): each budget bounds something that scripts, replays
// or the player can grow tick after tick, which loading cannot see. Defaults are the largest a level
// may have (rows "budgets.*" of the parameter table, parameters.h); a level may lower them in its
// "budgets" object. What would pass one is dropped, deterministically, and reported once
// (World::budgets_reached).
#pragma once

#include <cstdint>

namespace tire {

struct RunBudgets {
  int tires = 10000;           // tires alive at once (the level's own with those added)
  int particles = 1'000'000;   // their particles, 2 × segments a tire
  int props = 10000;           // props added over the run, the level's own with the script's
  int spawns_per_tick = 16;    // tires and props added in one tick (script, replay and player)
  int messages = 16;           // script messages on screen at once
  int message_bytes = 8192;    // their text together (bytes)
  int firings_per_tick = 256;  // trigger firings in one tick
};

}  // namespace tire

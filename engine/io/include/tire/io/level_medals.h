// A level's medals (levels/README.md, "medals"): winning within a medal's time earns it. The times
// are seconds of simulated time, compared in ticks, so that a run of exactly a medal's time earns it
// whatever the rounding of ticks × dt.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace tire {

enum class Medal : std::uint8_t { none, bronze, silver, gold };

struct LevelMedals {
  double gold = 0.0;  // s; gold < silver < bronze (the reader checks it)
  double silver = 0.0;
  double bronze = 0.0;
};

// The medal a win after `ticks` ticks of `dt` earns.
Medal medal_for(const LevelMedals& medals, std::uint64_t ticks, double dt);
// The time (s) that earns `medal` (none: nullopt).
std::optional<double> medal_time(const LevelMedals& medals, Medal medal);
// The next medal better than `medal`; none after gold.
Medal next_medal(Medal medal);

// "gold", "silver", "bronze" or "none", as files and tirectl write it; medal_from_name reads it back.
std::string_view medal_name(Medal medal);
std::optional<Medal> medal_from_name(std::string_view name);

}  // namespace tire

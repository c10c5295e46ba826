#include "tire/io/level_medals.h"

#include "tire/script/script_runner.h"

namespace tire {

Medal medal_for(const LevelMedals& medals, std::uint64_t ticks, double dt) {
  // tick_at: the tick at which a time is reached, as the time limit counts it.
  if (ticks <= tick_at(medals.gold, dt)) return Medal::gold;
  if (ticks <= tick_at(medals.silver, dt)) return Medal::silver;
  if (ticks <= tick_at(medals.bronze, dt)) return Medal::bronze;
  return Medal::none;
}

std::optional<double> medal_time(const LevelMedals& medals, Medal medal) {
  switch (medal) {
    case Medal::gold: return medals.gold;
    case Medal::silver: return medals.silver;
    case Medal::bronze: return medals.bronze;
    case Medal::none: break;
  }
  return std::nullopt;
}

Medal next_medal(Medal medal) {
  switch (medal) {
    case Medal::none: return Medal::bronze;
    case Medal::bronze: return Medal::silver;
    case Medal::silver: return Medal::gold;
    case Medal::gold: break;
  }
  return Medal::none;
}

std::string_view medal_name(Medal medal) {
  switch (medal) {
    case Medal::gold: return "gold";
    case Medal::silver: return "silver";
    case Medal::bronze: return "bronze";
    case Medal::none: break;
  }
  return "none";
}

std::optional<Medal> medal_from_name(std::string_view name) {
  for (const Medal m : {Medal::none, Medal::bronze, Medal::silver, Medal::gold})
    if (medal_name(m) == name) return m;
  return std::nullopt;
}

}  // namespace tire

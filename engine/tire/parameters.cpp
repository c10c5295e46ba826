#include "tire/tire/parameters.h"

namespace tire {

const Parameter* find_parameter(std::string_view key) {
  bool player = false;
  if (key.starts_with("player.")) {
    key.remove_prefix(7);
    player = true;
  }
  for (const Parameter& p : kParameters) {
    const std::string_view k(p.key);
    if (player ? (p.is_tire() && k.substr(6) == key) : k == key) return &p;
  }
  return nullptr;
}

}  // namespace tire

// The levels of a directory: its *.json files sorted by file name, with the name each level gives
// itself. The level select menu lists them; next/previous level follow this order.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tire/io/level_medals.h"

namespace game {

struct LevelEntry {
  std::filesystem::path path;
  std::string name;                         // the level's "name", or the file name when it does not load
  bool valid = true;                        // false: the file does not load (see its errors when chosen)
  std::optional<tire::LevelMedals> medals;  // the times that earn its medals, if it has them
};

std::vector<LevelEntry> scan_levels(const std::filesystem::path& dir);

// Index of `file` in `levels` (same file, however spelled), if it is there.
std::optional<std::size_t> find_level(const std::vector<LevelEntry>& levels,
                                      const std::filesystem::path& file);

}  // namespace game

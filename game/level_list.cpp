#include "level_list.h"

#include <algorithm>

#include "tire/io/level.h"

namespace game {

std::vector<LevelEntry> scan_levels(const std::filesystem::path& dir) {
  std::vector<LevelEntry> out;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::filesystem::path& p = it->path();
    if (p.extension() != ".json" || !it->is_regular_file(ec)) continue;
    if (p.filename() == "schema.json") continue;  // the levels' JSON schema, not a level
    LevelEntry e;
    e.path = p;
    const tire::LevelLoad load = tire::load_level_file(p);
    e.valid = load.level.has_value();
    e.name = e.valid ? load.level->name : p.filename().string();
    if (e.valid) e.medals = load.level->medals;
    out.push_back(std::move(e));
  }
  std::sort(out.begin(), out.end(),
            [](const LevelEntry& a, const LevelEntry& b) { return a.path.filename() < b.path.filename(); });
  return out;
}

std::optional<std::size_t> find_level(const std::vector<LevelEntry>& levels,
                                      const std::filesystem::path& file) {
  std::error_code ec;
  for (std::size_t i = 0; i < levels.size(); ++i)
    if (std::filesystem::equivalent(levels[i].path, file, ec)) return i;
  return std::nullopt;
}

}  // namespace game

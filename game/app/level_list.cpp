#include "app/level_list.h"

#include "tire/io/level.h"

namespace game {

std::vector<LevelEntry> scan_levels(const std::filesystem::path& dir) {
  std::vector<LevelEntry> out;
  std::string error;  // an unreadable folder lists what was read: the menu says when it is empty
  for (const std::filesystem::path& p : tire::level_files(dir, error)) {
    LevelEntry e;
    e.path = p;
    const tire::LevelLoad load = tire::load_level_file(p);
    e.valid = load.level.has_value();
    e.name = e.valid ? load.level->name : p.filename().string();
    if (e.valid) e.medals = load.level->medals;
    out.push_back(std::move(e));
  }
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

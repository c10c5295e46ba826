#include "app/level_list.h"

#include "tire/level.h"

namespace game {

std::vector<LevelEntry> scan_levels(const std::filesystem::path& dir) {
  std::vector<LevelEntry> out;
  std::string error;  // an unreadable folder lists what was read: the menu says when it is empty
  for (const std::filesystem::path& p : tire::level_files(dir, error)) {
    LevelEntry e;
    e.path = p;
    const tire::LevelOpen load = tire::open_level_file(p);
    e.valid = load.level != nullptr;
    e.name = e.valid ? load.info.name : p.filename().string();
    if (e.valid) e.medals = load.info.medals;
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

#include "tire/level.h"

#include <algorithm>

#include "tire/io/file_io.h"
#include "tire/io/level.h"

namespace tire {

namespace {

LevelOpen opened(LevelLoad load) {
  LevelOpen out;
  out.errors = std::move(load.errors);
  if (!load.level) return out;
  out.info = level_info(*load.level);
  out.level = std::make_shared<const Level>(std::move(*load.level));
  return out;
}

}  // namespace

LevelOpen open_level_file(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  std::string error;
  const std::optional<std::string> text = read_level_text(file, error);
  if (!text) {
    LevelOpen out;
    out.errors.push_back(printable(file.string()) + ": " + error);
    return out;
  }
  LevelOpen out = opened(load_level_text(*text, file.string(), overrides));
  if (out.level) out.sha256 = sha256_hex(*text);
  return out;
}

LevelOpen open_level_text(const std::string& text, const std::string& file,
                          const std::vector<std::string>& overrides) {
  return opened(load_level_text(text, file, overrides));
}

LevelInfo level_info(const Level& level) {
  return {level.name,
          level.description,
          level.gravity,
          level.solver.dt,
          level.script.time_limit,
          level.medals,
          level.tires.size(),
          level.vehicles.size(),
          std::any_of(level.vehicles.begin(), level.vehicles.end(),
                      [](const LevelVehicle& v) { return v.player; }),
          level.bounds.box,
          level.bounds.min.has_value(),
          level.bounds.max.has_value()};
}

std::optional<std::string> read_level_text(const std::filesystem::path& file, std::string& error) {
  return read_file(file, LevelLimits::max_file_bytes, error);
}

std::vector<std::filesystem::path> level_files(const std::filesystem::path& dir, std::string& error) {
  std::vector<std::filesystem::path> files = json_files(dir, error);
  std::erase_if(files, [](const std::filesystem::path& p) { return p.filename() == "schema.json"; });
  return files;
}

}  // namespace tire

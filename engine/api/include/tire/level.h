// Levels as a program uses them: read and validated from a file or from text, listed from a folder,
// and described by what menus and tools show of them. The level itself (its tires, props, obstacles
// and script) stays the engine's: a program holds it as a shared handle and plays it with a
// Simulation (tire/engine.h). Keys, units, defaults and ranges: levels/README.md.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tire/io/level_medals.h"
#include "tire/math/geometry.h"

namespace tire {

struct Level;  // a level read and validated (engine/io)

// What a level shows before it is played.
struct LevelInfo {
  std::string name;
  std::string description;
  Vec2 gravity;
  double dt = 0.0;                    // s, its fixed tick
  std::optional<double> time_limit;   // s, from its script
  std::optional<LevelMedals> medals;  // the times that earn a medal, if it has them
  std::size_t tires = 0;              // the tires it places (not those its script spawns)
  std::size_t vehicles = 0;           // the vehicles it places (levels/README.md, "Vehicles")
  bool player_vehicle = false;        // its player is a vehicle, not a tire
  // The box the player must stay in (levels/README.md, "bounds"), and whether the level gives its
  // lower and upper corners; a corner it does not give is computed from its geometry (a computed
  // top is open: +inf).
  Aabb bounds;
  bool bounds_min_given = false;
  bool bounds_max_given = false;
};

struct LevelOpen {
  std::shared_ptr<const Level> level;  // null when `errors` is not empty
  LevelInfo info;
  std::string sha256;               // of the file's bytes, as a replay records it ("" from text)
  std::vector<std::string> errors;  // "FILE: /json/path: what was expected, got what"
};

// Reads, parses (within the limits of levels/README.md), applies overrides ("solver.substeps=16",
// any numeric key by its dotted path) and validates a level file.
LevelOpen open_level_file(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
// The same, from text already in memory; `file` only names it in messages.
LevelOpen open_level_text(const std::string& text, const std::string& file,
                          const std::vector<std::string>& overrides = {});

LevelInfo level_info(const Level& level);

// A level file's text, read within the size a level may have (what an editor keeps to edit), or
// nullopt with `error` set.
std::optional<std::string> read_level_text(const std::filesystem::path& file, std::string& error);

// The levels of folder `dir` as the game's menu and tirectl course list them: its *.json files but
// schema.json (the levels' JSON schema), sorted by file name. `error` says why the folder could not
// be read.
std::vector<std::filesystem::path> level_files(const std::filesystem::path& dir, std::string& error);

}  // namespace tire

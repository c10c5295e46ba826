// A level as read from its JSON file, and the one loader every program uses. Keys, units,
// defaults and ranges are those of levels/README.md.
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tire/io/json_reader.h"
#include "tire/io/level_bounds.h"
#include "tire/io/level_medals.h"
#include "tire/rigid/bodies.h"
#include "tire/script/script_spec.h"
#include "tire/tire/parameters.h"
#include "tire/tire/solver_config.h"
#include "tire/tire/tire_spec.h"
#include "tire/tire/vehicle_joints.h"

namespace tire {

class LevelSession;
class World;

// A vehicle as a level places it (levels/README.md, "Vehicles").
struct LevelVehicle {
  VehicleSpec spec;
  bool player = false;
  std::optional<VehicleHead> head;  // touching an obstacle or a static or kinematic prop loses
};

struct Level {
  std::string name;
  std::string description;
  Vec2 gravity = kDefaultGravity;
  SolverConfig solver;
  RunBudgets budgets;  // what the level may add while it runs (run_budgets.h)
  std::vector<TireSpec> tires;
  std::vector<Obstacle> obstacles;
  std::vector<PropSpec> props;
  std::vector<LevelVehicle> vehicles;
  LevelBounds bounds;                 // the box the player must stay in (level_bounds.h)
  ScriptSpec script;                  // regions, goal, time limit, counters, triggers (levels/SCRIPTING.md)
  std::optional<LevelMedals> medals;  // the times that earn a medal (level_medals.h), if it has them
};

// Limits enforced before any work is done (docs/testing.md, "Hardening").
struct LevelLimits {
  static constexpr std::uintmax_t max_file_bytes = 64ull << 20;
  static constexpr int max_depth = 64;
  static constexpr std::size_t max_json_values = 1'000'000;  // numbers, strings, arrays, objects
  static constexpr std::size_t max_string_bytes = 4096;      // of one string or key
  static constexpr std::size_t max_tires = 10000;
  static constexpr std::size_t max_obstacles = 100000;
  static constexpr std::size_t max_props = 10000;
  static constexpr std::size_t max_vehicles = 16;
  static constexpr double max_coordinate = 10000.0;  // m
};

// Reads a level from parsed JSON. Returns the level when there were no issues.
std::optional<Level> read_level(const nlohmann::json& doc, std::vector<JsonIssue>& issues);

// One "--set a.b.0.c=value" override: sets a numeric value at a dotted path, creating missing
// object keys (which validation then judges like any other key). Returns an error text or "".
std::string apply_override(nlohmann::json& doc, const std::string& assignment);

struct LevelLoad {
  std::optional<Level> level;
  std::vector<std::string> errors;  // "FILE: /json/path: what was expected, got what"
  JsonWork work;                    // what reading it cost (file and parser), counted
};

// Reads, parses (with the size and depth limits), applies overrides and validates a level file.
LevelLoad load_level_file(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
// The same, from text already in memory; `file` only names it in messages.
LevelLoad load_level_text(const std::string& text, const std::string& file,
                          const std::vector<std::string>& overrides = {});

// Adds the level's obstacles, props and tires to an empty world built with its solver and
// gravity: its physics, without the script.
void populate_world(const Level& level, World& world);

// The level ready to play: its world populated, its bounds set and its script installed (tick-0
// actions done).
std::unique_ptr<LevelSession> make_session(const Level& level);

}  // namespace tire

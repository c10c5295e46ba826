// The readers of the level's pieces, shared by the level loader and by script actions that carry
// a tire or a prop (spawn_tire, spawn_prop): one definition of every key, unit, default and range.
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>

#include "tire/io/json_reader.h"
#include "tire/io/level_format.h"
#include "tire/rigid/bodies.h"
#include "tire/tire/parameters.h"
#include "tire/tire/tire_spec.h"

namespace tire {

// A tire, or (LevelObject::wheel) a wheel's tire: the keys of its material alone.
TireSpec read_tire(JsonReader& r, const nlohmann::json& j, const std::string& path,
                   LevelObject object = LevelObject::tire);
// A prop, or (LevelObject::chassis) a vehicle's chassis: a dynamic prop, no chain.
PropSpec read_prop(JsonReader& r, const nlohmann::json& j, const std::string& path,
                   LevelObject object = LevelObject::prop);

// A parameter of the table (tire/parameters.h) at its field in `j`, with the row's range and unit.
double read_parameter(JsonReader& r, const nlohmann::json& j, const std::string& path, ParamId id,
                      double fallback, bool required = false);
int read_integer_parameter(JsonReader& r, const nlohmann::json& j, const std::string& path, ParamId id,
                           int fallback, bool required = false);
// The table's row of a key the readers know `object` has (tire/io/level_format.h); throws
// std::logic_error for one it lacks, a mistake in the readers, not in a file.
const LevelKey& level_key(LevelObject object, std::string_view key);
// The keys of `object` in the table's order, as JsonReader::object takes them.
std::span<const std::string_view> level_key_names(LevelObject object);

// One key of `j` read with its row's range, unit, choices and required flag; a key read through
// the parameter table, with the parameter's row (as read_parameter).
double read_number(JsonReader& r, const nlohmann::json& j, const std::string& path, const LevelKey& key,
                   double fallback);
int read_integer(JsonReader& r, const nlohmann::json& j, const std::string& path, const LevelKey& key,
                 int fallback);
Vec2 read_vec2(JsonReader& r, const nlohmann::json& j, const std::string& path, const LevelKey& key,
               Vec2 fallback);
std::string read_string(JsonReader& r, const nlohmann::json& j, const std::string& path, const LevelKey& key,
                        const std::string& fallback);
bool read_boolean(JsonReader& r, const nlohmann::json& j, const std::string& path, const LevelKey& key,
                  bool fallback);
// A choice key: the index of the value in key.choices, `fallback` when missing or invalid.
std::size_t read_choice_index(JsonReader& r, const nlohmann::json& j, const std::string& path,
                              const LevelKey& key, std::size_t fallback);

// A gravity [x, y], each component in the range of the table's gravity.x and gravity.y.
Vec2 read_gravity(JsonReader& r, const nlohmann::json& j, const std::string& path, const char* key,
                  Vec2 fallback, bool required = false);

}  // namespace tire

// The readers of the level's pieces, shared by the level loader and by script actions that carry
// a tire or a prop (spawn_tire, spawn_prop): one definition of every key, unit, default and range.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "tire/io/json_reader.h"
#include "tire/rigid/prop_spec.h"
#include "tire/tire/parameters.h"
#include "tire/tire/tire_spec.h"

namespace tire {

TireSpec read_tire(JsonReader& r, const nlohmann::json& j, const std::string& path);
PropSpec read_prop(JsonReader& r, const nlohmann::json& j, const std::string& path);

// A parameter of the table (tire/parameters.h) at its field in `j`, with the row's range and unit.
double read_parameter(JsonReader& r, const nlohmann::json& j, const std::string& path, ParamId id,
                      double fallback, bool required = false);
int read_integer_parameter(JsonReader& r, const nlohmann::json& j, const std::string& path, ParamId id,
                           int fallback, bool required = false);
// A gravity [x, y], each component in the range of the table's gravity.x and gravity.y.
Vec2 read_gravity(JsonReader& r, const nlohmann::json& j, const std::string& path, const char* key,
                  Vec2 fallback, bool required = false);

}  // namespace tire

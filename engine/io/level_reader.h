// The readers of the level's pieces, shared by the level loader and by script actions that carry
// a tire or a prop (spawn_tire, spawn_prop): one definition of every key, unit, default and range.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "tire/io/json_reader.h"
#include "tire/rigid/prop_spec.h"
#include "tire/tire/tire_spec.h"

namespace tire {

TireSpec read_tire(JsonReader& r, const nlohmann::json& j, const std::string& path);
PropSpec read_prop(JsonReader& r, const nlohmann::json& j, const std::string& path);

}  // namespace tire

// Reads a level's script keys ("regions", "goal", "time_limit", "counters", "triggers") from the
// level's root object, with every problem reported by its JSON path in one pass.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tire/io/json_reader.h"
#include "tire/script/script_spec.h"
#include "tire/tire/parameters.h"

namespace tire {

// Reads the script keys of `level_doc` (the level's root object; its other keys are left to the
// level reader). `prop_names` are the names of the level's props: a trigger or action naming a
// prop must name one of them or one that a spawn_prop action of the script spawns.
ScriptSpec read_script(JsonReader& r, const nlohmann::json& level_doc,
                       const std::vector<std::string>& prop_names);

// The keys a `set` action may change: the parameter table's rows a script may set, the solver's by
// their key, then each tire row as "player.<key>", then each as "tires.<key>".
struct SettableKey {
  std::string key;
  const Parameter* parameter;
};
const std::vector<SettableKey>& settable_keys();

}  // namespace tire

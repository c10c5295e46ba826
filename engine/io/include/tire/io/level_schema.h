// levels/schema.json, generated from the parameter table (tire/parameters.h) for the parts the
// table decides: the numeric keys of the solver, of a tire and of its compliances, the gravity
// components (the "acceleration" definition), and the keys and value ranges of the script's `set`
// action. Everything else in the schema (props, regions, triggers, ...) is written by hand and
// passes through unchanged; the whole file is laid out one way (format_json).
//
//   tirectl schema --write levels/schema.json   rewrites it after the table changed
//   tirectl schema --check levels/schema.json   what the test runs: exit 1 while they differ
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "tire/math/numbers.h"

namespace tire {

struct SchemaGeneration {
  std::optional<std::string> text;  // the schema to commit
  std::string error;                // why there is none: `current` is not the level schema
};

// `current` (the committed schema's text) with the table's parts rewritten from the table.
SchemaGeneration generate_level_schema(const std::string& current);

// The layout of the generated schema: two-space indents, an object or array on one line when it
// fits in 100 columns, numbers as short as they read back exactly ("1e-6", not "1e-06").
std::string format_json(const nlohmann::ordered_json& value);

// A range as the schema's descriptions write it: "[0.0001, 0.1]", "(0, 10⁶]".
std::string range_for_docs(const Range& range);

// A parameter's description as people read it (the schema, the tuning panel's tooltips): its
// "{range}" replaced by the range, written as range_for_docs writes it.
std::string described(const char* description, const Range& range);

}  // namespace tire

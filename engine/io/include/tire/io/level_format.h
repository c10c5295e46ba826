// The level format described, for editors and tools: the keys a level file holds (types, units,
// defaults, ranges, meanings), the tunable parameters (who may set each, its range and default),
// the material presets, and the layout and generation of levels/schema.json. Read-only views of
// the engine's own tables (engine/io/level_keys.cpp, tire/parameters.h): the level reader, the
// script reader, World::set_parameter and the schema read the same rows.
//
// The keys of a level file are one table: for each kind of object a level holds, its keys in the
// order levels/README.md lists them. Everything that needs a fact about a level key takes it from
// here: the level and script readers (which keys an object may have, their ranges and choices), the
// editor's property panel (what it lists for a selection, its bounds and tooltips) and the editor's
// save (keys written in this order). Numeric keys of the solver, a tire and its compliance come
// from the parameter table, which stays their one source: their rows here name it.
//
// levels/schema.json is generated from the parameter table for the parts the table decides: the
// numeric keys of the solver, of a tire and of its compliances, the gravity components (the
// "acceleration" definition), and the keys and value ranges of the script's `set` action.
// Everything else in the schema (props, regions, triggers, ...) is written by hand and passes
// through unchanged; the whole file is laid out one way (format_json).
//
//   tirectl schema --write levels/schema.json   rewrites it after the table changed
//   tirectl schema --check levels/schema.json   what the test runs: exit 1 while they differ
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tire/math/numbers.h"

namespace tire {

// The kinds of object a level file holds, each a section of levels/README.md (regions:
// levels/SCRIPTING.md).
enum class LevelObject {
  root,
  solver,
  tire,
  compliance,
  obstacle,
  prop,
  path,
  region,
  budgets,
  bounds,
  medals,
  vehicle,  // levels/README.md "Vehicles": a chassis on wheels
  chassis,  // a vehicle's chassis: a dynamic prop's keys
  wheel,    // a vehicle's wheel: its axle and a tire's material keys
  head      // the driver's head, in the chassis' frame
};
inline constexpr std::size_t kLevelObjects = static_cast<std::size_t>(LevelObject::head) + 1;

enum class KeyType {
  number,   // a finite number in `range`
  integer,  // a whole number in `range`
  vec2,     // [x, y], each in `range`
  points,   // an array of [x, y], each coordinate in `range`
  boolean,
  choice,  // one of `choices`
  string,  // at most range.max characters
  object,  // a nested object (LevelObject `nested`), or the script's counters (no `nested`)
  array,   // an array of objects (LevelObject `nested`), or of scripts' entries (no `nested`)
};

struct LevelKey {
  std::string key;  // as written in the file: "density"
  KeyType type = KeyType::number;
  Range range{0.0, 0.0};  // also, for an array or the counters: at most range.max entries
  std::string unit;       // as the reference page writes it: "m", "kg/m²", "" for none
  // The value a missing key takes, as JSON; null when the key is required, has no fixed default
  // (it follows another key, or depends on the shape) or is a nested object or array.
  nlohmann::json default_value;
  std::vector<std::string> choices;  // KeyType::choice, in the reference page's order
  bool required = false;             // required whenever the object is present (a shape's key: and
                                     // the prop has one of its `shapes`)
  // Prop keys that belong to some shapes only: the shapes, e.g. {"polygon", "chain"}; empty: all.
  std::vector<std::string> shapes;
  // The parameter table's key this key is read through ("tires.friction"), "" for none.
  std::string_view parameter;
  std::optional<LevelObject> nested;  // KeyType::object / array of objects
  std::string description;            // one line, for tooltips

  // KeyType::points: how many points, per shape where that differs (a prop's `points`: polygon,
  // chain); one entry with no shape where it does not (a path's `waypoints`).
  struct PointCount {
    std::string shape;  // "" for any
    std::size_t min = 0;
    std::size_t max = 0;
  };
  std::vector<PointCount> point_counts;
};

// The shortest length of a prop (m): a box's side, a circle's radius, a chain's thickness, the
// distance between neighbouring points. Box2D welds vertices closer than its linear slop.
inline constexpr double kMinPropLength = 0.01;

// The keys of one kind of object, in the reference page's order.
std::span<const LevelKey> level_keys(LevelObject object);

// One key of an object, or nullptr when the object has no such key.
const LevelKey* find_level_key(LevelObject object, std::string_view key);

// Whether `key` applies to a prop of shape `shape` ("box", "circle", "polygon", "chain").
bool applies_to_shape(const LevelKey& key, std::string_view shape);

// How many points a KeyType::points key takes for a prop of shape `shape` (any shape for a path's
// waypoints), or nullptr when the key takes no points for that shape.
const LevelKey::PointCount* point_count(const LevelKey& key, std::string_view shape = "");

// A row of the parameter table: a scalar number of the solver, of a tire or of the level's budgets
// that a level, a script's `set` action, a replay's `set` input or the game's tuning panel may give.
struct TunableParameter {
  // As written in scripts, replays and the panel: "solver.substeps", "tires.compliance.outer",
  // "gravity.x". A "tires." key sets every tire; "player." + the rest sets the player's tire only.
  std::string_view key;
  std::string_view unit;  // as messages print it after the range: "m/s^2"; "" for none
  Range range;
  bool integer = false;
  double default_value = 0.0;
  // The key whose value is the default instead of default_value ("tires.kinetic_friction": the
  // tire's friction); "" for a fixed default.
  std::string_view default_follows;
  std::string_view description;  // "{range}" stands where the range goes (described())
  // Who may set it.
  bool by_level = false;
  bool by_script = false;
  bool by_replay = false;
  bool by_panel = false;
  // The value is finite, in the range, and whole when the parameter is an integer.
  bool accepts(double value) const;
};

// The whole table, in its order.
std::span<const TunableParameter> tunable_parameters();
// The row a key names, or nullptr: "player.X" names the tire row "tires.X".
const TunableParameter* find_tunable_parameter(std::string_view key);

// A material preset: a named starting point for a tire's material, which a level's tire, the tuning
// panel and the editor name ("material": "balloon"); a key the tire also gives overrides the
// preset's. docs/soft-tire.md has what each measures.
struct MaterialPreset {
  std::string_view name;
  std::string_view description;
  struct Value {
    std::string_view key;  // the parameter table's: "tires.friction"
    double value = 0.0;
  };
  std::vector<Value> values;  // the tire parameters it sets, in the table's order
  // Its value of a tire parameter ("tires.friction"), or nullopt for one it leaves to the default.
  std::optional<double> value(std::string_view key) const;
};

// The presets, "standard" (TireSpec{}'s own) first.
std::span<const MaterialPreset> material_presets();
const MaterialPreset* find_material_preset(std::string_view name);

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
std::string described(std::string_view description, const Range& range);

}  // namespace tire

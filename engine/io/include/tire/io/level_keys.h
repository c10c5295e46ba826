// The keys of a level file in one table: for each kind of object a level holds, its keys in the
// order levels/README.md lists them, with each key's type, unit, default, range and meaning.
//
// Everything that needs a fact about a level key takes it from here: the level and script readers
// (which keys an object may have, their ranges and choices), the editor's property panel (what it
// lists for a selection, its bounds and tooltips) and the editor's save (keys written in this
// order). Numeric keys of the solver, a tire and its compliance come from the parameter table
// (tire/parameters.h), which stays their one source: their rows here point at it.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tire/math/numbers.h"
#include "tire/tire/parameters.h"

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
  medals
};
inline constexpr std::size_t kLevelObjects = static_cast<std::size_t>(LevelObject::medals) + 1;

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
  std::optional<ParamId> parameter;   // the parameter-table row this key is read through, if any
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

}  // namespace tire

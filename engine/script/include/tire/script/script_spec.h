// A level's script as the level describes it: named regions, named integer counters, the win and
// lose conditions, and triggers that run lists of actions. Keys, units, defaults and ranges are
// those of levels/SCRIPTING.md. Names are resolved to indices at load (regions, counters); props
// stay names, because props can be spawned and removed while the level runs.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "tire/math/geometry.h"
#include "tire/rigid/bodies.h"
#include "tire/script/script_status.h"
#include "tire/tire/tire_spec.h"

namespace tire {

// Limits on a script's size, so that a hostile level cannot make loading or a tick unbounded.
struct ScriptLimits {
  static constexpr std::size_t max_regions = 10000;
  static constexpr std::size_t max_counters = 1000;
  static constexpr std::size_t max_triggers = 10000;
  static constexpr std::size_t max_actions = 1000;  // per trigger
  static constexpr std::size_t max_name_length = 64;
  static constexpr std::size_t max_prop_name_length = 100;  // as the level reader allows
  static constexpr std::size_t max_message_length = 500;
  static constexpr double max_seconds = 86400.0;        // any time or period: one day
  static constexpr int max_counter_value = 1000000000;  // counters saturate at ±this
};

struct Counter {
  std::string name;
  int initial = 0;
};

// ---- Triggers ("when") --------------------------------------------------------------------------

// Which tires a region trigger watches.
enum class Who { player, any };

struct AtStart {};  // the first update of the level
struct AtTime {
  double at = 0.0;  // s since the level started
};
struct Every {
  double period = 1.0;       // s, > 0
  double start = 0.0;        // s, the first firing
  std::optional<int> count;  // firings in all; none: unlimited
};
// A tire's centroid crossing a region's boundary, inwards (enter) or outwards (leave).
struct RegionCrossing {
  bool entering = true;
  std::size_t region = 0;  // index into ScriptSpec::regions
  Who who = Who::player;
};
// A prop's origin entering a region.
struct PropEnters {
  std::size_t region = 0;
  std::string prop;
};
// An action changing a counter to `value`.
struct CounterReaches {
  std::size_t counter = 0;  // index into ScriptSpec::counters
  int value = 0;
};

using Condition = std::variant<AtStart, AtTime, Every, RegionCrossing, PropEnters, CounterReaches>;

// ---- Actions ("do") -----------------------------------------------------------------------------

struct SpawnTire {
  TireSpec tire;
};
struct SpawnProp {
  PropSpec prop;
};
struct RemoveProp {
  std::string prop;
};
struct SetGravity {
  Vec2 gravity;  // m/s²
};
enum class ImpulseTarget { player, all_tires, prop };
struct ApplyImpulse {
  ImpulseTarget target = ImpulseTarget::player;
  std::string prop;  // when target is prop
  Vec2 impulse;      // N·s
};
// One of the keys of kSettableKeys (script_reader.cpp): "solver.substeps", "player.friction", ...
struct SetParameter {
  std::string key;
  double value = 0.0;  // already checked against the key's range (and integral where it must be)
};
struct ControlPath {
  std::string prop;
  PathCommand command = PathCommand::start;
};
struct ShowMessage {
  std::string text;
  double seconds = 3.0;
};
struct SetCheckpoint {
  Vec2 position;  // m
};
struct ChangeCounter {
  std::size_t counter = 0;  // index into ScriptSpec::counters
  bool set = false;         // true: counter = amount; false: counter += amount
  int amount = 0;
};
struct Win {};
struct Lose {};
struct NextLevel {};

using Action = std::variant<SpawnTire, SpawnProp, RemoveProp, SetGravity, ApplyImpulse, SetParameter,
                            ControlPath, ShowMessage, SetCheckpoint, ChangeCounter, Win, Lose, NextLevel>;

struct Trigger {
  std::string name;  // optional; for messages and debugging only
  Condition when;
  // Fire at most once. Defaults: true for start, time, counter and prop_enter; false for enter,
  // leave and every (which `count` bounds instead).
  bool once = true;
  std::vector<Action> actions;  // run in this order
};

struct ScriptSpec {
  std::vector<Region> regions;
  std::optional<std::size_t> goal;   // region index: the player's centroid inside it wins
  std::optional<double> time_limit;  // s: reaching it while running loses
  std::vector<Counter> counters;     // in name order
  std::vector<Trigger> triggers;     // in file order, which is their firing order
};

}  // namespace tire

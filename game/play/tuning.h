// The live-tunable numbers of the tuning panel and how a change reaches the simulation. The keys
// are the parameter table's rows that the panel may set (tire/io/level_format.h), in the table's order;
// each slider's range lies inside its row's range. A change is always a key = value pair (a
// TuneEvent), so a replay can log and re-apply it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "input/session_input.h"
#include "tire/engine.h"
#include "tire/io/level_format.h"

namespace game {

// The parameter table's rows the panel may set, in the table's order.
const std::vector<const tire::TunableParameter*>& tuning_parameters();
// Their keys, in the same order: the order changes are emitted in.
const std::vector<std::string>& tuning_keys();

// The panel's "sleep" checkbox, SolverConfig::sleep, changed as this key = 1 (on) or 0 (off), after
// the table's keys. It is no row of the parameter table: replays do not record it (tirectl replay
// would refuse the key).
inline constexpr std::string_view kSleepKey = "solver.sleep";
// The "rolling hold" checkbox, SolverConfig::rolling_hold, carried the same way.
inline constexpr std::string_view kRollingHoldKey = "solver.rolling_hold";

struct Tuning {
  std::vector<double> values;  // one per tuning_keys(), in that order
  bool sleep = tire::SolverConfig{}.sleep;
  bool rolling_hold = tire::SolverConfig{}.rolling_hold;

  // The table's defaults.
  Tuning();
  // The values in force in a freshly loaded simulation: the player's tire (or the first one; the
  // table's defaults without tires), the solver's settings and the gravity.
  static Tuning from_simulation(const tire::Simulation& simulation);

  // Sets the value a key names (a checkbox's key: on unless 0); false for a key the panel does not
  // tune.
  bool set(std::string_view key, double value);
  bool operator==(const Tuning&) const = default;
};

// The value of `key` in `t` (a checkbox's key: 1 or 0); 0 for a key the panel does not tune.
double tuning_value(const Tuning& t, std::string_view key);

// `t` with a material preset's values (tire::material_presets()) in the keys the panel tunes:
// the compliances, material damping, friction, restitution and pressure. Kinetic friction follows
// friction, as the panel's one friction slider has it; rolling resistance is not the panel's.
Tuning with_material(Tuning t, const tire::MaterialPreset& material);
// The preset whose values `t` holds in those keys, or nullptr (the panel then shows "custom").
const tire::MaterialPreset* material_of(const Tuning& t);

// The key = value changes that turn `from` into `to`.
std::vector<TuneEvent> tuning_changes(const Tuning& from, const Tuning& to);

// Applies one change through Simulation::set_parameter (an integer key's value rounded first;
// "tires.friction" sets the kinetic friction too: the panel has one friction slider), or, for
// kSleepKey and kRollingHoldKey, Simulation::set_sleep and set_rolling_hold; then wakes every sleeping tire
// (Simulation::wake_all), as a change of the rules does. False, changing and waking nothing, for a key the
// panel does not tune or a value outside its range (a checkbox's key: other than 0 and 1).
bool apply_tuning(tire::Simulation& simulation, std::string_view key, double value);

// How the panel shows a key: its slider. The slider's range may be narrower than the table's
// range, for usability and to keep to what the solver holds without folding the tire
// (docs/tuning-limits.md), never wider (slider_range() clips it, and a test checks it).
enum class SliderScale { linear, logarithmic, exponent, integer };
struct SliderSpec {
  std::string_view key;
  const char* section;  // the panel's collapsing header
  const char* label;
  double min, max;
  SliderScale scale;
  const char* format;  // linear and logarithmic sliders
  const char* tip;
};
// The panel's sections, in the order it shows them.
const std::vector<const char*>& slider_sections();
// The slider of a tuned key; nullptr when the panel has no spec for it (it then shows a plain
// slider over the table's range, in the last section).
const SliderSpec* slider_spec(std::string_view key);
// What the slider of `p` offers: its spec's range clipped to the table's (an open end of the
// table's range moves in by a millionth of the span).
struct SliderRange {
  double min, max;
};
SliderRange slider_range(const tire::TunableParameter& p);

}  // namespace game

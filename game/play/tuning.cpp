#include "play/tuning.h"

#include <algorithm>
#include <cmath>

namespace game {

namespace {

constexpr const char* kCompliance = "Compliance (inverse stiffness)";
constexpr const char* kTire = "Tire";
constexpr const char* kWorld = "World and solver";

// The panel's presentation of each key it tunes. Which keys those are is the table's business.
// The ranges of the compliances and of the pressure are what the solver holds: at either end of any
// slider, with any other slider at either end, a tire dropped from 1.5 m and driven over a kerb
// keeps every cell between tread and rim the right way out and its tread uncrossed. Softer spokes
// or rim, stiffer air, or a pressure further from 1 fold it (docs/tuning-limits.md, measured by
// game/tests/test_tuning_limits.cpp).
constexpr SliderSpec kSliders[] = {
    {"tires.compliance.outer", kCompliance, "outer ring", 1e-8, 1e-1, SliderScale::exponent, "",
     "tread segments (m/N): larger is softer"},
    {"tires.compliance.inner", kCompliance, "inner ring", 1e-7, 1e-3, SliderScale::exponent, "",
     "rim segments (m/N)"},
    {"tires.compliance.spoke", kCompliance, "spokes", 1e-9, 1e-4, SliderScale::exponent, "",
     "sidewall spokes (m/N)"},
    {"tires.compliance.pressure", kCompliance, "pressure##c", 1e-6, 1e0, SliderScale::exponent, "",
     "the air (m^4/J): larger lets the area change more"},
    {"tires.pressure", kTire, "pressure", 0.9, 2.0, SliderScale::linear, "%.2f",
     "target area / rest area: above 1 inflates"},
    {"tires.mass_scale", kTire, "mass scale", 0.1, 10.0, SliderScale::logarithmic, "%.2f x",
     "each tire's mass times this"},
    {"tires.friction", kTire, "friction", 0.0, 3.0, SliderScale::linear, "%.2f",
     "static and kinetic friction coefficient"},
    {"tires.material_damping", kTire, "material damping", 1e-5, 1.0, SliderScale::exponent, "",
     "Kelvin-Voigt damping time (s)"},
    {"tires.restitution", kTire, "restitution", 0.0, 1.0, SliderScale::linear, "%.2f",
     "a landing tire leaves at this fraction of its landing speed; 0: the material decides"},
    {"gravity.x", kWorld, "gravity x", -30.0, 30.0, SliderScale::linear, "%.2f m/s2", "horizontal gravity"},
    {"gravity.y", kWorld, "gravity y", -30.0, 30.0, SliderScale::linear, "%.2f m/s2",
     "vertical gravity (-9.81 is Earth)"},
    {"solver.damping", kWorld, "damping", 0.0, 100.0, SliderScale::logarithmic, "%.2f 1/s",
     "solver.damping: decay rate of non-rigid motion"},
    {"solver.substeps", kWorld, "substeps", 1, 256, SliderScale::integer, "",
     "solver.substeps: the most effective accuracy knob"},
    {"solver.iterations", kWorld, "iterations", 1, 64, SliderScale::integer, "",
     "solver.iterations: constraint sweeps per substep"},
};

// The panel's checkboxes: the solver's flags they show and how the simulation takes a change.
struct Checkbox {
  std::string_view key;
  bool Tuning::*tuned;
  bool tire::SolverConfig::*config;
  void (tire::Simulation::*apply)(bool);
};
constexpr Checkbox kCheckboxes[] = {
    {kSleepKey, &Tuning::sleep, &tire::SolverConfig::sleep, &tire::Simulation::set_sleep},
    {kRollingHoldKey, &Tuning::rolling_hold, &tire::SolverConfig::rolling_hold,
     &tire::Simulation::set_rolling_hold},
};
const Checkbox* checkbox(std::string_view key) {
  for (const Checkbox& c : kCheckboxes)
    if (c.key == key) return &c;
  return nullptr;
}

std::size_t index_of(std::string_view key) {
  const auto& keys = tuning_keys();
  return static_cast<std::size_t>(std::find(keys.begin(), keys.end(), key) - keys.begin());
}

// apply_tuning's change, without the waking.
bool set_tuned(tire::Simulation& simulation, std::string_view key, double value) {
  if (const Checkbox* c = checkbox(key)) {
    if (value != 0.0 && value != 1.0) return false;
    (simulation.*c->apply)(value == 1.0);
    return true;
  }
  const tire::TunableParameter* p = tire::find_tunable_parameter(key);
  if (!p || !p->by_panel || key != p->key) return false;
  if (p->integer) value = std::round(value);
  if (p->key == "tires.friction")
    return simulation.set_parameter("tires.friction", value) &&
           simulation.set_parameter("tires.kinetic_friction", value);
  return simulation.set_parameter(key, value);
}

}  // namespace

const std::vector<const tire::TunableParameter*>& tuning_parameters() {
  static const std::vector<const tire::TunableParameter*> rows = [] {
    std::vector<const tire::TunableParameter*> out;
    for (const tire::TunableParameter& p : tire::tunable_parameters())
      if (p.by_panel) out.push_back(&p);
    return out;
  }();
  return rows;
}

const std::vector<std::string>& tuning_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> out;
    for (const tire::TunableParameter* p : tuning_parameters()) out.emplace_back(p->key);
    return out;
  }();
  return keys;
}

Tuning::Tuning() {
  for (const tire::TunableParameter* p : tuning_parameters()) values.push_back(p->default_value);
}

Tuning Tuning::from_simulation(const tire::Simulation& simulation) {
  Tuning t;
  for (std::size_t i = 0; i < t.values.size(); ++i)
    t.values[i] =
        simulation.parameter(tuning_parameters()[i]->key).value_or(tuning_parameters()[i]->default_value);
  for (const Checkbox& c : kCheckboxes) t.*c.tuned = simulation.config().*c.config;
  return t;
}

bool Tuning::set(std::string_view key, double value) {
  if (const Checkbox* c = checkbox(key)) {
    this->*c->tuned = value != 0.0;
    return true;
  }
  const std::size_t i = index_of(key);
  if (i == values.size()) return false;
  values[i] = value;
  return true;
}

namespace {
// The keys of a preset the panel tunes; every preset sets each of them.
constexpr std::string_view kMaterialKeys[] = {
    "tires.compliance.outer", "tires.compliance.inner", "tires.compliance.spoke", "tires.compliance.pressure",
    "tires.material_damping", "tires.friction",         "tires.restitution",      "tires.pressure",
};
double value_in(const tire::MaterialPreset& m, std::string_view key) { return m.value(key).value_or(0.0); }
}  // namespace

Tuning with_material(Tuning t, const tire::MaterialPreset& material) {
  for (const std::string_view key : kMaterialKeys) t.set(key, value_in(material, key));
  return t;
}

const tire::MaterialPreset* material_of(const Tuning& t) {
  for (const tire::MaterialPreset& m : tire::material_presets()) {
    bool all = true;
    for (const std::string_view key : kMaterialKeys) all = all && tuning_value(t, key) == value_in(m, key);
    if (all) return &m;
  }
  return nullptr;
}

double tuning_value(const Tuning& t, std::string_view key) {
  if (const Checkbox* c = checkbox(key)) return t.*c->tuned ? 1.0 : 0.0;
  const std::size_t i = index_of(key);
  return i < t.values.size() ? t.values[i] : 0.0;
}

std::vector<TuneEvent> tuning_changes(const Tuning& from, const Tuning& to) {
  std::vector<TuneEvent> out;
  const auto& keys = tuning_keys();
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (from.values.at(i) != to.values.at(i)) out.push_back({keys[i], to.values[i]});
  for (const Checkbox& c : kCheckboxes)
    if (from.*c.tuned != to.*c.tuned) out.push_back({std::string(c.key), to.*c.tuned ? 1.0 : 0.0});
  return out;
}

bool apply_tuning(tire::Simulation& simulation, std::string_view key, double value) {
  if (!set_tuned(simulation, key, value)) return false;
  // No sleeping island can tell whether it still rests under the new rules, and turning sleep off
  // must leave no tire asleep.
  simulation.wake_all();
  return true;
}

const std::vector<const char*>& slider_sections() {
  static const std::vector<const char*> sections{kCompliance, kTire, kWorld};
  return sections;
}

const SliderSpec* slider_spec(std::string_view key) {
  for (const SliderSpec& s : kSliders)
    if (s.key == key) return &s;
  return nullptr;
}

SliderRange slider_range(const tire::TunableParameter& p) {
  const double inset = (p.range.max - p.range.min) * 1e-6;
  const double lo = p.range.min + (p.range.min_open ? inset : 0.0);
  const double hi = p.range.max - (p.range.max_open ? inset : 0.0);
  const SliderSpec* s = slider_spec(p.key);
  if (!s) return {lo, hi};
  return {std::clamp(s->min, lo, hi), std::clamp(s->max, lo, hi)};
}

}  // namespace game

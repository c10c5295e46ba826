// The parameter table and the material presets (tire/parameters.h) as tire/io/level_format.h
// describes them: each row read from the one table, once, when first asked for.
#include <algorithm>
#include <vector>

#include "tire/io/level_format.h"
#include "tire/tire/parameters.h"

namespace tire {

namespace {

TunableParameter describe(const Parameter& p) {
  TunableParameter d;
  d.key = p.key;
  d.unit = p.unit;
  d.range = p.range;
  d.integer = p.integer;
  d.default_value = p.default_value;
  d.default_follows = p.default_follows ? p.default_follows : "";
  d.description = p.description;
  d.by_level = p.may(by_level);
  d.by_script = p.may(by_script);
  d.by_replay = p.may(by_replay);
  d.by_panel = p.may(by_panel);
  return d;
}

MaterialPreset describe(const Material& m) {
  MaterialPreset d;
  d.name = m.name;
  d.description = m.description;
  for (const Parameter& p : parameters())
    if (const std::optional<double> v = m.value_of(p.id)) d.values.push_back({p.key, *v});
  return d;
}

}  // namespace

std::span<const TunableParameter> tunable_parameters() {
  static const std::vector<TunableParameter> rows = [] {
    std::vector<TunableParameter> out;
    for (const Parameter& p : parameters()) out.push_back(describe(p));
    return out;
  }();
  return rows;
}

const TunableParameter* find_tunable_parameter(std::string_view key) {
  const Parameter* p = find_parameter(key);
  return p ? &tunable_parameters()[static_cast<std::size_t>(p->id)] : nullptr;
}

bool TunableParameter::accepts(double value) const { return find_parameter(key)->accepts(value); }

std::optional<double> MaterialPreset::value(std::string_view key) const {
  const auto it = std::find_if(values.begin(), values.end(), [&](const Value& v) { return v.key == key; });
  return it == values.end() ? std::nullopt : std::optional<double>(it->value);
}

std::span<const MaterialPreset> material_presets() {
  static const std::vector<MaterialPreset> presets = [] {
    std::vector<MaterialPreset> out;
    for (const Material& m : kMaterials) out.push_back(describe(m));
    return out;
  }();
  return presets;
}

const MaterialPreset* find_material_preset(std::string_view name) {
  const Material* m = find_material(name);
  return m ? &material_presets()[static_cast<std::size_t>(m - kMaterials.data())] : nullptr;
}

}  // namespace tire

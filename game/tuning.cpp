#include "tuning.h"

#include <cmath>

namespace game {

namespace {

struct Field {
  const char* key;
  double Tuning::*member;
};

constexpr Field kFields[] = {
    {"tires.compliance.outer", &Tuning::compliance_outer},
    {"tires.compliance.inner", &Tuning::compliance_inner},
    {"tires.compliance.spoke", &Tuning::compliance_spoke},
    {"tires.compliance.pressure", &Tuning::compliance_pressure},
    {"tires.pressure", &Tuning::pressure},
    {"tires.mass_scale", &Tuning::mass_scale},
    {"tires.friction", &Tuning::friction},
    {"gravity.x", &Tuning::gravity_x},
    {"gravity.y", &Tuning::gravity_y},
    {"solver.damping", &Tuning::solver_damping},
    {"tires.material_damping", &Tuning::material_damping},
    {"solver.substeps", &Tuning::substeps},
    {"solver.iterations", &Tuning::iterations},
};

}  // namespace

Tuning Tuning::from_world(const tire::World& world) {
  Tuning t;
  tire::TireSpec spec;
  if (const tire::Tire* p = world.player()) spec = p->spec;
  else if (!world.tires().empty()) spec = world.tires().front().spec;
  t.compliance_outer = spec.compliance.outer;
  t.compliance_inner = spec.compliance.inner;
  t.compliance_spoke = spec.compliance.spoke;
  t.compliance_pressure = spec.compliance.pressure;
  t.pressure = spec.pressure;
  t.mass_scale = 1.0;
  t.friction = spec.friction;
  t.gravity_x = world.gravity().x;
  t.gravity_y = world.gravity().y;
  t.solver_damping = world.config().damping;
  t.material_damping = spec.material_damping;
  t.substeps = world.config().substeps;
  t.iterations = world.config().iterations;
  return t;
}

bool Tuning::set(std::string_view key, double value) {
  for (const Field& f : kFields)
    if (key == f.key) {
      this->*f.member = value;
      return true;
    }
  return false;
}

const std::vector<std::string>& tuning_keys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const Field& f : kFields) k.emplace_back(f.key);
    return k;
  }();
  return keys;
}

double tuning_value(const Tuning& t, std::string_view key) {
  for (const Field& f : kFields)
    if (key == f.key) return t.*f.member;
  return 0.0;
}

std::vector<TuneEvent> tuning_changes(const Tuning& from, const Tuning& to) {
  std::vector<TuneEvent> out;
  for (const Field& f : kFields)
    if (from.*f.member != to.*f.member) out.push_back({f.key, to.*f.member});
  return out;
}

bool apply_tuning(tire::World& world, std::string_view key, double value) {
  if (key == "gravity.x") {
    world.set_gravity({value, world.gravity().y});
    return true;
  }
  if (key == "gravity.y") {
    world.set_gravity({world.gravity().x, value});
    return true;
  }
  if (key == "tires.friction")
    return world.set_parameter("tires.friction", value) && world.set_parameter("tires.kinetic_friction", value);
  if (key == "solver.substeps" || key == "solver.iterations") value = std::round(value);
  return world.set_parameter(key, value);
}

}  // namespace game

// The live-tunable numbers of the tuning panel, in one struct, and how a change reaches the World.
// A change is always a key = value pair (a TuneEvent), so a replay can log and re-apply it.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "session_input.h"
#include "tire/world/world.h"

namespace game {

struct Tuning {
  // XPBD compliances of every tire (m/N; the pressure one m⁴/J).
  double compliance_outer = 1e-6;
  double compliance_inner = 1e-7;
  double compliance_spoke = 1e-6;
  double compliance_pressure = 1e-5;
  double pressure = 1.0;          // target area / rest area
  double mass_scale = 1.0;        // each tire's mass = its spawn mass × this
  double friction = 0.9;          // static and kinetic
  double gravity_x = 0.0;         // m/s²
  double gravity_y = -9.81;       // m/s²
  double solver_damping = 0.0;    // 1/s
  double material_damping = 5e-3; // s
  double substeps = 8;            // integral
  double iterations = 1;          // integral

  // The values in force in a freshly loaded world: the player's tire (or a default one) and the
  // solver's settings.
  static Tuning from_world(const tire::World& world);

  // Sets the field a key names; false for an unknown key.
  bool set(std::string_view key, double value);
};

// The keys, in the order changes are emitted.
const std::vector<std::string>& tuning_keys();
double tuning_value(const Tuning& t, std::string_view key);

// The key = value changes that turn `from` into `to`.
std::vector<TuneEvent> tuning_changes(const Tuning& from, const Tuning& to);

// Applies one change to the world: World::set_parameter for the engine's keys ("tires.mass_scale"
// scales each tire's spawn mass), both frictions for "tires.friction", World::set_gravity for
// "gravity.x" and "gravity.y". False for an unknown key.
bool apply_tuning(tire::World& world, std::string_view key, double value);

}  // namespace game

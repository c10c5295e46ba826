// Everything that defines a tire as built: the level's tire object, with SI units and defaults.
#pragma once

#include <cstdint>

#include "tire/math/geometry.h"

namespace tire {

// A tire's id in its world: given by the world when the tire is added, never reused.
using TireId = std::uint32_t;

// Which particle pairs the spokes join: "radial" joins inner i to outer i only (the prototype's
// layout; the rings can shear against each other at first order), "cross" adds the diagonals
// inner i – outer i±1, which gives the sidewall shear stiffness.
enum class SpokePattern { radial, cross };

// The default is a stiff tire (it sags 0.1 mm); the "soft" material preset (parameters.h) is the
// soft tire of docs/soft-tire.md.
struct TireCompliance {
  double outer = 1e-6;     // outer ring (tread) distance constraints (m/N)
  double inner = 1e-7;     // inner ring (rim) distance constraints (m/N)
  double spoke = 1e-6;     // spokes, the sidewall (m/N)
  double pressure = 1e-5;  // area constraint, the air (m⁴/J in 2D)
};

struct TireSpec {
  Vec2 position{0.0, 0.5};  // hub position at spawn (m)
  Vec2 velocity{0.0, 0.0};  // initial velocity (m/s)
  double angle = 0.0;       // rotation (rad, CCW) from the pose with one tread segment flat at the bottom
  double angular_velocity = 0.0;  // initial spin (rad/s, counter-clockwise positive)
  double outer_radius = 0.5;      // R (m)
  double inner_radius = 0.3;      // r (m), r < R
  int segments = 28;              // N particles per ring
  double mass = 10.0;             // whole tire (kg), shared equally by the 2N particles
  double friction = 0.9;          // static friction coefficient μ_s
  double kinetic_friction = 0.9;  // kinetic friction coefficient μ_k
  // The air: the area constraint's target is pressure · rest area, so above 1 the air pushes out
  // with (pressure · A₀ − A)/α per metre of tread and carries load as a real tire's does; below 1
  // it would pull the tread in.
  double pressure = 1.0;
  TireCompliance compliance;
  SpokePattern spokes = SpokePattern::cross;
  // Material damping time τ (s): a dashpot beside every constraint's spring (Kelvin–Voigt rubber),
  // resisting its rate of change with a force τ·k·dC/dt. It is the rubber's hysteresis: it takes
  // energy out of bounces and vibrations. 0 is perfectly elastic.
  double material_damping = 5e-3;
  // Rolling resistance coefficient C_rr: a grounded tire feels a moment C_rr·N·R against its spin
  // (N the contact normal force), as in vehicle dynamics (SAE J2452); car tires are near 0.01.
  double rolling_resistance = 0.01;
  // Restitution e: a tire that lands at a normal speed v (over restitution_threshold) leaves that
  // surface at e·v, whatever its elasticity and the substeps made of the impact (the global step
  // damps a stiff tire's ringing as backward Euler does, more at fewer substeps). 0 leaves the
  // rebound to the tire's elasticity and material_damping.
  double restitution = 0.0;
  bool player = false;
  double drive_acceleration = 12.0;  // tangential acceleration of the tread at full steer (m/s²)
  double jump_speed = 5.0;           // upward speed a jump adds (m/s)
  double max_speed = 15.0;           // cap on the hub's horizontal speed and the tread's drive speed (m/s)
  // Inflating and deflating (TickInput::inflate): the pressure moves at inflate_rate (per second)
  // between min_pressure and max_pressure.
  double inflate_rate = 0.3;
  double min_pressure = 1.0;  // deflated: the air carries nothing
  double max_pressure = 1.3;
};

}  // namespace tire

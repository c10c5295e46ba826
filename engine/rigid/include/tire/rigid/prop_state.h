// A prop's motion as Box2D has it between ticks.
#pragma once

#include "tire/math/pose.h"
#include "tire/math/vec2.h"

namespace tire {

// A prop's id in its world: its index in the order the props were added (a removed prop keeps its
// id, dead).
using PropId = std::uint32_t;

// A live prop as Box2D holds it between ticks (its floats widened to double): what a test or tool
// measures (energy, finiteness), without reaching into Box2D.
struct PropState {
  Pose pose;                      // body origin and angle
  Vec2 center;                    // centre of mass, world
  Vec2 velocity;                  // of the centre of mass (m/s)
  double angular_velocity = 0.0;  // rad/s, counter-clockwise
  double mass = 0.0;              // kg; 0 for a static or kinematic prop
  double inertia = 0.0;           // about the centre of mass (kg m²); 0 for a static or kinematic prop
  bool awake = false;             // Box2D has not put it to sleep
};

}  // namespace tire

// The rigid bodies of a world as built and as they move: static box obstacles (Obstacle), Box2D
// props as the level describes them (PropSpec) and a prop's motion between ticks (PropState).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tire/math/geometry.h"

namespace tire {

// A static axis-aligned obstacle with exact minimal-overlap contact.
struct Obstacle {
  Aabb box;
  double friction = 1.0;  // mixed with the tire's as sqrt(μ_tire · μ_obstacle), as Box2D does
};

// A rigid level prop as the level describes it: a Box2D body with one shape.
enum class PropShape { box, circle, polygon, chain };
enum class PropType { static_body, dynamic_body, kinematic_body };
enum class PathMode { once, loop, ping_pong };
enum class PathCommand { start, stop, reverse };  // what a script can tell a kinematic path

// A kinematic prop's scripted motion: along waypoints at a speed, and/or spinning at a rate.
struct KinematicPath {
  std::vector<Vec2> waypoints;  // world positions (m) the prop's origin visits in order
  double speed = 1.0;           // m/s along the path
  PathMode mode = PathMode::loop;
  bool running = true;  // scripts start, stop and reverse it
};

struct PropSpec {
  std::string name;  // optional; scripts and tirectl's report refer to props by name
  PropShape shape = PropShape::box;
  PropType type = PropType::static_body;
  Vec2 position;             // body origin (m)
  double angle = 0.0;        // rad
  Vec2 size{1.0, 1.0};       // box: full width and height (m)
  double radius = 0.5;       // circle (m)
  std::vector<Vec2> points;  // polygon: convex, CCW, ≤ 8, local; chain: polyline, local
  bool loop = false;         // chain: closed
  double thickness = 0.5;    // chain: how far behind its line a particle still counts as inside (m)
  double density = 1.0;      // kg/m² (dynamic)
  double friction = 0.5;
  double restitution = 0.0;
  Vec2 velocity;                  // initial linear velocity (m/s)
  double angular_velocity = 0.0;  // initial (dynamic) or constant (kinematic spin) rate, rad/s
  KinematicPath path;             // kinematic only; empty waypoints: no path
};

// A prop's motion as Box2D has it between ticks.
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

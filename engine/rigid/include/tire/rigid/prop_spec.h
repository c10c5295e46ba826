// A rigid level prop as the level describes it: a Box2D body with one shape.
#pragma once

#include <string>
#include <vector>

#include "tire/math/vec2.h"

namespace tire {

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

}  // namespace tire

// Debug drawing, as Box2D's b2Draw: the game (or a test) implements DebugDraw, sets its flags and
// hands it to World::debug_draw, which walks the engine's own state (rings, spokes, contacts, broad
// phase) and calls back with plain shapes in world units (metres). Only the engine reads the
// solver's scratch; the drawer never sees it, and chooses colours and widths from each shape's
// DebugShape.
#pragma once

#include <cstdint>
#include <span>

#include "tire/math/geometry.h"
#include "tire/world/views.h"

namespace tire {

// What a shape stands for: one kind may come as several primitives (a contact is a point and a
// vector), so the drawer styles by (primitive, kind).
enum class DebugShape : std::uint8_t {
  tread,            // the outer ring (polygon) and its particles (points)
  rim,              // the inner ring (polygon) and its particles (points)
  spoke,            // a spoke constraint between the rings (segment)
  contact,          // a particle touching an obstacle or prop (point) and the surface normal (vector, unit)
  velocity,         // a tire's hub velocity (vector, m/s, at the hub)
  tire_bounds,      // box around a tire's particles
  prop_bounds,      // box around a live prop's shape
  obstacle_bounds,  // a static box obstacle
  candidate_obstacle,  // an obstacle a tire's broad phase returned this tick (box; segment from the hub)
  candidate_prop,      // a prop a tire's broad phase returned this tick (box; segment from the hub)
  pair,                // a particle of a tire's narrow-phase pairs this substep (point)
  head,  // a vehicle driver's head, the circle a level watches (polygon), joined to its chassis'
         // centre of mass (segment); Simulation::debug_draw reports it with the structure
};

class DebugDraw {
 public:
  // What World::debug_draw walks; or them together. Zero draws nothing.
  enum Flag : unsigned {
    structure = 1u << 0,   // tread and rim rings, their particles, the spokes
    contacts = 1u << 1,    // particles touching an obstacle or prop, with the surface normal
    velocities = 1u << 2,  // each tire's hub velocity
    bounds = 1u << 3,      // boxes around tires and live props; the obstacles
    broadphase = 1u << 4,  // each tire's candidate obstacles and props, and its narrow-phase pairs
  };

  virtual ~DebugDraw() = default;

  unsigned flags() const { return flags_; }
  void set_flags(unsigned flags) { flags_ = flags; }

  virtual void segment(Vec2 a, Vec2 b, DebugShape kind) = 0;
  // A closed ring through `points` (the last joins the first).
  virtual void polygon(std::span<const Vec2> points, DebugShape kind) = 0;
  virtual void point(Vec2 p, DebugShape kind) = 0;
  // A vector quantity `v` attached at `at`, in its own unit (a unit normal, a velocity in m/s): the
  // drawer picks the scale that turns it into a length on screen.
  virtual void vector(Vec2 at, Vec2 v, DebugShape kind) = 0;
  virtual void box(const Aabb& box, DebugShape kind) = 0;

  // Where to draw tire t's particles (2N, as t.positions lays them out): by default where they
  // are; a game that draws between ticks returns them blended. The span is read before the next
  // call. A tire's hub, contacts and pairs are drawn at these positions too.
  virtual std::span<const Vec2> tire_positions(const TireView& t);
  // Where to draw live prop `prop`, whose pose is `now`: by default there.
  virtual Pose prop_pose(std::uint32_t /*prop*/, const Pose& now) { return now; }

 private:
  unsigned flags_ = 0;
};

}  // namespace tire

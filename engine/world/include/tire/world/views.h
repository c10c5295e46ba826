// What a world shows of its tires and props between ticks: read-only views, copied out or pointing
// into the world's own arrays (valid until the next step, add or remove).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "tire/math/geometry.h"
#include "tire/rigid/bodies.h"
#include "tire/tire/tick_contacts.h"
#include "tire/tire/tire_spec.h"

namespace tire {

struct TireView {
  TireId id = 0;
  bool player = false;
  bool asleep = false;
  bool grounded = false;    // a tread particle touched ground in the last substep
  Vec2 centroid;            // of all particles: the hub (m)
  Vec2 velocity;            // of the centroid (m/s)
  double spin = 0.0;        // angular velocity about the hub (rad/s, counter-clockwise)
  double area_ratio = 0.0;  // the tread's area over its rest area
  double pressure = 0.0;    // the pressure in force (TireSpec::pressure, moved by inflating)
  std::uint32_t segments = 0;
  // The particles' positions: the tread's `segments` counter-clockwise, then the rim's.
  std::span<const Vec2> positions;
  TickContacts contacts;  // what its contacts did over the last tick
};

// The world's mechanical energy between ticks, and what was brought into it from outside since it
// was made: the bodies added (less those removed), the commands that changed its energy, and the
// work of the tires' drives, jumps and inflating. The energy less what came in rises only by what
// nothing brought: a contact making energy, or the work of kinematic props and grabs, which are
// not counted (docs/at-rest.md, "The energy watch's books").
struct EnergyView {
  double kinetic = 0.0;        // J
  double gravitational = 0.0;  // J, zero at the origin
  double elastic = 0.0;        // J, held by the tires' compliant constraints
  double brought_in = 0.0;     // J
  double total() const { return kinetic + gravitational + elastic; }
};

// How far tires are inside each other: the deepest tread particle of one tire inside another's
// tread polygon (docs/at-rest.md).
struct TireOverlap {
  double depth = 0.0;  // how far the particle is from the other's tread, inside it (m); 0 for none
  TireId tire = 0;     // the tire whose particle it is
  TireId inside = 0;   // the tire it is inside
};

struct PropView {
  PropId id = 0;
  PropType type = PropType::static_body;
  PropShape shape = PropShape::box;
  bool alive = false;     // a removed prop stays, dead
  std::string_view name;  // as the level names it; "" for none
  PropState state;
};

}  // namespace tire

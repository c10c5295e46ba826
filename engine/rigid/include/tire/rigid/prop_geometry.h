// Where a particle touches a prop's shape. Shapes are kept in the prop's own frame, in doubles;
// a particle's path over the substep is brought into that frame (with the prop's pose at the
// start and at the end of the substep, so a moving prop is handled by its relative motion), and
// the contact comes back out in world coordinates.
//
// Every test is exact for points (no margin, like the box obstacles) and swept: a particle that
// entered a shape during the substep leaves through the side it came in by.
#pragma once

#include <optional>
#include <vector>

#include "tire/math/geometry.h"
#include "tire/rigid/bodies.h"
#include "tire/rigid/edge_tree.h"
#include "tire/xpbd/contact.h"

namespace tire {

struct PropGeometry {
  PropShape shape = PropShape::box;
  std::vector<Vec2> vertices;  // polygon (box too): convex, CCW; chain: the polyline
  // Polygon: outward normal of edge i (v_i → v_i+1); chain: normal of edge i (out of the solid).
  std::vector<Vec2> normals;
  double radius = 0.0;     // circle
  double thickness = 0.0;  // chain: how far behind the line still counts as inside (m)
  bool loop = false;       // chain
  EdgeTree edges;          // chain: which edges are near a point, each widened by the thickness
  Aabb bounds;             // the shape's box in its frame (a chain's widened by its thickness)

  // The shape of a prop in its frame. Box: centred rectangle of spec.size. Chain: one-sided, solid
  // on the right of the direction its points go (a closed chain: solid inside, either winding).
  static PropGeometry from_spec(const PropSpec& spec);

  const Aabb& local_bounds() const { return bounds; }
};

// The contact of a particle that moved from `from` to `to` (both local coordinates), as a local
// normal and depth; nullopt when it does not touch. `held`: a surface held the particle at the end
// of the substep before. A one-sided chain pushes out a particle that starts inside it only if so:
// one that was not came in from behind the solid, and passes.
std::optional<SurfaceContact> local_contact(const PropGeometry& g, Vec2 from, Vec2 to, bool held = true);

// True when a circle (its centre in the shape's frame) touches or overlaps the shape: a chain by
// its line alone (either side), a closed chain also inside.
bool circle_touches(const PropGeometry& g, Vec2 center, double radius);

// True when a polygon's points are convex and counter-clockwise (no three in a line).
bool is_convex_ccw(const std::vector<Vec2>& points);

}  // namespace tire

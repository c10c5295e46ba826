// The changes the editor makes to a level's JSON, each a function from the document to the changed
// document (LevelDocument::change judges the result). Numbers are written tidy: whole numbers as
// integers, others to 12 significant digits, so that 0.1 + 0.2 is saved as 0.3.
#pragma once

#include "level_items.h"

namespace editor {

// `v` as the editor writes a number.
Json number(double v);
// A point [x, y] (coordinates, sizes, velocities), each to the nanometre.
Json vec2(Vec2 v);

// Moves the selected items (and their paths) and points by `delta` (m). A point whose item is
// selected too moves with its item.
Json moved(const Json& doc, const Selection& selection, Vec2 delta);
// Deletes the selected items and points (a vehicle's axle point: its wheel; its head point: the head).
Json removed(const Json& doc, const Selection& selection);
// Appends copies of the selected items moved by `offset`, with fresh names; `copies` gets them.
Json duplicated(const Json& doc, const Selection& selection, Vec2 offset, Selection& copies);
// Appends `item` to the array of `kind` (made when missing); `added` names it.
Json with_item(const Json& doc, ItemKind kind, Json item, Pick& added);

// A box-shaped item (obstacle, region, box prop, a vehicle's box chassis) with one corner at `corner_world`
// and the opposite corner where it was. Corners count counter-clockwise from the lower left.
Json with_corner(const Json& doc, const Pick& item, int corner, Vec2 corner_world);
// A circle prop's (or circle chassis') radius, or a tire's (its rim scaled with it).
Json with_radius(const Json& doc, const Pick& item, double radius);
// A prop's angle, or a vehicle's chassis' (rad; its wheels and head turn with it).
Json with_angle(const Json& doc, const Pick& item, double angle);
// One point (a polygon's or chain's vertex, a waypoint, a vehicle's axle point or head) at `world`.
Json with_point(const Json& doc, const Pick& point, Vec2 world);
// A new point inserted at index `point.point` of its set, at `world`.
Json with_point_inserted(const Json& doc, const Pick& point, Vec2 world);

// A waypoint at `world` appended to a prop's path; the prop becomes kinematic and gets a path when
// it has none. `added` names the waypoint.
Json with_waypoint(const Json& doc, const Pick& prop, Vec2 world, Pick& added);

// A vehicle as the editor adds it: a car like tests/levels/vehicle-car.json's, a 1.6 × 0.3 m chassis
// whose origin is at `at` on two wheels of radius 0.35 m (the rear one driven, the front one sprung),
// and a driver's head; the player's when `player`.
Json default_vehicle(Vec2 at, bool player);
// Whether any tire or vehicle of the level says "player": true.
bool names_a_player(const Json& doc);

// A name for a new item of `kind`, "base" or "base2", "base3", ..., that no item of it has.
std::string unique_name(const Json& doc, ItemKind kind, const std::string& base);

}  // namespace editor

// What the editor can point at in a level, read straight from the level's JSON: its tires,
// obstacles, props, regions and vehicles, the points of its polygons and chains, the waypoints of
// its paths, and a vehicle's axle points (its wheels) and driver's head. Reading is lenient (a missing or
// half-typed key takes its default), so that a level the validator refuses can still be drawn and fixed.
#pragma once

#include <compare>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tire/math/geometry.h"

namespace editor {

using Json = nlohmann::ordered_json;
using tire::Vec2;

// The arrays of the level's root that hold items, in the order they are drawn (the last on top).
enum class ItemKind { obstacle, region, prop, tire, vehicle };
// The root key of each kind: "obstacles", "regions", "props", "tires", "vehicles".
const char* array_key(ItemKind kind);
// One item, for messages and the panel's title: "prop 2 (crate)".
std::string describe(const Json& doc, ItemKind kind, std::size_t index);

// Which points of an item a pick names: a polygon's or chain's points, a path's waypoints, a
// vehicle's axle points (point w: wheel w's `axle`) or its driver's head (point 0: `head.position`).
enum class PointSet { none, points, waypoints, axles, head };

// An item, or one point of an item: what a click selects.
struct Pick {
  ItemKind kind = ItemKind::obstacle;
  std::size_t index = 0;
  PointSet set = PointSet::none;
  std::size_t point = 0;
  auto operator<=>(const Pick&) const = default;
  bool is_point() const { return set != PointSet::none; }
  Pick item() const { return {kind, index}; }
};

// A selection, kept sorted and without repeats.
using Selection = std::vector<Pick>;
void select(Selection& s, const Pick& p);
bool is_selected(const Selection& s, const Pick& p);

// Lenient readers: the value at `key`, or `fallback` when it is missing or not of that type.
double number_at(const Json& j, const char* key, double fallback);
Vec2 vec2_at(const Json& j, const char* key, Vec2 fallback);
std::string string_at(const Json& j, const char* key, const std::string& fallback);

// The geometry of one item in world coordinates.
struct ItemShape {
  enum class Form { box, circle, polygon, chain };
  Form form = Form::box;
  Vec2 position;              // a prop's origin, a tire's hub, a box's centre
  double angle = 0.0;         // rad
  Vec2 half_size;             // Form::box (obstacles and regions are boxes at angle 0)
  double radius = 0.0;        // Form::circle; a tire's tread
  double inner_radius = 0.0;  // a tire's rim
  std::vector<Vec2>
      outline;        // world points: a box's corners, a circle's 32 points, a polygon's or chain's points
  bool loop = false;  // a chain's last point joins its first
  std::vector<Vec2> waypoints;  // a kinematic prop's path, world coordinates
  // A vehicle: the shape above is its chassis' (position, angle and outline), and these its parts.
  std::vector<Vec2> axles;          // each wheel's axle point, world coordinates
  std::vector<double> wheel_radii;  // each wheel's outer radius
  std::optional<Vec2> head;         // the driver's head's centre, world coordinates
  double head_radius = 0.0;
};
std::optional<ItemShape> shape_of(const Json& doc, ItemKind kind, std::size_t index);
// A prop's shape (or a vehicle's chassis', which has a prop's keys) from its JSON object.
ItemShape prop_shape(const Json& prop);

// Every point an item covers, for its bounds: its outline, waypoints, and a vehicle's wheels and head.
std::vector<Vec2> extent_points(const ItemShape& shape);

// How many items of a kind the document holds.
std::size_t count(const Json& doc, ItemKind kind);

// A prop's local point in world coordinates, and back.
Vec2 to_world(const ItemShape& prop, Vec2 local);
Vec2 to_local(const ItemShape& prop, Vec2 world);

// The item under `p` (the topmost: tires over props over regions over obstacles, later over
// earlier), within `tolerance` metres of a chain's line or a circle's edge.
std::optional<Pick> pick_item(const Json& doc, Vec2 p, double tolerance);
// The polygon or chain point, or path waypoint, within `reach` metres of `p` (the topmost prop's).
// A vehicle's axle points and head are not picked here: they are handles of a selected vehicle.
std::optional<Pick> pick_point(const Json& doc, Vec2 p, double reach);
// The items whose shapes lie wholly inside `box`.
Selection items_inside(const Json& doc, const tire::Aabb& box);
// The bounds of every item (nullopt for an empty level).
std::optional<tire::Aabb> level_extent(const Json& doc);

}  // namespace editor

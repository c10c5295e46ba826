#include "level_edits.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>

#include "tire/math/numbers.h"

namespace editor {

namespace {

double tidy(double v) {
  // 12 significant digits, as std::to_chars(general, 12) writes (its specification is printf's
  // %.12g; libc++ 14, the browser build's, has neither floating-point to_chars nor from_chars).
  char text[32];
  const int n = std::snprintf(text, sizeof text, "%.12g", v);
  if (n <= 0 || n >= static_cast<int>(sizeof text)) return v;
  return tire::parse_double(std::string_view(text, static_cast<std::size_t>(n))).value_or(v);
}

Json& item_at(Json& doc, const Pick& p) { return doc[array_key(p.kind)][p.index]; }

bool has_item(const Json& doc, const Pick& p) {
  const auto it = doc.find(array_key(p.kind));
  return it != doc.end() && it->is_array() && p.index < it->size() && (*it)[p.index].is_object();
}

const char* set_key(PointSet set) { return set == PointSet::waypoints ? "waypoints" : "points"; }

// The object whose position, angle and shape an item's handles change: a vehicle's chassis, or the
// item itself.
Json& body_of(Json& doc, const Pick& p) {
  Json& item = item_at(doc, p);
  if (p.kind != ItemKind::vehicle) return item;
  if (!item.contains("chassis") || !item["chassis"].is_object()) item["chassis"] = Json::object();
  return item["chassis"];
}

// The array a point pick indexes into, or nullptr (none for a vehicle's axles or head). A vehicle's
// points are its polygon chassis'.
Json* point_array(Json& doc, const Pick& p) {
  if (!has_item(doc, p.item()) || p.set == PointSet::axles || p.set == PointSet::head) return nullptr;
  Json& item = item_at(doc, p);
  Json* holder = &item;
  if (p.kind == ItemKind::vehicle) {
    if (p.set != PointSet::points || !item.contains("chassis") || !item["chassis"].is_object())
      return nullptr;
    holder = &item["chassis"];
  } else if (p.set == PointSet::waypoints) {
    if (!item.contains("path") || !item["path"].is_object()) return nullptr;
    holder = &item["path"];
  }
  const auto it = holder->find(set_key(p.set));
  return it != holder->end() && it->is_array() ? &*it : nullptr;
}

// The [x, y] a point pick names, or nullptr. A vehicle's axle point or head is made when missing.
Json* point_at(Json& doc, const Pick& p) {
  if (!has_item(doc, p.item())) return nullptr;
  Json& item = item_at(doc, p);
  if (p.set == PointSet::axles) {
    if (!item.contains("wheels") || !item["wheels"].is_array() || p.point >= item["wheels"].size() ||
        !item["wheels"][p.point].is_object())
      return nullptr;
    return &item["wheels"][p.point]["axle"];
  }
  if (p.set == PointSet::head) {
    if (!item.contains("head") || !item["head"].is_object()) return nullptr;
    return &item["head"]["position"];
  }
  Json* points = point_array(doc, p);
  return points && p.point < points->size() ? &(*points)[p.point] : nullptr;
}

void shift(Json& j, const char* key, Vec2 d) {
  if (j.contains(key)) j[key] = vec2(vec2_at(j, key, {}) + d);
}

void move_item(Json& doc, const Pick& p, Vec2 d) {
  Json& j = item_at(doc, p);
  switch (p.kind) {
    case ItemKind::tire: shift(j, "position", d); break;
    case ItemKind::vehicle: {
      // The wheels and the head hang in the chassis' frame: they come along.
      Json& chassis = body_of(doc, p);
      chassis["position"] = vec2(vec2_at(chassis, "position", {}) + d);
      break;
    }
    case ItemKind::obstacle:
    case ItemKind::region:
      shift(j, "min", d);
      shift(j, "max", d);
      break;
    case ItemKind::prop: {
      j["position"] = vec2(vec2_at(j, "position", {}) + d);
      if (j.contains("path") && j["path"].is_object() && j["path"].contains("waypoints") &&
          j["path"]["waypoints"].is_array())
        for (Json& w : j["path"]["waypoints"])
          if (w.is_array() && w.size() == 2 && w[0].is_number() && w[1].is_number())
            w = vec2(Vec2{w[0].get<double>(), w[1].get<double>()} + d);
      break;
    }
  }
}

}  // namespace

Json number(double v) {
  const double t = tidy(v);
  if (std::floor(t) == t && std::fabs(t) < 9.0e15) return static_cast<std::int64_t>(t);
  return t;
}

// A coordinate to the nanometre, so that a point turned into a rotated prop's frame is written
// [0, 2], not [-1.2246467991473532e-16, 2].
double coordinate(double v) { return std::round(v * 1e9) / 1e9; }

Json vec2(Vec2 v) { return Json::array({number(coordinate(v.x)), number(coordinate(v.y))}); }

Json moved(const Json& doc, const Selection& selection, Vec2 delta) {
  Json out = doc;
  for (const Pick& p : selection) {
    if (!p.is_point()) {
      if (has_item(out, p)) move_item(out, p, delta);
      continue;
    }
    if (is_selected(selection, p.item())) continue;
    const auto shape = shape_of(out, p.kind, p.index);
    Json* point = point_at(out, p);
    if (!shape || !point) continue;
    Json& q = *point;
    const Vec2 old{q.is_array() && q.size() == 2 && q[0].is_number() ? q[0].get<double>() : 0.0,
                   q.is_array() && q.size() == 2 && q[1].is_number() ? q[1].get<double>() : 0.0};
    if (p.set == PointSet::waypoints)
      q = vec2(old + delta);
    else
      q = vec2(to_local(*shape, to_world(*shape, old) + delta));
  }
  return out;
}

Json removed(const Json& doc, const Selection& selection) {
  Json out = doc;
  // From the back, so that the indices still to come stay valid.
  for (auto it = selection.rbegin(); it != selection.rend(); ++it) {
    const Pick& p = *it;
    if (p.is_point()) {
      if (is_selected(selection, p.item())) continue;
      if (p.set == PointSet::axles && has_item(out, p.item())) {
        Json& item = item_at(out, p);
        if (item.contains("wheels") && item["wheels"].is_array() && p.point < item["wheels"].size())
          item["wheels"].erase(p.point);
      } else if (p.set == PointSet::head && has_item(out, p.item())) {
        item_at(out, p).erase("head");
      } else if (Json* points = point_array(out, p); points && p.point < points->size()) {
        points->erase(p.point);
      }
    } else if (has_item(out, p)) {
      out[array_key(p.kind)].erase(p.index);
    }
  }
  return out;
}

std::string unique_name(const Json& doc, ItemKind kind, const std::string& base) {
  const auto taken = [&](const std::string& name) {
    for (std::size_t i = 0; i < count(doc, kind); ++i)
      if (string_at(doc[array_key(kind)][i], "name", "") == name) return true;
    return false;
  };
  if (!taken(base)) return base;
  // "crate2" duplicated becomes "crate3", not "crate22".
  std::string stem = base;
  while (!stem.empty() && std::isdigit(static_cast<unsigned char>(stem.back()))) stem.pop_back();
  for (int n = 2;; ++n)
    if (const std::string name = stem + std::to_string(n); !taken(name)) return name;
}

Json with_item(const Json& doc, ItemKind kind, Json item, Pick& added) {
  Json out = doc;
  const char* key = array_key(kind);
  if (!out.contains(key) || !out[key].is_array()) out[key] = Json::array();
  if (item.contains("name") && item["name"].is_string())
    item["name"] = unique_name(out, kind, item["name"].get<std::string>());
  out[key].push_back(std::move(item));
  added = {kind, out[key].size() - 1};
  return out;
}

Json duplicated(const Json& doc, const Selection& selection, Vec2 offset, Selection& copies) {
  Json out = doc;
  copies.clear();
  for (const Pick& p : selection) {
    if (p.is_point() || !has_item(doc, p)) continue;
    Json copy = doc[array_key(p.kind)][p.index];
    copy.erase("player");  // one player at most
    Json staged = Json::object();
    staged[array_key(p.kind)] = Json::array({std::move(copy)});
    move_item(staged, {p.kind, 0}, offset);
    Pick added;
    out = with_item(out, p.kind, std::move(staged[array_key(p.kind)][0]), added);
    copies.push_back(added);
  }
  std::sort(copies.begin(), copies.end());
  return out;
}

Json with_corner(const Json& doc, const Pick& item, int corner, Vec2 corner_world) {
  const auto shape = shape_of(doc, item.kind, item.index);
  if (!shape || shape->form != ItemShape::Form::box || shape->outline.size() != 4) return doc;
  Json out = doc;
  Json& j = body_of(out, item);
  const Vec2 opposite = shape->outline[static_cast<std::size_t>((corner + 2) % 4)];
  if (item.kind != ItemKind::prop && item.kind != ItemKind::vehicle) {
    j["min"] = vec2({std::min(corner_world.x, opposite.x), std::min(corner_world.y, opposite.y)});
    j["max"] = vec2({std::max(corner_world.x, opposite.x), std::max(corner_world.y, opposite.y)});
    return out;
  }
  const Vec2 a = to_local(*shape, opposite), b = to_local(*shape, corner_world);
  j["position"] = vec2(to_world(*shape, (a + b) * 0.5));
  j["size"] = vec2({std::fabs(b.x - a.x), std::fabs(b.y - a.y)});
  return out;
}

Json with_radius(const Json& doc, const Pick& item, double radius) {
  const auto shape = shape_of(doc, item.kind, item.index);
  if (!shape || shape->form != ItemShape::Form::circle) return doc;
  Json out = doc;
  Json& j = body_of(out, item);
  if (item.kind == ItemKind::tire) {
    j["outer_radius"] = number(radius);
    j["inner_radius"] = number(shape->inner_radius * radius / shape->radius);
  } else {
    j["radius"] = number(radius);
  }
  return out;
}

Json with_angle(const Json& doc, const Pick& item, double angle) {
  if (!has_item(doc, item) || (item.kind != ItemKind::prop && item.kind != ItemKind::vehicle)) return doc;
  Json out = doc;
  body_of(out, item)["angle"] = number(angle);
  return out;
}

Json with_point(const Json& doc, const Pick& point, Vec2 world) {
  const auto shape = shape_of(doc, point.kind, point.index);
  Json out = doc;
  Json* at = point_at(out, point);
  if (!shape || !at) return doc;
  *at = vec2(point.set == PointSet::waypoints ? world : to_local(*shape, world));
  return out;
}

Json with_point_inserted(const Json& doc, const Pick& point, Vec2 world) {
  const auto shape = shape_of(doc, point.kind, point.index);
  Json out = doc;
  Json* points = point_array(out, point);
  if (!shape || !points || point.point > points->size()) return doc;
  points->insert(points->begin() + static_cast<std::ptrdiff_t>(point.point),
                 vec2(point.set == PointSet::waypoints ? world : to_local(*shape, world)));
  return out;
}

Json default_vehicle(Vec2 at, bool player) {
  // Keys in the reference's order, as a save writes them.
  const auto wheel = [](Vec2 axle, bool sprung) {
    Json w{{"axle", vec2(axle)}};
    if (sprung) {
      w["stiffness"] = 6000;
      w["damping"] = 300;
      w["travel"] = 0.1;
      w["driven"] = false;
    }
    w["outer_radius"] = 0.35;
    w["inner_radius"] = 0.22;
    w["segments"] = 24;
    w["mass"] = 8;
    return w;
  };
  const Json rear = wheel({-0.6, -0.3}, false), front = wheel({0.6, -0.3}, true);
  Json v = Json::object();
  if (player) v["player"] = true;
  v["chassis"] = {{"shape", "box"}, {"position", vec2(at)}, {"size", vec2({1.6, 0.3})}, {"density", 100}};
  v["wheels"] = Json::array({rear, front});
  v["head"] = {{"position", vec2({0.3, 0.35})}, {"radius", 0.15}};
  return v;
}

bool names_a_player(const Json& doc) {
  for (const ItemKind kind : {ItemKind::tire, ItemKind::vehicle})
    for (std::size_t i = 0; i < count(doc, kind); ++i) {
      const Json& item = doc[array_key(kind)][i];
      if (item.is_object() && item.value("player", false)) return true;
    }
  return false;
}

Json with_waypoint(const Json& doc, const Pick& prop, Vec2 world, Pick& added) {
  if (prop.kind != ItemKind::prop || !has_item(doc, prop)) return doc;
  Json out = doc;
  Json& j = item_at(out, prop);
  j["type"] = "kinematic";
  if (!j.contains("path") || !j["path"].is_object()) j["path"] = Json::object();
  Json& path = j["path"];
  if (!path.contains("waypoints") || !path["waypoints"].is_array()) path["waypoints"] = Json::array();
  path["waypoints"].push_back(vec2(world));
  added = {prop.kind, prop.index, PointSet::waypoints, path["waypoints"].size() - 1};
  return out;
}

}  // namespace editor

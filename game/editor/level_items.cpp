#include "level_items.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tire/rigid/bodies.h"
#include "tire/tire/tire_spec.h"

namespace editor {

namespace {

constexpr int kCirclePoints = 32;
constexpr ItemKind kTopFirst[] = {ItemKind::vehicle, ItemKind::tire, ItemKind::prop, ItemKind::region,
                                  ItemKind::obstacle};

const Json* item_json(const Json& doc, ItemKind kind, std::size_t index) {
  const auto it = doc.find(array_key(kind));
  if (it == doc.end() || !it->is_array() || index >= it->size()) return nullptr;
  const Json& item = (*it)[index];
  return item.is_object() ? &item : nullptr;
}

std::vector<Vec2> points_at(const Json& j, const char* key) {
  std::vector<Vec2> out;
  const auto it = j.find(key);
  if (it == j.end() || !it->is_array()) return out;
  for (const Json& p : *it)
    if (p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number())
      out.push_back({p[0].get<double>(), p[1].get<double>()});
  return out;
}

std::vector<Vec2> circle_points(Vec2 c, double r) {
  std::vector<Vec2> out;
  for (int i = 0; i < kCirclePoints; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kCirclePoints;
    out.push_back(c + Vec2{std::cos(a), std::sin(a)} * r);
  }
  return out;
}

bool inside_polygon(const std::vector<Vec2>& poly, Vec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double l2 = tire::length_squared(ab);
  const double t = l2 > 0.0 ? std::clamp(tire::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  return tire::length(p - (a + ab * t));
}

bool hits(const ItemShape& s, Vec2 p, double tolerance) {
  // A vehicle is hit on its wheels and head as on its chassis.
  for (std::size_t w = 0; w < s.axles.size() && w < s.wheel_radii.size(); ++w)
    if (tire::length(p - s.axles[w]) <= s.wheel_radii[w] + tolerance) return true;
  if (s.head && tire::length(p - *s.head) <= s.head_radius + tolerance) return true;
  if (s.outline.empty()) return false;
  if (s.form == ItemShape::Form::chain) {
    const std::size_t n = s.outline.size();
    for (std::size_t i = 0; i + 1 < n + (s.loop ? 1 : 0); ++i)
      if (distance_to_segment(p, s.outline[i], s.outline[(i + 1) % n]) <= tolerance) return true;
    return n == 1 && tire::length(p - s.outline[0]) <= tolerance;
  }
  if (s.form == ItemShape::Form::circle) return tire::length(p - s.position) <= s.radius + tolerance;
  return inside_polygon(s.outline, p);
}

}  // namespace

const char* array_key(ItemKind kind) {
  switch (kind) {
    case ItemKind::obstacle: return "obstacles";
    case ItemKind::region: return "regions";
    case ItemKind::prop: return "props";
    case ItemKind::tire: return "tires";
    case ItemKind::vehicle: return "vehicles";
  }
  return "";
}

std::string describe(const Json& doc, ItemKind kind, std::size_t index) {
  static constexpr const char* kNames[] = {"obstacle", "region", "prop", "tire", "vehicle"};
  std::string text = std::string(kNames[static_cast<int>(kind)]) + " " + std::to_string(index);
  if (const Json* j = item_json(doc, kind, index)) {
    const std::string name = string_at(*j, "name", "");
    if (!name.empty()) text += " (" + name + ")";
    if (kind == ItemKind::prop)
      text += ": " + string_at(*j, "type", "static") + " " + string_at(*j, "shape", "?");
    if (kind == ItemKind::vehicle) {
      const auto wheels = j->find("wheels");
      text += std::string(j->value("player", false) ? " (the player)" : "") + ": " +
              std::to_string(wheels != j->end() && wheels->is_array() ? wheels->size() : 0) + " wheels";
    }
  }
  return text;
}

void select(Selection& s, const Pick& p) {
  const auto it = std::lower_bound(s.begin(), s.end(), p);
  if (it == s.end() || *it != p) s.insert(it, p);
}

bool is_selected(const Selection& s, const Pick& p) { return std::binary_search(s.begin(), s.end(), p); }

double number_at(const Json& j, const char* key, double fallback) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : fallback;
}

Vec2 vec2_at(const Json& j, const char* key, Vec2 fallback) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_array() || it->size() != 2 || !(*it)[0].is_number() || !(*it)[1].is_number())
    return fallback;
  return {(*it)[0].get<double>(), (*it)[1].get<double>()};
}

std::string string_at(const Json& j, const char* key, const std::string& fallback) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : fallback;
}

std::size_t count(const Json& doc, ItemKind kind) {
  const auto it = doc.find(array_key(kind));
  return it != doc.end() && it->is_array() ? it->size() : 0;
}

Vec2 to_world(const ItemShape& prop, Vec2 local) {
  const double c = std::cos(prop.angle), s = std::sin(prop.angle);
  return prop.position + Vec2{c * local.x - s * local.y, s * local.x + c * local.y};
}

Vec2 to_local(const ItemShape& prop, Vec2 world) {
  const double c = std::cos(prop.angle), s = std::sin(prop.angle);
  const Vec2 d = world - prop.position;
  return {c * d.x + s * d.y, -s * d.x + c * d.y};
}

std::optional<ItemShape> shape_of(const Json& doc, ItemKind kind, std::size_t index) {
  const Json* jp = item_json(doc, kind, index);
  if (!jp) return std::nullopt;
  const Json& j = *jp;
  ItemShape s;
  switch (kind) {
    case ItemKind::obstacle:
    case ItemKind::region: {
      const Vec2 lo = vec2_at(j, "min", {}), hi = vec2_at(j, "max", lo + Vec2{1, 1});
      s.position = (lo + hi) * 0.5;
      s.half_size = (hi - lo) * 0.5;
      s.outline = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
      return s;
    }
    case ItemKind::tire: {
      const tire::TireSpec defaults;
      s.form = ItemShape::Form::circle;
      s.position = vec2_at(j, "position", {});
      s.angle = number_at(j, "angle", defaults.angle);
      s.radius = number_at(j, "outer_radius", defaults.outer_radius);
      s.inner_radius = number_at(j, "inner_radius", defaults.inner_radius);
      s.outline = circle_points(s.position, s.radius);
      return s;
    }
    case ItemKind::vehicle: {
      static const Json kNone = Json::object();
      const auto chassis = j.find("chassis");
      s = prop_shape(chassis != j.end() && chassis->is_object() ? *chassis : kNone);
      s.waypoints.clear();
      if (const auto wheels = j.find("wheels"); wheels != j.end() && wheels->is_array())
        for (const Json& w : *wheels) {
          if (!w.is_object()) continue;
          s.axles.push_back(to_world(s, vec2_at(w, "axle", {})));
          s.wheel_radii.push_back(number_at(w, "outer_radius", tire::TireSpec{}.outer_radius));
        }
      if (const auto head = j.find("head"); head != j.end() && head->is_object()) {
        s.head = to_world(s, vec2_at(*head, "position", {}));
        s.head_radius = number_at(*head, "radius", 0.0);
      }
      return s;
    }
    case ItemKind::prop: return prop_shape(j);
  }
  return std::nullopt;
}

ItemShape prop_shape(const Json& j) {
  ItemShape s;
  {
    {
      const tire::PropSpec defaults;
      s.position = vec2_at(j, "position", defaults.position);
      s.angle = number_at(j, "angle", defaults.angle);
      const std::string shape = string_at(j, "shape", "box");
      if (shape == "circle") {
        s.form = ItemShape::Form::circle;
        s.radius = number_at(j, "radius", defaults.radius);
        s.outline = circle_points(s.position, s.radius);
      } else if (shape == "polygon" || shape == "chain") {
        s.form = shape == "polygon" ? ItemShape::Form::polygon : ItemShape::Form::chain;
        for (const Vec2 p : points_at(j, "points")) s.outline.push_back(to_world(s, p));
        s.loop = shape == "chain" && j.value("loop", false);
      } else {
        s.half_size = vec2_at(j, "size", {1, 1}) * 0.5;
        const Vec2 h = s.half_size;
        s.outline = {to_world(s, {-h.x, -h.y}), to_world(s, {h.x, -h.y}), to_world(s, {h.x, h.y}),
                     to_world(s, {-h.x, h.y})};
      }
      if (const auto path = j.find("path"); path != j.end() && path->is_object())
        s.waypoints = points_at(*path, "waypoints");
      return s;
    }
  }
}

std::vector<Vec2> extent_points(const ItemShape& s) {
  std::vector<Vec2> points = s.outline;
  points.insert(points.end(), s.waypoints.begin(), s.waypoints.end());
  for (std::size_t w = 0; w < s.axles.size() && w < s.wheel_radii.size(); ++w) {
    const double r = s.wheel_radii[w];
    points.push_back(s.axles[w] - Vec2{r, r});
    points.push_back(s.axles[w] + Vec2{r, r});
  }
  if (s.head) {
    points.push_back(*s.head - Vec2{s.head_radius, s.head_radius});
    points.push_back(*s.head + Vec2{s.head_radius, s.head_radius});
  }
  return points;
}

std::optional<Pick> pick_item(const Json& doc, Vec2 p, double tolerance) {
  for (const ItemKind kind : kTopFirst) {
    for (std::size_t i = count(doc, kind); i-- > 0;) {
      const auto s = shape_of(doc, kind, i);
      if (s && hits(*s, p, tolerance)) return Pick{kind, i};
    }
  }
  return std::nullopt;
}

std::optional<Pick> pick_point(const Json& doc, Vec2 p, double reach) {
  for (std::size_t i = count(doc, ItemKind::prop); i-- > 0;) {
    const auto s = shape_of(doc, ItemKind::prop, i);
    if (!s) continue;
    if (s->form == ItemShape::Form::polygon || s->form == ItemShape::Form::chain)
      for (std::size_t k = 0; k < s->outline.size(); ++k)
        if (tire::length(s->outline[k] - p) <= reach) return Pick{ItemKind::prop, i, PointSet::points, k};
    for (std::size_t k = 0; k < s->waypoints.size(); ++k)
      if (tire::length(s->waypoints[k] - p) <= reach) return Pick{ItemKind::prop, i, PointSet::waypoints, k};
  }
  return std::nullopt;
}

Selection items_inside(const Json& doc, const tire::Aabb& box) {
  Selection out;
  for (const ItemKind kind : kTopFirst) {
    for (std::size_t i = 0; i < count(doc, kind); ++i) {
      const auto s = shape_of(doc, kind, i);
      if (!s || s->outline.empty()) continue;
      const tire::Aabb b = tire::bounds_of(extent_points(*s));
      if (b.min.x >= box.min.x && b.min.y >= box.min.y && b.max.x <= box.max.x && b.max.y <= box.max.y)
        select(out, Pick{kind, i});
    }
  }
  return out;
}

std::optional<tire::Aabb> level_extent(const Json& doc) {
  std::optional<tire::Aabb> all;
  for (const ItemKind kind : kTopFirst) {
    for (std::size_t i = 0; i < count(doc, kind); ++i) {
      const auto s = shape_of(doc, kind, i);
      if (!s) continue;
      const std::vector<Vec2> points = extent_points(*s);
      if (points.empty()) continue;
      const tire::Aabb b = tire::bounds_of(points);
      all = all ? tire::Aabb{{std::min(all->min.x, b.min.x), std::min(all->min.y, b.min.y)},
                             {std::max(all->max.x, b.max.x), std::max(all->max.y, b.max.y)}}
                : b;
    }
  }
  return all;
}

}  // namespace editor

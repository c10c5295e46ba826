// Level validation: every key of levels/README.md, with its unit, default and range.
#include "level_reader.h"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>

#include "script_reader.h"
#include "tire/io/file_io.h"
#include "tire/io/level.h"
#include "tire/rigid/prop_geometry.h"

namespace tire {

namespace {

using json = nlohmann::json;

// How far from 1 the length of a wheel's axis may be before it is refused rather than normalised.
constexpr double kAxisTolerance = 1e-3;

// A unit as messages print it: the reference page's "kg/m²" as "kg/m^2".
std::string message_unit(const LevelKey& key) {
  std::string out = key.unit;
  for (const auto& [superscript, ascii] :
       std::array<std::pair<std::string_view, std::string_view>, 3>{{{"²", "^2"}, {"³", "^3"}, {"⁴", "^4"}}})
    for (std::size_t at = out.find(superscript); at != std::string::npos; at = out.find(superscript))
      out.replace(at, superscript.size(), ascii);
  return out;
}

// A choice read into an enum whose values are in the order of the key's choices.
template <typename Enum>
Enum read_enum(JsonReader& r, const json& j, const std::string& path, const LevelKey& key, Enum fallback) {
  return static_cast<Enum>(read_choice_index(r, j, path, key, static_cast<std::size_t>(fallback)));
}

SolverConfig read_solver(JsonReader& r, const json& j, const std::string& path) {
  using O = LevelObject;
  SolverConfig s;
  if (!r.object(j, path, level_key_names(O::solver))) return s;
  const LevelKey& method = level_key(O::solver, "method");
  s.method = kSolverMethods[read_choice_index(r, j, path, method, static_cast<std::size_t>(s.method))];
  s.sleep = read_boolean(r, j, path, level_key(O::solver, "sleep"), s.sleep);
  s.rolling_hold = read_boolean(r, j, path, level_key(O::solver, "rolling_hold"), s.rolling_hold);
  s.dt = read_number(r, j, path, level_key(O::solver, "dt"), s.dt);
  s.substeps = read_integer(r, j, path, level_key(O::solver, "substeps"), s.substeps);
  s.iterations = read_integer(r, j, path, level_key(O::solver, "iterations"), s.iterations);
  s.damping = read_number(r, j, path, level_key(O::solver, "damping"), s.damping);
  s.tunnel_clamp = read_number(r, j, path, level_key(O::solver, "tunnel_clamp"), s.tunnel_clamp);
  s.ground_normal_y = read_number(r, j, path, level_key(O::solver, "ground_normal_y"), s.ground_normal_y);
  s.jump_grace = read_number(r, j, path, level_key(O::solver, "jump_grace"), s.jump_grace);
  s.divergence_area = read_number(r, j, path, level_key(O::solver, "divergence_area"), s.divergence_area);
  s.divergence_speed = read_number(r, j, path, level_key(O::solver, "divergence_speed"), s.divergence_speed);
  s.restitution_threshold =
      read_number(r, j, path, level_key(O::solver, "restitution_threshold"), s.restitution_threshold);
  s.tire_neighbours = read_integer(r, j, path, level_key(O::solver, "tire_neighbours"), s.tire_neighbours);
  s.island_tires = read_integer(r, j, path, level_key(O::solver, "island_tires"), s.island_tires);
  return s;
}

RunBudgets read_budgets(JsonReader& r, const json& j, const std::string& path) {
  using O = LevelObject;
  RunBudgets b;
  if (!r.object(j, path, level_key_names(O::budgets))) return b;
  b.tires = read_integer(r, j, path, level_key(O::budgets, "tires"), b.tires);
  b.particles = read_integer(r, j, path, level_key(O::budgets, "particles"), b.particles);
  b.props = read_integer(r, j, path, level_key(O::budgets, "props"), b.props);
  b.spawns_per_tick = read_integer(r, j, path, level_key(O::budgets, "spawns_per_tick"), b.spawns_per_tick);
  b.messages = read_integer(r, j, path, level_key(O::budgets, "messages"), b.messages);
  b.message_bytes = read_integer(r, j, path, level_key(O::budgets, "message_bytes"), b.message_bytes);
  b.firings_per_tick =
      read_integer(r, j, path, level_key(O::budgets, "firings_per_tick"), b.firings_per_tick);
  return b;
}

// Each compliance the object leaves out keeps `c`'s (the tire's material's).
TireCompliance read_compliance(JsonReader& r, const json& j, const std::string& path, TireCompliance c) {
  using O = LevelObject;
  if (!r.object(j, path, level_key_names(O::compliance))) return c;
  c.outer = read_number(r, j, path, level_key(O::compliance, "outer"), c.outer);
  c.inner = read_number(r, j, path, level_key(O::compliance, "inner"), c.inner);
  c.spoke = read_number(r, j, path, level_key(O::compliance, "spoke"), c.spoke);
  c.pressure = read_number(r, j, path, level_key(O::compliance, "pressure"), c.pressure);
  return c;
}

}  // namespace

const LevelKey& level_key(LevelObject object, std::string_view key) {
  if (const LevelKey* k = find_level_key(object, key)) return *k;
  throw std::logic_error("the level key table has no key \"" + std::string(key) + "\" in that object");
}

std::span<const std::string_view> level_key_names(LevelObject object) {
  static const std::array<std::vector<std::string_view>, kLevelObjects> names = [] {
    std::array<std::vector<std::string_view>, kLevelObjects> out;
    for (std::size_t o = 0; o < out.size(); ++o)
      for (const LevelKey& k : level_keys(static_cast<LevelObject>(o))) out[o].push_back(k.key);
    return out;
  }();
  return names.at(static_cast<std::size_t>(object));
}

double read_number(JsonReader& r, const json& j, const std::string& path, const LevelKey& key,
                   double fallback) {
  if (!key.parameter.empty())
    return read_parameter(r, j, path, find_parameter(key.parameter)->id, fallback, key.required);
  return r.number(j, path, key.key.c_str(), fallback, key.range, message_unit(key).c_str(), key.required);
}

int read_integer(JsonReader& r, const json& j, const std::string& path, const LevelKey& key, int fallback) {
  if (!key.parameter.empty())
    return read_integer_parameter(r, j, path, find_parameter(key.parameter)->id, fallback, key.required);
  return r.integer(j, path, key.key.c_str(), fallback, key.range, key.required);
}

Vec2 read_vec2(JsonReader& r, const json& j, const std::string& path, const LevelKey& key, Vec2 fallback) {
  return r.vec2(j, path, key.key.c_str(), fallback, key.range, message_unit(key).c_str(), key.required);
}

std::string read_string(JsonReader& r, const json& j, const std::string& path, const LevelKey& key,
                        const std::string& fallback) {
  return r.string(j, path, key.key.c_str(), fallback, static_cast<std::size_t>(key.range.max), key.required);
}

bool read_boolean(JsonReader& r, const json& j, const std::string& path, const LevelKey& key, bool fallback) {
  return r.boolean(j, path, key.key.c_str(), fallback);
}

std::size_t read_choice_index(JsonReader& r, const json& j, const std::string& path, const LevelKey& key,
                              std::size_t fallback) {
  const std::string value = r.choice(j, path, key.key.c_str(), key.choices.at(fallback), key.choices);
  return static_cast<std::size_t>(std::find(key.choices.begin(), key.choices.end(), value) -
                                  key.choices.begin());
}

double read_parameter(JsonReader& r, const json& j, const std::string& path, ParamId id, double fallback,
                      bool required) {
  const Parameter& p = parameter(id);
  if (p.integer) return read_integer_parameter(r, j, path, id, static_cast<int>(fallback), required);
  return r.number(j, path, p.field(), fallback, p.range, p.unit, required);
}

int read_integer_parameter(JsonReader& r, const json& j, const std::string& path, ParamId id, int fallback,
                           bool required) {
  const Parameter& p = parameter(id);
  return r.integer(j, path, p.field(), fallback, p.range, required);
}

Vec2 read_gravity(JsonReader& r, const json& j, const std::string& path, const char* key, Vec2 fallback,
                  bool required) {
  const Parameter& x = parameter(ParamId::gravity_x);  // gravity.y has the same range (parameters.h)
  return r.vec2(j, path, key, fallback, x.range, x.unit, required);
}

TireSpec read_tire(JsonReader& r, const json& j, const std::string& path, LevelObject object) {
  // The keys `object` has of a tire's (a wheel's are its material's): the others keep TireSpec{}'s.
  const auto key = [object](std::string_view name) { return find_level_key(object, name); };
  const auto number = [&](std::string_view name, double& field) {
    if (const LevelKey* k = key(name)) field = read_number(r, j, path, *k, field);
  };
  TireSpec t;
  if (!r.object(j, path, level_key_names(object))) return t;
  kMaterials[read_choice_index(r, j, path, *key("material"), 0)].apply_to(t);
  if (const LevelKey* k = key("position")) t.position = read_vec2(r, j, path, *k, t.position);
  if (const LevelKey* k = key("velocity")) t.velocity = read_vec2(r, j, path, *k, t.velocity);
  number("angle", t.angle);
  number("angular_velocity", t.angular_velocity);
  number("outer_radius", t.outer_radius);
  number("inner_radius", t.inner_radius);
  if (j.contains("outer_radius") || j.contains("inner_radius")) {
    if (t.inner_radius >= t.outer_radius)
      r.fail(join_path(path, "inner_radius"), "must be less than outer_radius (" +
                                                  JsonReader::describe(t.outer_radius) + "), got " +
                                                  JsonReader::describe(t.inner_radius));
  }
  t.segments = read_integer(r, j, path, *key("segments"), t.segments);
  number("mass", t.mass);
  number("friction", t.friction);
  // Kinetic friction defaults to the static coefficient (the row's default_follows) when the tire
  // gives one, else to its material's.
  t.kinetic_friction = read_number(r, j, path, *key("kinetic_friction"),
                                   j.contains("friction") ? t.friction : t.kinetic_friction);
  number("pressure", t.pressure);
  if (const auto it = j.find("compliance"); it != j.end())
    t.compliance = read_compliance(r, *it, join_path(path, "compliance"), t.compliance);
  t.spokes = read_enum(r, j, path, *key("spokes"), t.spokes);
  number("material_damping", t.material_damping);
  number("rolling_resistance", t.rolling_resistance);
  if (const LevelKey* k = key("player")) t.player = read_boolean(r, j, path, *k, t.player);
  number("drive_acceleration", t.drive_acceleration);
  number("jump_speed", t.jump_speed);
  number("max_speed", t.max_speed);
  number("restitution", t.restitution);
  number("inflate_rate", t.inflate_rate);
  number("min_pressure", t.min_pressure);
  number("max_pressure", t.max_pressure);
  if (t.min_pressure > t.max_pressure)
    r.fail(join_path(path, "max_pressure"), "must be at least min_pressure (" +
                                                JsonReader::describe(t.min_pressure) + "), got " +
                                                JsonReader::describe(t.max_pressure));
  return t;
}

namespace {

// A KeyType::points key, with as many points as `count` allows.
std::vector<Vec2> read_points(JsonReader& r, const json& j, const std::string& path, const LevelKey& key,
                              const LevelKey::PointCount& count) {
  const std::size_t min_count = count.min, max_count = count.max;
  const Range& coordinate = key.range;
  std::vector<Vec2> points;
  const std::string p = join_path(path, key.key);
  const auto it = j.find(key.key);
  if (it == j.end()) {
    r.fail(p, "is required: an array of " + std::to_string(min_count) + " to " + std::to_string(max_count) +
                  " points [x, y] in " + message_unit(key));
    return points;
  }
  if (!it->is_array() || it->size() < min_count || it->size() > max_count) {
    r.fail(p, "must be an array of " + std::to_string(min_count) + " to " + std::to_string(max_count) +
                  " points [x, y] in " + message_unit(key) + ", got " + JsonReader::describe(*it));
    return points;
  }
  for (std::size_t i = 0; i < it->size(); ++i) {
    const json& v = (*it)[i];
    const bool ok = v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number() &&
                    coordinate.contains(v[0].get<double>()) && coordinate.contains(v[1].get<double>());
    if (!ok) {
      r.fail(join_path(p, i), "must be [x, y] with each in " + coordinate.text() + " " + message_unit(key) +
                                  ", got " + JsonReader::describe(v));
      continue;
    }
    points.push_back({v[0].get<double>(), v[1].get<double>()});
  }
  return points;
}

KinematicPath read_path(JsonReader& r, const json& j, const std::string& path) {
  const auto key = [](std::string_view name) -> const LevelKey& {
    return level_key(LevelObject::path, name);
  };
  KinematicPath k;
  if (!r.object(j, path, level_key_names(LevelObject::path))) return k;
  k.waypoints = read_points(r, j, path, key("waypoints"), *point_count(key("waypoints")));
  k.speed = read_number(r, j, path, key("speed"), k.speed);
  k.mode = read_enum(r, j, path, key("mode"), k.mode);
  k.running = read_boolean(r, j, path, key("running"), k.running);
  return k;
}

Obstacle read_obstacle(JsonReader& r, const json& j, const std::string& path) {
  const auto key = [](std::string_view name) -> const LevelKey& {
    return level_key(LevelObject::obstacle, name);
  };
  Obstacle o;
  if (!r.object(j, path, level_key_names(LevelObject::obstacle))) return o;
  o.box.min = read_vec2(r, j, path, key("min"), {});
  o.box.max = read_vec2(r, j, path, key("max"), {});
  if (j.contains("min") && j.contains("max") && !(o.box.min.x < o.box.max.x && o.box.min.y < o.box.max.y))
    r.fail(join_path(path, "max"), "must be greater than min on both axes, got " +
                                       JsonReader::describe(j["max"]) + " with min " +
                                       JsonReader::describe(j["min"]));
  o.friction = read_number(r, j, path, key("friction"), o.friction);
  return o;
}

}  // namespace

PropSpec read_prop(JsonReader& r, const json& j, const std::string& path, LevelObject object) {
  // A chassis has the keys of a dynamic prop that is not a chain: the others keep PropSpec{}'s.
  const auto key = [object](std::string_view name) -> const LevelKey& { return level_key(object, name); };
  const auto has = [object](std::string_view name) { return find_level_key(object, name) != nullptr; };
  PropSpec p;
  if (object == LevelObject::chassis) p.type = PropType::dynamic_body;
  if (!r.object(j, path, level_key_names(object))) return p;
  if (has("name")) p.name = read_string(r, j, path, key("name"), p.name);
  const LevelKey& shape_key = key("shape");
  if (!j.contains("shape")) {
    std::string choices;
    for (const std::string& c : shape_key.choices) choices += (choices.empty() ? "\"" : ", \"") + c + "\"";
    r.fail(join_path(path, "shape"), "is required: one of " + choices);
  }
  p.shape = read_enum(r, j, path, shape_key, p.shape);
  const std::string& shape = level_key(LevelObject::prop, "shape").choices[static_cast<std::size_t>(p.shape)];
  if (has("type")) p.type = read_enum(r, j, path, key("type"), p.type);
  const std::string& type = level_key(LevelObject::prop, "type").choices[static_cast<std::size_t>(p.type)];
  p.position = read_vec2(r, j, path, key("position"), p.position);
  p.angle = read_number(r, j, path, key("angle"), p.angle);

  // Shape keys: each belongs to some shapes only.
  for (const LevelKey& k : level_keys(object)) {
    if (!j.contains(k.key) || applies_to_shape(k, shape)) continue;
    std::string which;
    for (std::size_t i = 0; i < k.shapes.size(); ++i)
      which += (i == 0 ? "" : i + 1 == k.shapes.size() ? " and " : ", ") + k.shapes[i];
    const char* noun = object == LevelObject::chassis ? " chassis" : " props";
    r.fail(join_path(path, k.key), "applies only to " + which + noun + ", and this one is a " + shape);
  }
  const LevelKey& points = key("points");
  switch (p.shape) {
    case PropShape::box: p.size = read_vec2(r, j, path, key("size"), p.size); break;
    case PropShape::circle: p.radius = read_number(r, j, path, key("radius"), p.radius); break;
    case PropShape::polygon: {
      const LevelKey::PointCount& count = *point_count(points, shape);
      p.points = read_points(r, j, path, points, count);
      if (p.points.size() >= count.min && p.points.size() == j["points"].size() && !is_convex_ccw(p.points))
        r.fail(join_path(path, "points"), "must be a convex polygon in counter-clockwise order, got " +
                                              JsonReader::describe(j["points"]));
      break;
    }
    case PropShape::chain:  // not a chassis' choice
      p.points = read_points(r, j, path, points, *point_count(points, shape));
      p.loop = read_boolean(r, j, path, key("loop"), p.loop);
      p.thickness = read_number(r, j, path, key("thickness"), p.thickness);
      if (p.loop && p.points.size() < 3)
        r.fail(join_path(path, "points"), "a closed chain needs at least 3 points");
      if (p.type != PropType::static_body)
        r.fail(join_path(path, "type"),
               "a chain can only be static (it has no mass), got \"" + printable(type) + "\"");
      break;
  }
  for (std::size_t i = 0; i + 1 < p.points.size() + (p.loop ? 1 : 0) && p.points.size() >= 2; ++i) {
    const Vec2 a = p.points[i], b = p.points[(i + 1) % p.points.size()];
    if (length(b - a) < kMinPropLength) {
      r.fail(join_path(join_path(path, "points"), (i + 1) % p.points.size()),
             "must be at least " + JsonReader::describe(kMinPropLength) + " m from the point before it");
      break;
    }
  }
  p.density = read_number(r, j, path, key("density"), p.density);
  p.friction = read_number(r, j, path, key("friction"), p.friction);
  p.restitution = read_number(r, j, path, key("restitution"), p.restitution);
  p.velocity = read_vec2(r, j, path, key("velocity"), p.velocity);
  p.angular_velocity = read_number(r, j, path, key("angular_velocity"), p.angular_velocity);
  if (const auto it = j.find("path"); it != j.end() && has("path")) {
    if (p.type != PropType::kinematic_body)
      r.fail(join_path(path, "path"), "applies only to kinematic props, and this one is " + type);
    p.path = read_path(r, *it, join_path(path, "path"));
  }
  return p;
}

namespace {

WheelSpec read_wheel(JsonReader& r, const json& j, const std::string& path) {
  const auto key = [](std::string_view name) -> const LevelKey& {
    return level_key(LevelObject::wheel, name);
  };
  WheelSpec w;
  w.tire = read_tire(r, j, path, LevelObject::wheel);  // checks the wheel's keys too
  if (!j.is_object()) return w;
  w.axle.point = read_vec2(r, j, path, key("axle"), w.axle.point);
  const Vec2 axis = read_vec2(r, j, path, key("axis"), w.axle.axis);
  // A unit vector as written to a few digits ([0.7071, 0.7071]) is made exactly one; anything
  // further from it is a mistake.
  const double norm = length(axis);
  if (std::abs(norm - 1.0) <= kAxisTolerance)
    w.axle.axis = axis / norm;
  else
    r.fail(join_path(path, "axis"),
           "must be a unit vector (length 1 within " + JsonReader::describe(kAxisTolerance) + "), got " +
               JsonReader::describe(j["axis"]) + " of length " + JsonReader::describe(norm));
  w.axle.stiffness = read_number(r, j, path, key("stiffness"), w.axle.stiffness);
  w.axle.damping = read_number(r, j, path, key("damping"), w.axle.damping);
  w.axle.travel = read_number(r, j, path, key("travel"), w.axle.travel);
  w.axle.driven = read_boolean(r, j, path, key("driven"), w.axle.driven);
  return w;
}

VehicleHead read_head(JsonReader& r, const json& j, const std::string& path) {
  const auto key = [](std::string_view name) -> const LevelKey& {
    return level_key(LevelObject::head, name);
  };
  VehicleHead h;
  if (!r.object(j, path, level_key_names(LevelObject::head))) return h;
  h.position = read_vec2(r, j, path, key("position"), h.position);
  h.radius = read_number(r, j, path, key("radius"), h.radius);
  return h;
}

LevelVehicle read_vehicle(JsonReader& r, const json& j, const std::string& path) {
  const auto key = [](std::string_view name) -> const LevelKey& {
    return level_key(LevelObject::vehicle, name);
  };
  LevelVehicle v;
  if (!r.object(j, path, level_key_names(LevelObject::vehicle))) return v;
  v.player = read_boolean(r, j, path, key("player"), v.player);
  if (const auto it = j.find("chassis"); it != j.end())
    v.spec.chassis = read_prop(r, *it, join_path(path, "chassis"), LevelObject::chassis);
  else
    r.fail(join_path(path, "chassis"), "is required: the body the wheels hang from, as a prop's keys");
  const LevelKey& wheels = key("wheels");
  const auto min_wheels = static_cast<std::size_t>(wheels.range.min);
  const auto max_wheels = static_cast<std::size_t>(wheels.range.max);
  const std::string count = std::to_string(min_wheels) + " to " + std::to_string(max_wheels) + " wheels";
  const std::string wheels_path = join_path(path, "wheels");
  if (const auto it = j.find("wheels"); it == j.end()) {
    r.fail(wheels_path, "is required: an array of " + count);
  } else if (r.array(*it, wheels_path, max_wheels)) {
    if (it->size() < min_wheels)
      r.fail(wheels_path, "must be an array of " + count + ", got " + std::to_string(it->size()));
    for (std::size_t i = 0; i < it->size(); ++i)
      v.spec.wheels.push_back(read_wheel(r, (*it)[i], join_path(wheels_path, i)));
  }
  Drivetrain& d = v.spec.drivetrain;
  d.motor_torque = read_number(r, j, path, key("motor_torque"), d.motor_torque);
  d.motor_speed = read_number(r, j, path, key("motor_speed"), d.motor_speed);
  d.brake_torque = read_number(r, j, path, key("brake_torque"), d.brake_torque);
  d.lean_torque = read_number(r, j, path, key("lean_torque"), d.lean_torque);
  if (const auto it = j.find("head"); it != j.end()) v.head = read_head(r, *it, join_path(path, "head"));
  return v;
}

}  // namespace

namespace {

// Budgets over the whole level, beyond the per-array limits: a file within every one of those can
// still describe a world too big to build (10 000 tires of 256 segments are 5 million particles,
// half a kilobyte each). What the script spawns counts too, each spawn action once.
constexpr auto kMaxParticles = static_cast<std::size_t>(RunBudgets{}.particles);  // 2 × segments per tire
constexpr std::size_t kMaxPoints = 200'000;  // chain, polygon and path points over all props

struct Totals {
  std::size_t tires = 0, particles = 0, props = 0, points = 0;
  // Where each total first went past its limit.
  std::string tires_path, particles_path, props_path, points_path;
};

void count_tire(Totals& t, std::size_t segments, const std::string& path) {
  ++t.tires;
  t.particles += 2 * segments;
  if (t.tires > LevelLimits::max_tires && t.tires_path.empty()) t.tires_path = path;
  if (t.particles > kMaxParticles && t.particles_path.empty()) t.particles_path = path;
}

void count_prop(Totals& t, std::size_t points, const std::string& path) {
  ++t.props;
  t.points += points;
  if (t.props > LevelLimits::max_props && t.props_path.empty()) t.props_path = path;
  if (t.points > kMaxPoints && t.points_path.empty()) t.points_path = path;
}

std::size_t array_size(const json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_array() ? it->size() : 0;
}

// A spawn action's tire segments as the tire reader takes them (the default when missing or
// invalid).
std::size_t spawned_segments(const json& tire) {
  const Parameter& segments = parameter(ParamId::tire_segments);
  const auto fallback = static_cast<std::size_t>(segments.default_value);
  const auto it = tire.find("segments");
  if (it == tire.end() || !it->is_number()) return fallback;
  const double s = it->get<double>();
  return segments.range.contains(s) ? static_cast<std::size_t>(s) : fallback;
}

// The level's run budgets (run_budgets.h) against what it holds from the start, and against what one
// firing of a trigger does: a firing that alone passes a budget of a tick can never do all it says.
void check_budgets(JsonReader& r, const json& doc, const Level& level) {
  const RunBudgets& b = level.budgets;
  const auto named = [&](ParamId id, int limit) {
    return std::string(parameter(id).key) + " (" + std::to_string(limit) + ")";
  };
  // The level's tires, then its vehicles' wheels, each named by its path.
  std::vector<std::pair<std::string, int>> tires;  // path, segments
  for (std::size_t i = 0; i < level.tires.size(); ++i)
    tires.emplace_back(join_path("/tires", i), level.tires[i].segments);
  for (std::size_t i = 0; i < level.vehicles.size(); ++i)
    for (std::size_t w = 0; w < level.vehicles[i].spec.wheels.size(); ++w)
      tires.emplace_back(join_path(join_path(join_path("/vehicles", i), "wheels"), w),
                         level.vehicles[i].spec.wheels[w].tire.segments);
  std::size_t particles = 0;
  for (std::size_t i = 0; i < tires.size(); ++i) {
    particles += 2 * static_cast<std::size_t>(tires[i].second);
    if (i + 1 == static_cast<std::size_t>(b.tires) + 1)
      r.fail(tires[i].first, "the level's own tires are more than " + named(ParamId::budget_tires, b.tires));
    if (particles > static_cast<std::size_t>(b.particles)) {
      r.fail(tires[i].first, "the level's own tires have more particles than " +
                                 named(ParamId::budget_particles, b.particles));
      break;
    }
  }
  const std::size_t props = level.props.size() + level.vehicles.size();  // a chassis is a prop
  if (props > static_cast<std::size_t>(b.props))
    r.fail(level.props.size() > static_cast<std::size_t>(b.props)
               ? join_path("/props", static_cast<std::size_t>(b.props))
               : join_path(join_path("/vehicles", static_cast<std::size_t>(b.props) - level.props.size()),
                           "chassis"),
           "the level's own props are more than " + named(ParamId::budget_props, b.props));
  const auto triggers = doc.find("triggers");
  if (triggers == doc.end() || !triggers->is_array()) return;
  for (std::size_t i = 0; i < triggers->size(); ++i) {
    const json& trigger = (*triggers)[i];
    if (!trigger.is_object() || !trigger.contains("do") || !trigger["do"].is_array()) continue;
    std::size_t spawns = 0, messages = 0, message_bytes = 0;
    for (const json& a : trigger["do"]) {
      if (!a.is_object() || !a.contains("action") || !a["action"].is_string()) continue;
      const std::string& action = a["action"].get_ref<const std::string&>();
      spawns += action == "spawn_tire" || action == "spawn_prop";
      if (action == "message" && a.contains("text") && a["text"].is_string()) {
        ++messages;
        message_bytes += a["text"].get_ref<const std::string&>().size();
      }
    }
    const std::string path = join_path(join_path("/triggers", i), "do");
    const auto per_firing = [&](std::size_t count, const char* what, ParamId id, int limit) {
      if (count > static_cast<std::size_t>(limit))
        r.fail(path, "one firing adds " + std::to_string(count) + " " + what + ", more than " +
                         named(id, limit) + " allows: the rest would be dropped every time it fires");
    };
    per_firing(spawns, "tires and props", ParamId::budget_spawns_per_tick, b.spawns_per_tick);
    per_firing(messages, "messages", ParamId::budget_messages, b.messages);
    per_firing(message_bytes, "bytes of message text", ParamId::budget_message_bytes, b.message_bytes);
  }
}

// The level's bounds (level_bounds.h): the corners given, the box in force, and that the player
// starts inside it. `issues`: the reader's, to tell whether the bounds object itself was sound.
void read_bounds(JsonReader& r, const json& doc, Level& level, const std::vector<JsonIssue>& issues) {
  const auto key = [](std::string_view name) -> const LevelKey& {
    return level_key(LevelObject::bounds, name);
  };
  LevelBounds& b = level.bounds;
  const std::size_t issues_before = issues.size();
  const auto it = doc.find("bounds");
  const std::string path = "/bounds";
  if (it != doc.end() && r.object(*it, path, level_key_names(LevelObject::bounds))) {
    const json& j = *it;
    if (j.contains("min")) b.min = read_vec2(r, j, path, key("min"), {});
    if (j.contains("max")) b.max = read_vec2(r, j, path, key("max"), {});
    b.margin = read_number(r, j, path, key("margin"), b.margin);
    if (b.min && b.max && j.contains("margin"))
      r.fail(join_path(path, "margin"),
             "has no effect when min and max are both given (it places a side that is not given): remove it");
  }
  b.box = resolve_bounds(b, level_extent(level));
  if (issues.size() != issues_before) return;
  // As the file writes them: the bounds object's corners and the player's position.
  const auto written = [&doc](const std::string& pointer) {
    return JsonReader::describe(doc.at(json::json_pointer(pointer)));
  };
  if ((b.min || b.max) && !(b.box.min.x < b.box.max.x && b.box.min.y < b.box.max.y)) {
    const auto shown = [](Vec2 v) { return JsonReader::describe(json::array({v.x, v.y})); };
    if (b.min && b.max)
      r.fail(join_path(path, "max"), "must be greater than min on both axes, got " + written("/bounds/max") +
                                         " with min " + written("/bounds/min"));
    else if (b.min)  // the computed top is open: only x can fail
      r.fail(join_path(path, "min"),
             "must be left of the computed right side x = " + JsonReader::describe(b.box.max.x) +
                 " (the level's geometry plus margin), got " + written("/bounds/min"));
    else  // computed sides lie beyond the geometry: only a given one can cross them
      r.fail(join_path(path, "max"), "must be above and right of the computed lower-left corner " +
                                         shown(b.box.min) + " (the level's geometry less margin), got " +
                                         written("/bounds/max"));
    return;
  }
  // The player starts inside: a level lost before its first tick is a mistake. A player vehicle
  // starts where its chassis does.
  std::size_t player = 0;
  for (std::size_t i = 0; i < level.tires.size(); ++i)
    if (level.tires[i].player) player = i;
  Vec2 start;
  std::string position;
  const auto vehicle = std::find_if(level.vehicles.begin(), level.vehicles.end(),
                                    [](const LevelVehicle& v) { return v.player; });
  if (vehicle != level.vehicles.end()) {
    start = vehicle->spec.chassis.position;
    position = join_path(
        join_path(join_path("/vehicles", static_cast<std::size_t>(vehicle - level.vehicles.begin())),
                  "chassis"),
        "position");
  } else if (player < level.tires.size()) {
    start = level.tires[player].position;
    position = join_path(join_path("/tires", player), "position");
  } else {
    return;
  }
  if (!doc.contains(json::json_pointer(position))) return;  // missing: reported as such
  const std::string where = " the player's start " + written(position) + " (" + position + ")";
  if (b.min && !(b.min->x <= start.x && b.min->y <= start.y))
    r.fail(join_path(path, "min"), "must be below and left of" + where + ", got " + written("/bounds/min"));
  if (b.max && !(start.x <= b.max->x && start.y <= b.max->y))
    r.fail(join_path(path, "max"), "must be above and right of" + where + ", got " + written("/bounds/max"));
}

// The level's medals (level_medals.h): each time given, gold < silver < bronze, and bronze within
// the time limit (a medal the time limit takes away first cannot be won).
void read_medals(JsonReader& r, const json& doc, Level& level, const std::vector<JsonIssue>& issues) {
  const auto it = doc.find("medals");
  const std::string path = "/medals";
  if (it == doc.end() || !r.object(*it, path, level_key_names(LevelObject::medals))) return;
  const auto key = [](std::string_view name) -> const LevelKey& {
    return level_key(LevelObject::medals, name);
  };
  const json& j = *it;
  const std::size_t issues_before = issues.size();
  LevelMedals m;
  m.gold = read_number(r, j, path, key("gold"), 0.0);
  m.silver = read_number(r, j, path, key("silver"), 0.0);
  m.bronze = read_number(r, j, path, key("bronze"), 0.0);
  if (issues.size() != issues_before) return;
  // The values as read; the message quotes them as the file writes them.
  const auto order = [&](const char* faster, double a, const char* slower, double b) {
    if (!(a < b))
      r.fail(join_path(path, faster), std::string("must be less than ") + slower + " (" +
                                          JsonReader::describe(j[slower]) + "), got " +
                                          JsonReader::describe(j[faster]));
  };
  order("gold", m.gold, "silver", m.silver);
  order("silver", m.silver, "bronze", m.bronze);
  if (level.script.time_limit && m.bronze > *level.script.time_limit)
    r.fail(join_path(path, "bronze"), "must be at most the time limit (" +
                                          JsonReader::describe(doc["time_limit"]) + " s), got " +
                                          JsonReader::describe(j["bronze"]));
  if (issues.size() == issues_before) level.medals = m;
}

void check_totals(JsonReader& r, const json& doc, const Level& level) {
  Totals t;
  for (std::size_t i = 0; i < level.tires.size(); ++i)
    count_tire(t, static_cast<std::size_t>(level.tires[i].segments), join_path("/tires", i));
  for (std::size_t i = 0; i < level.props.size(); ++i)
    count_prop(t, level.props[i].points.size() + level.props[i].path.waypoints.size(),
               join_path("/props", i));
  for (std::size_t i = 0; i < level.vehicles.size(); ++i) {
    const std::string path = join_path("/vehicles", i);
    const VehicleSpec& v = level.vehicles[i].spec;
    count_prop(t, v.chassis.points.size(), join_path(path, "chassis"));
    for (std::size_t w = 0; w < v.wheels.size(); ++w)
      count_tire(t, static_cast<std::size_t>(v.wheels[w].tire.segments),
                 join_path(join_path(path, "wheels"), w));
  }
  // The script's spawn actions, read from the document so that each is named by its own path.
  if (const auto triggers = doc.find("triggers"); triggers != doc.end() && triggers->is_array()) {
    for (std::size_t i = 0; i < triggers->size(); ++i) {
      const json& trigger = (*triggers)[i];
      if (!trigger.is_object() || !trigger.contains("do") || !trigger["do"].is_array()) continue;
      const json& actions = trigger["do"];
      for (std::size_t k = 0; k < actions.size(); ++k) {
        const json& a = actions[k];
        if (!a.is_object() || !a.contains("action") || !a["action"].is_string()) continue;
        const std::string path = join_path(join_path(join_path("/triggers", i), "do"), k);
        const std::string& action = a["action"].get_ref<const std::string&>();
        if (action == "spawn_tire" && a.contains("tire") && a["tire"].is_object())
          count_tire(t, spawned_segments(a["tire"]), path);
        if (action == "spawn_prop" && a.contains("prop") && a["prop"].is_object()) {
          const json& prop = a["prop"];
          const auto path_it = prop.find("path");
          count_prop(
              t,
              array_size(prop, "points") +
                  (path_it != prop.end() && path_it->is_object() ? array_size(*path_it, "waypoints") : 0),
              path);
        }
      }
    }
  }
  check_budgets(r, doc, level);
  const auto over = [&r](const std::string& path, const std::string& what, std::size_t total,
                         std::size_t limit) {
    r.fail(path, what + " may add up to at most " + std::to_string(limit) + ", got " + std::to_string(total) +
                     " (this entry is the first past the limit)");
  };
  if (!t.tires_path.empty())
    over(t.tires_path, "the level's tires, with those its script spawns,", t.tires, LevelLimits::max_tires);
  if (!t.particles_path.empty())
    over(t.particles_path,
         "the particles of the level's tires (2 x segments each), with those its script spawns,", t.particles,
         kMaxParticles);
  if (!t.props_path.empty())
    over(t.props_path, "the level's props, with those its script spawns,", t.props, LevelLimits::max_props);
  if (!t.points_path.empty())
    over(t.points_path,
         "the points of the level's props (chain, polygon and path points), with those its script spawns,",
         t.points, kMaxPoints);
}

}  // namespace

std::optional<Level> read_level(const json& doc, std::vector<JsonIssue>& issues) {
  const std::size_t issues_before = issues.size();
  JsonReader r(issues);
  Level level;
  if (!r.object(doc, "", level_key_names(LevelObject::root))) return std::nullopt;
  level.name = read_string(r, doc, "", level_key(LevelObject::root, "name"), "");
  level.description = read_string(r, doc, "", level_key(LevelObject::root, "description"), level.description);
  level.gravity = read_gravity(r, doc, "", "gravity", level.gravity);
  if (const auto it = doc.find("solver"); it != doc.end()) level.solver = read_solver(r, *it, "/solver");
  if (const auto it = doc.find("budgets"); it != doc.end()) level.budgets = read_budgets(r, *it, "/budgets");

  std::string first_player;  // the player tire's or vehicle's path
  if (const auto it = doc.find("tires"); it != doc.end() && r.array(*it, "/tires", LevelLimits::max_tires)) {
    for (std::size_t i = 0; i < it->size(); ++i) {
      const std::string path = join_path("/tires", i);
      level.tires.push_back(read_tire(r, (*it)[i], path));
      if (!level.tires.back().player) continue;
      if (first_player.empty())
        first_player = path;
      else
        r.fail(path + "/player", "only one tire may be the player, and " + first_player + " already is");
    }
  }
  if (const auto it = doc.find("obstacles");
      it != doc.end() && r.array(*it, "/obstacles", LevelLimits::max_obstacles)) {
    for (std::size_t i = 0; i < it->size(); ++i)
      level.obstacles.push_back(read_obstacle(r, (*it)[i], join_path("/obstacles", i)));
  }
  if (const auto it = doc.find("props"); it != doc.end() && r.array(*it, "/props", LevelLimits::max_props)) {
    std::map<std::string, std::size_t> first_with_name;  // a lookup, not a scan: 10 000 props stay quick
    for (std::size_t i = 0; i < it->size(); ++i) {
      const std::string path = join_path("/props", i);
      level.props.push_back(read_prop(r, (*it)[i], path));
      const std::string& name = level.props.back().name;
      if (name.empty()) continue;
      const auto [first, inserted] = first_with_name.emplace(name, i);
      if (!inserted)
        r.fail(path + "/name", "must be unique, and /props/" + std::to_string(first->second) +
                                   " is already \"" + printable(name) + "\"");
    }
  }
  if (const auto it = doc.find("vehicles");
      it != doc.end() && r.array(*it, "/vehicles", LevelLimits::max_vehicles)) {
    for (std::size_t i = 0; i < it->size(); ++i) {
      const std::string path = join_path("/vehicles", i);
      level.vehicles.push_back(read_vehicle(r, (*it)[i], path));
      if (!level.vehicles.back().player) continue;
      if (first_player.empty())
        first_player = path;
      else
        r.fail(path + "/player",
               "only one tire or vehicle may be the player, and " + first_player + " already is");
    }
    if (!level.vehicles.empty() && level.solver.method != SolverMethod::global)
      r.fail("/vehicles", std::string("a level with vehicles needs the global solver method (\"solver\": "
                                      "{\"method\": \"global\"}), and this one's is \"") +
                              method_name(level.solver.method) + "\"");
  }
  std::vector<std::string> prop_names;
  for (const PropSpec& p : level.props)
    if (!p.name.empty()) prop_names.push_back(p.name);
  level.script = read_script(r, doc, prop_names);
  read_bounds(r, doc, level, issues);
  read_medals(r, doc, level, issues);
  check_totals(r, doc, level);
  if (issues.size() != issues_before) return std::nullopt;
  return level;
}

}  // namespace tire

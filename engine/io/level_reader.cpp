// Level validation: every key of levels/README.md, with its unit, default and range.
#include "level_reader.h"

#include <algorithm>
#include <map>

#include "script_reader.h"
#include "tire/io/level.h"
#include "tire/rigid/prop_geometry.h"

namespace tire {

namespace {

using json = nlohmann::json;

const Range kCoordinate{-LevelLimits::max_coordinate, LevelLimits::max_coordinate};
const Range kVelocity{-1000.0, 1000.0};
const Range kFriction{0.0, 10.0};

SolverConfig read_solver(JsonReader& r, const json& j, const std::string& path) {
  SolverConfig s;
  if (!r.object(
          j, path,
          {"dt", "substeps", "iterations", "damping", "tunnel_clamp", "ground_normal_y", "method", "sleep"}))
    return s;
  const std::string method =
      r.choice(j, path, "method", method_name(s.method),
               {method_name(SolverMethod::gauss_seidel), method_name(SolverMethod::global)});
  for (const SolverMethod m : kSolverMethods)
    if (method == method_name(m)) s.method = m;
  s.sleep = r.boolean(j, path, "sleep", s.sleep);
  s.dt = read_parameter(r, j, path, ParamId::solver_dt, s.dt);
  s.substeps = read_integer_parameter(r, j, path, ParamId::solver_substeps, s.substeps);
  s.iterations = read_integer_parameter(r, j, path, ParamId::solver_iterations, s.iterations);
  s.damping = read_parameter(r, j, path, ParamId::solver_damping, s.damping);
  s.tunnel_clamp = read_parameter(r, j, path, ParamId::solver_tunnel_clamp, s.tunnel_clamp);
  s.ground_normal_y = read_parameter(r, j, path, ParamId::solver_ground_normal_y, s.ground_normal_y);
  return s;
}

TireCompliance read_compliance(JsonReader& r, const json& j, const std::string& path) {
  TireCompliance c;
  if (!r.object(j, path, {"outer", "inner", "spoke", "pressure"})) return c;
  c.outer = read_parameter(r, j, path, ParamId::tire_compliance_outer, c.outer);
  c.inner = read_parameter(r, j, path, ParamId::tire_compliance_inner, c.inner);
  c.spoke = read_parameter(r, j, path, ParamId::tire_compliance_spoke, c.spoke);
  c.pressure = read_parameter(r, j, path, ParamId::tire_compliance_pressure, c.pressure);
  return c;
}

}  // namespace

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

TireSpec read_tire(JsonReader& r, const json& j, const std::string& path) {
  TireSpec t;
  if (!r.object(
          j, path,
          {"position", "velocity", "angle", "angular_velocity", "outer_radius", "inner_radius", "segments",
           "mass", "friction", "kinetic_friction", "pressure", "compliance", "spokes", "material_damping",
           "rolling_resistance", "player", "drive_acceleration", "jump_speed", "max_speed"}))
    return t;
  t.position = r.vec2(j, path, "position", t.position, kCoordinate, "m", true);
  t.velocity = r.vec2(j, path, "velocity", t.velocity, kVelocity, "m/s");
  t.angle = read_parameter(r, j, path, ParamId::tire_angle, t.angle);
  t.angular_velocity = read_parameter(r, j, path, ParamId::tire_angular_velocity, t.angular_velocity);
  t.outer_radius = read_parameter(r, j, path, ParamId::tire_outer_radius, t.outer_radius);
  t.inner_radius = read_parameter(r, j, path, ParamId::tire_inner_radius, t.inner_radius);
  if (j.contains("outer_radius") || j.contains("inner_radius")) {
    if (t.inner_radius >= t.outer_radius)
      r.fail(join_path(path, "inner_radius"), "must be less than outer_radius (" +
                                                  JsonReader::describe(t.outer_radius) + "), got " +
                                                  JsonReader::describe(t.inner_radius));
  }
  t.segments = read_integer_parameter(r, j, path, ParamId::tire_segments, t.segments);
  t.mass = read_parameter(r, j, path, ParamId::tire_mass, t.mass);
  t.friction = read_parameter(r, j, path, ParamId::tire_friction, t.friction);
  // Kinetic friction defaults to the static coefficient (the row's default_follows).
  t.kinetic_friction = read_parameter(r, j, path, ParamId::tire_kinetic_friction, t.friction);
  t.pressure = read_parameter(r, j, path, ParamId::tire_pressure, t.pressure);
  if (const auto it = j.find("compliance"); it != j.end())
    t.compliance = read_compliance(r, *it, join_path(path, "compliance"));
  t.spokes = r.choice(j, path, "spokes", "cross", {"radial", "cross"}) == "radial" ? SpokePattern::radial
                                                                                   : SpokePattern::cross;
  t.material_damping = read_parameter(r, j, path, ParamId::tire_material_damping, t.material_damping);
  t.rolling_resistance = read_parameter(r, j, path, ParamId::tire_rolling_resistance, t.rolling_resistance);
  t.player = r.boolean(j, path, "player", t.player);
  t.drive_acceleration = read_parameter(r, j, path, ParamId::tire_drive_acceleration, t.drive_acceleration);
  t.jump_speed = read_parameter(r, j, path, ParamId::tire_jump_speed, t.jump_speed);
  t.max_speed = read_parameter(r, j, path, ParamId::tire_max_speed, t.max_speed);
  return t;
}

namespace {

// Points far enough apart for Box2D, which welds vertices closer than its linear slop.
constexpr double kMinPointSpacing = 0.01;  // m

std::vector<Vec2> read_points(JsonReader& r, const json& j, const std::string& path, const char* key,
                              std::size_t min_count, std::size_t max_count) {
  std::vector<Vec2> points;
  const std::string p = join_path(path, key);
  const auto it = j.find(key);
  if (it == j.end()) {
    r.fail(p, "is required: an array of " + std::to_string(min_count) + " to " + std::to_string(max_count) +
                  " points [x, y] in m");
    return points;
  }
  if (!it->is_array() || it->size() < min_count || it->size() > max_count) {
    r.fail(p, "must be an array of " + std::to_string(min_count) + " to " + std::to_string(max_count) +
                  " points [x, y] in m, got " + JsonReader::describe(*it));
    return points;
  }
  for (std::size_t i = 0; i < it->size(); ++i) {
    const json& v = (*it)[i];
    const bool ok = v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number() &&
                    kCoordinate.contains(v[0].get<double>()) && kCoordinate.contains(v[1].get<double>());
    if (!ok) {
      r.fail(join_path(p, i),
             "must be [x, y] with each in " + kCoordinate.text() + " m, got " + JsonReader::describe(v));
      continue;
    }
    points.push_back({v[0].get<double>(), v[1].get<double>()});
  }
  return points;
}

KinematicPath read_path(JsonReader& r, const json& j, const std::string& path) {
  KinematicPath k;
  if (!r.object(j, path, {"waypoints", "speed", "mode", "running"})) return k;
  k.waypoints = read_points(r, j, path, "waypoints", 1, 1000);
  k.speed = r.number(j, path, "speed", k.speed, {0.0, 1000.0, true}, "m/s");
  const std::string mode = r.choice(j, path, "mode", "loop", {"once", "loop", "ping_pong"});
  k.mode = mode == "once" ? PathMode::once : mode == "ping_pong" ? PathMode::ping_pong : PathMode::loop;
  k.running = r.boolean(j, path, "running", k.running);
  return k;
}

Obstacle read_obstacle(JsonReader& r, const json& j, const std::string& path) {
  Obstacle o;
  if (!r.object(j, path, {"min", "max", "friction"})) return o;
  o.box.min = r.vec2(j, path, "min", {}, kCoordinate, "m", true);
  o.box.max = r.vec2(j, path, "max", {}, kCoordinate, "m", true);
  if (j.contains("min") && j.contains("max") && !(o.box.min.x < o.box.max.x && o.box.min.y < o.box.max.y))
    r.fail(join_path(path, "max"), "must be greater than min on both axes, got " +
                                       JsonReader::describe(j["max"]) + " with min " +
                                       JsonReader::describe(j["min"]));
  o.friction = r.number(j, path, "friction", o.friction, kFriction, "");
  return o;
}

}  // namespace

PropSpec read_prop(JsonReader& r, const json& j, const std::string& path) {
  PropSpec p;
  if (!r.object(j, path,
                {"name", "shape", "type", "position", "angle", "size", "radius", "points", "loop",
                 "thickness", "density", "friction", "restitution", "velocity", "angular_velocity", "path"}))
    return p;
  p.name = r.string(j, path, "name", "", 100);
  if (!j.contains("shape"))
    r.fail(join_path(path, "shape"), "is required: one of \"box\", \"circle\", \"polygon\", \"chain\"");
  const std::string shape = r.choice(j, path, "shape", "box", {"box", "circle", "polygon", "chain"});
  p.shape = shape == "circle"    ? PropShape::circle
            : shape == "polygon" ? PropShape::polygon
            : shape == "chain"   ? PropShape::chain
                                 : PropShape::box;
  const std::string type = r.choice(j, path, "type", "static", {"static", "dynamic", "kinematic"});
  p.type = type == "dynamic"     ? PropType::dynamic_body
           : type == "kinematic" ? PropType::kinematic_body
                                 : PropType::static_body;
  p.position = r.vec2(j, path, "position", p.position, kCoordinate, "m");
  p.angle = r.number(j, path, "angle", p.angle, {-100.0, 100.0}, "rad");

  // Shape keys: each belongs to some shapes only.
  auto only_for = [&](const char* key, std::initializer_list<PropShape> shapes, const char* which) {
    if (j.contains(key) && std::find(shapes.begin(), shapes.end(), p.shape) == shapes.end())
      r.fail(join_path(path, key),
             std::string("applies only to ") + which + " props, and this one is a " + shape);
  };
  only_for("size", {PropShape::box}, "box");
  only_for("radius", {PropShape::circle}, "circle");
  only_for("points", {PropShape::polygon, PropShape::chain}, "polygon and chain");
  only_for("loop", {PropShape::chain}, "chain");
  only_for("thickness", {PropShape::chain}, "chain");
  switch (p.shape) {
    case PropShape::box:
      p.size =
          r.vec2(j, path, "size", p.size, {kMinPointSpacing, 2.0 * LevelLimits::max_coordinate}, "m", true);
      break;
    case PropShape::circle:
      p.radius = r.number(j, path, "radius", p.radius, {kMinPointSpacing, 1000.0}, "m", true);
      break;
    case PropShape::polygon:
      p.points = read_points(r, j, path, "points", 3, 8);
      if (p.points.size() >= 3 && p.points.size() == j["points"].size() && !is_convex_ccw(p.points))
        r.fail(join_path(path, "points"), "must be a convex polygon in counter-clockwise order, got " +
                                              JsonReader::describe(j["points"]));
      break;
    case PropShape::chain:
      p.points = read_points(r, j, path, "points", 2, 100000);
      p.loop = r.boolean(j, path, "loop", p.loop);
      p.thickness = r.number(j, path, "thickness", p.thickness, {kMinPointSpacing, 100.0}, "m");
      if (p.loop && p.points.size() < 3)
        r.fail(join_path(path, "points"), "a closed chain needs at least 3 points");
      if (p.type != PropType::static_body)
        r.fail(join_path(path, "type"), "a chain can only be static (it has no mass), got \"" + type + "\"");
      break;
  }
  for (std::size_t i = 0; i + 1 < p.points.size() + (p.loop ? 1 : 0) && p.points.size() >= 2; ++i) {
    const Vec2 a = p.points[i], b = p.points[(i + 1) % p.points.size()];
    if (length(b - a) < kMinPointSpacing) {
      r.fail(join_path(join_path(path, "points"), (i + 1) % p.points.size()),
             "must be at least 0.01 m from the point before it");
      break;
    }
  }
  p.density = r.number(j, path, "density", p.density, {0.0, 1e5, true}, "kg/m^2");
  p.friction = r.number(j, path, "friction", p.friction, kFriction, "");
  p.restitution = r.number(j, path, "restitution", p.restitution, {0.0, 1.0}, "");
  p.velocity = r.vec2(j, path, "velocity", p.velocity, kVelocity, "m/s");
  p.angular_velocity = r.number(j, path, "angular_velocity", p.angular_velocity, {-1000.0, 1000.0}, "rad/s");
  if (const auto it = j.find("path"); it != j.end()) {
    if (p.type != PropType::kinematic_body)
      r.fail(join_path(path, "path"), "applies only to kinematic props, and this one is " + type);
    p.path = read_path(r, *it, join_path(path, "path"));
  }
  return p;
}

namespace {

// Budgets over the whole level, beyond the per-array limits: a file within every one of those can
// still describe a world too big to build (10 000 tires of 256 segments are 5 million particles,
// half a kilobyte each). What the script spawns counts too, each spawn action once.
constexpr std::size_t kMaxParticles = 1'000'000;  // 2 × segments per tire
constexpr std::size_t kMaxPoints = 200'000;       // chain, polygon and path points over all props

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

// A spawn action's tire segments as the tire reader takes them (28 when missing or invalid).
std::size_t spawned_segments(const json& tire) {
  const auto it = tire.find("segments");
  if (it == tire.end() || !it->is_number()) return 28;
  const double s = it->get<double>();
  return s >= 6 && s <= 256 ? static_cast<std::size_t>(s) : 28;
}

void check_totals(JsonReader& r, const json& doc, const Level& level) {
  Totals t;
  for (std::size_t i = 0; i < level.tires.size(); ++i)
    count_tire(t, static_cast<std::size_t>(level.tires[i].segments), join_path("/tires", i));
  for (std::size_t i = 0; i < level.props.size(); ++i)
    count_prop(t, level.props[i].points.size() + level.props[i].path.waypoints.size(),
               join_path("/props", i));
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
  if (!r.object(doc, "",
                {"$schema", "name", "description", "gravity", "solver", "tires", "obstacles", "props",
                 "regions", "goal", "time_limit", "counters", "triggers"}))
    return std::nullopt;
  level.name = r.string(doc, "", "name", "", 200, true);
  level.description = r.string(doc, "", "description", "", 2000);
  level.gravity = read_gravity(r, doc, "", "gravity", level.gravity);
  if (const auto it = doc.find("solver"); it != doc.end()) level.solver = read_solver(r, *it, "/solver");

  if (const auto it = doc.find("tires"); it != doc.end() && r.array(*it, "/tires", LevelLimits::max_tires)) {
    std::string first_player;
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
                                   " is already \"" + name + "\"");
    }
  }
  std::vector<std::string> prop_names;
  for (const PropSpec& p : level.props)
    if (!p.name.empty()) prop_names.push_back(p.name);
  level.script = read_script(r, doc, prop_names);
  check_totals(r, doc, level);
  if (issues.size() != issues_before) return std::nullopt;
  return level;
}

}  // namespace tire

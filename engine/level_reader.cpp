// Level validation: every key of levels/README.md, with its unit, default and range.
#include <algorithm>

#include "level.h"
#include "level_reader.h"

namespace tire {

namespace {

using json = nlohmann::json;

const Range kCoordinate{-LevelLimits::max_coordinate, LevelLimits::max_coordinate};
const Range kVelocity{-1000.0, 1000.0};
const Range kFriction{0.0, 10.0};
const Range kCompliance{0.0, 1.0};

SolverConfig read_solver(JsonReader& r, const json& j, const std::string& path) {
  SolverConfig s;
  if (!r.object(j, path, {"dt", "substeps", "iterations", "damping", "tunnel_clamp", "ground_normal_y"}))
    return s;
  s.dt = r.number(j, path, "dt", s.dt, {1e-4, 0.1}, "s");
  s.substeps = r.integer(j, path, "substeps", s.substeps, {1, 256});
  s.iterations = r.integer(j, path, "iterations", s.iterations, {1, 64});
  s.damping = r.number(j, path, "damping", s.damping, {0.0, 1000.0}, "1/s");
  s.tunnel_clamp = r.number(j, path, "tunnel_clamp", s.tunnel_clamp, {0.1, 10.0}, "segments per substep");
  s.ground_normal_y = r.number(j, path, "ground_normal_y", s.ground_normal_y, {0.0, 1.0}, "");
  return s;
}

TireCompliance read_compliance(JsonReader& r, const json& j, const std::string& path) {
  TireCompliance c;
  if (!r.object(j, path, {"outer", "inner", "spoke", "pressure"})) return c;
  c.outer = r.number(j, path, "outer", c.outer, kCompliance, "m/N");
  c.inner = r.number(j, path, "inner", c.inner, kCompliance, "m/N");
  c.spoke = r.number(j, path, "spoke", c.spoke, kCompliance, "m/N");
  c.pressure = r.number(j, path, "pressure", c.pressure, kCompliance, "m^4/J");
  return c;
}

}  // namespace

TireSpec read_tire(JsonReader& r, const json& j, const std::string& path) {
  TireSpec t;
  if (!r.object(j, path,
                {"position", "velocity", "angle", "angular_velocity", "outer_radius", "inner_radius",
                 "segments", "mass", "friction", "kinetic_friction", "pressure", "compliance", "spokes", "material_damping", "rolling_resistance",
                 "player", "drive_acceleration", "jump_speed", "max_speed"}))
    return t;
  t.position = r.vec2(j, path, "position", t.position, kCoordinate, "m", true);
  t.velocity = r.vec2(j, path, "velocity", t.velocity, kVelocity, "m/s");
  t.angle = r.number(j, path, "angle", t.angle, {-100.0, 100.0}, "rad");
  t.angular_velocity = r.number(j, path, "angular_velocity", t.angular_velocity, {-1000.0, 1000.0}, "rad/s");
  t.outer_radius = r.number(j, path, "outer_radius", t.outer_radius, {0.01, 100.0}, "m");
  t.inner_radius = r.number(j, path, "inner_radius", t.inner_radius, {0.005, 100.0}, "m");
  if (j.contains("outer_radius") || j.contains("inner_radius")) {
    if (t.inner_radius >= t.outer_radius)
      r.fail(join_path(path, "inner_radius"), "must be less than outer_radius (" +
                                                  JsonReader::describe(t.outer_radius) + "), got " +
                                                  JsonReader::describe(t.inner_radius));
  }
  t.segments = r.integer(j, path, "segments", t.segments, {6, 256});
  t.mass = r.number(j, path, "mass", t.mass, {0.0, 1e6, true}, "kg");
  t.friction = r.number(j, path, "friction", t.friction, kFriction, "");
  // Kinetic friction defaults to the static coefficient.
  t.kinetic_friction = r.number(j, path, "kinetic_friction", t.friction, kFriction, "");
  t.pressure = r.number(j, path, "pressure", t.pressure, {0.1, 4.0}, "(fraction of the rest area)");
  if (const auto it = j.find("compliance"); it != j.end())
    t.compliance = read_compliance(r, *it, join_path(path, "compliance"));
  t.spokes = r.choice(j, path, "spokes", "cross", {"radial", "cross"}) == "radial" ? SpokePattern::radial
                                                                                   : SpokePattern::cross;
  t.material_damping = r.number(j, path, "material_damping", t.material_damping, {0.0, 1.0}, "s");
  t.rolling_resistance = r.number(j, path, "rolling_resistance", t.rolling_resistance, {0.0, 1.0}, "");
  t.player = r.boolean(j, path, "player", t.player);
  t.drive_acceleration = r.number(j, path, "drive_acceleration", t.drive_acceleration, {0.0, 1000.0}, "m/s^2");
  t.jump_speed = r.number(j, path, "jump_speed", t.jump_speed, {0.0, 100.0}, "m/s");
  t.max_speed = r.number(j, path, "max_speed", t.max_speed, {0.0, 1000.0, true}, "m/s");
  return t;
}

namespace {

Obstacle read_obstacle(JsonReader& r, const json& j, const std::string& path) {
  Obstacle o;
  if (!r.object(j, path, {"min", "max", "friction"})) return o;
  o.box.min = r.vec2(j, path, "min", {}, kCoordinate, "m", true);
  o.box.max = r.vec2(j, path, "max", {}, kCoordinate, "m", true);
  if (j.contains("min") && j.contains("max") && !(o.box.min.x < o.box.max.x && o.box.min.y < o.box.max.y))
    r.fail(join_path(path, "max"), "must be greater than min on both axes, got " + JsonReader::describe(j["max"]) +
                                       " with min " + JsonReader::describe(j["min"]));
  o.friction = r.number(j, path, "friction", o.friction, kFriction, "");
  return o;
}

}  // namespace

std::optional<Level> read_level(const json& doc, std::vector<JsonIssue>& issues) {
  const std::size_t issues_before = issues.size();
  JsonReader r(issues);
  Level level;
  if (!r.object(doc, "", {"$schema", "name", "description", "gravity", "solver", "tires", "obstacles"}))
    return std::nullopt;
  level.name = r.string(doc, "", "name", "", 200, true);
  level.description = r.string(doc, "", "description", "", 2000);
  level.gravity = r.vec2(doc, "", "gravity", level.gravity, {-1000.0, 1000.0}, "m/s^2");
  if (const auto it = doc.find("solver"); it != doc.end()) level.solver = read_solver(r, *it, "/solver");

  if (const auto it = doc.find("tires"); it != doc.end() && r.array(*it, "/tires", LevelLimits::max_tires)) {
    std::string first_player;
    for (std::size_t i = 0; i < it->size(); ++i) {
      const std::string path = join_path("/tires", i);
      level.tires.push_back(read_tire(r, (*it)[i], path));
      if (!level.tires.back().player) continue;
      if (first_player.empty()) first_player = path;
      else r.fail(path + "/player", "only one tire may be the player, and " + first_player + " already is");
    }
  }
  if (const auto it = doc.find("obstacles"); it != doc.end() &&
                                             r.array(*it, "/obstacles", LevelLimits::max_obstacles)) {
    for (std::size_t i = 0; i < it->size(); ++i)
      level.obstacles.push_back(read_obstacle(r, (*it)[i], join_path("/obstacles", i)));
  }
  if (issues.size() != issues_before) return std::nullopt;
  return level;
}

}  // namespace tire

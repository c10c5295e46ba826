// The table of level keys (tire/io/level_format.h) against the validator and the reference pages:
// every check is driven from the table, so a key added to it and not to the readers (or the other
// way round) fails here.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "error_messages.h"
#include "tire/io/level_format.h"
#include "tire_fixtures.h"

using tire_test::has;
using tire_test::joined;

using namespace tire;
using namespace tire::test;
using json = nlohmann::json;

namespace {

constexpr std::array kObjects{LevelObject::root,       LevelObject::solver,   LevelObject::tire,
                              LevelObject::compliance, LevelObject::obstacle, LevelObject::prop,
                              LevelObject::path,       LevelObject::region,   LevelObject::budgets,
                              LevelObject::bounds,     LevelObject::medals,   LevelObject::vehicle,
                              LevelObject::chassis,    LevelObject::wheel,    LevelObject::head};
static_assert(kObjects.size() == kLevelObjects);

const char* object_name(LevelObject o) {
  switch (o) {
    case LevelObject::root: return "root";
    case LevelObject::solver: return "solver";
    case LevelObject::tire: return "tire";
    case LevelObject::compliance: return "compliance";
    case LevelObject::obstacle: return "obstacle";
    case LevelObject::prop: return "prop";
    case LevelObject::path: return "path";
    case LevelObject::region: return "region";
    case LevelObject::budgets: return "budgets";
    case LevelObject::bounds: return "bounds";
    case LevelObject::medals: return "medals";
    case LevelObject::vehicle: return "vehicle";
    case LevelObject::chassis: return "chassis";
    case LevelObject::wheel: return "wheel";
    case LevelObject::head: return "head";
  }
  return "?";
}

// A minimal valid vehicle: a box chassis on two wheels.
json minimal_vehicle() {
  return {{"chassis", {{"shape", "box"}, {"size", {1.6, 0.3}}, {"position", {0, 1}}}},
          {"wheels", {{{"axle", {-0.6, -0.3}}}, {{"axle", {0.6, -0.3}}}}}};
}

// A minimal valid level holding one object of kind `object` (a prop of `shape`), and the JSON
// pointer of that object in it.
struct Placed {
  json doc;
  std::string pointer;
  json& object() { return doc[json::json_pointer(pointer)]; }
};

json minimal_prop(std::string_view shape) {
  if (shape == "circle") return {{"shape", "circle"}, {"radius", 0.5}};
  if (shape == "polygon") return {{"shape", "polygon"}, {"points", {{0, 0}, {1, 0}, {0, 1}}}};
  if (shape == "chain") return {{"shape", "chain"}, {"points", {{0, 0}, {1, 0}}}};
  return {{"shape", "box"}, {"size", {1, 1}}};
}

Placed place(LevelObject object, std::string_view shape = "box") {
  Placed p{{{"name", "n"}}, ""};
  switch (object) {
    case LevelObject::root: break;
    case LevelObject::solver:
      p.doc["solver"] = json::object();
      p.pointer = "/solver";
      break;
    case LevelObject::tire:
      p.doc["tires"] = {{{"position", {0, 0.5}}}};
      p.pointer = "/tires/0";
      break;
    case LevelObject::compliance:
      p.doc["tires"] = {{{"position", {0, 0.5}}, {"compliance", json::object()}}};
      p.pointer = "/tires/0/compliance";
      break;
    case LevelObject::obstacle:
      p.doc["obstacles"] = {{{"min", {-1, -1}}, {"max", {1, 0}}}};
      p.pointer = "/obstacles/0";
      break;
    case LevelObject::prop:
      p.doc["props"] = json::array({minimal_prop(shape)});
      p.pointer = "/props/0";
      break;
    case LevelObject::path: {
      json prop = minimal_prop("box");
      prop["type"] = "kinematic";
      prop["path"] = {{"waypoints", {{0, 0}}}};
      p.doc["props"] = json::array({prop});
      p.pointer = "/props/0/path";
      break;
    }
    case LevelObject::region:
      p.doc["regions"] = {{{"name", "r"}, {"min", {0, 0}}, {"max", {1, 1}}}};
      p.pointer = "/regions/0";
      break;
    case LevelObject::budgets:
      p.doc["budgets"] = json::object();
      p.pointer = "/budgets";
      break;
    case LevelObject::bounds:
      p.doc["bounds"] = json::object();
      p.pointer = "/bounds";
      break;
    case LevelObject::medals:
      p.doc["medals"] = {{"gold", 10}, {"silver", 20}, {"bronze", 30}};
      p.pointer = "/medals";
      break;
    case LevelObject::vehicle:
      p.doc["vehicles"] = json::array({minimal_vehicle()});
      p.pointer = "/vehicles/0";
      break;
    case LevelObject::chassis: {
      json v = minimal_vehicle();
      v["chassis"] = minimal_prop(shape == "chain" ? "box" : shape);
      p.doc["vehicles"] = json::array({v});
      p.pointer = "/vehicles/0/chassis";
      break;
    }
    case LevelObject::wheel:
      p.doc["vehicles"] = json::array({minimal_vehicle()});
      p.pointer = "/vehicles/0/wheels/0";
      break;
    case LevelObject::head: {
      json v = minimal_vehicle();
      v["head"] = {{"position", {0, 0.4}}, {"radius", 0.1}};
      p.doc["vehicles"] = json::array({v});
      p.pointer = "/vehicles/0/head";
      break;
    }
  }
  return p;
}

// The shape a prop needs for `key` to apply to it.
std::string shape_for(const LevelKey& key) { return key.shapes.empty() ? "box" : key.shapes.front(); }

// A minimal level with `key` of `object` set to `value`, and the key's JSON pointer.
std::pair<json, std::string> with_key(LevelObject object, const LevelKey& key, const json& value) {
  Placed p = place(object, shape_for(key));
  p.object()[key.key] = value;
  return {p.doc, p.pointer + "/" + key.key};
}

std::vector<std::string> errors_of(const json& doc) { return load_level_text(doc.dump(), "x.json").errors; }

std::string quoted(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "\"" : ", \"") + n + "\"";
  return out;
}

// Every value a level loads to, written out: two levels that load alike print alike.
std::string dump(const Level& level) {
  std::ostringstream s;
  s.precision(17);
  const auto v = [&s](Vec2 p) { s << "(" << p.x << "," << p.y << ")"; };
  s << level.name << "|" << level.description << "|";
  v(level.gravity);
  const SolverConfig& c = level.solver;
  s << "|solver " << c.dt << " " << c.substeps << " " << c.iterations << " " << static_cast<int>(c.method)
    << " " << c.damping << " " << c.tunnel_clamp << " " << c.ground_normal_y << " " << c.jump_grace << " "
    << c.sleep << "\n";
  for (const LevelVehicle& lv : level.vehicles) {
    const VehicleSpec& vs = lv.spec;
    const Drivetrain& d = vs.drivetrain;
    s << "vehicle " << lv.player << " " << d.motor_torque << " " << d.motor_speed << " " << d.brake_torque
      << " " << d.lean_torque << " head " << lv.head.has_value();
    if (lv.head) {
      v(lv.head->position);
      s << lv.head->radius;
    }
    s << " chassis " << static_cast<int>(vs.chassis.shape) << " ";
    v(vs.chassis.position);
    v(vs.chassis.size);
    v(vs.chassis.velocity);
    s << " " << vs.chassis.angle << " " << vs.chassis.radius << " " << vs.chassis.density << " "
      << vs.chassis.friction << " " << vs.chassis.restitution << " " << vs.chassis.angular_velocity << "\n";
    for (const WheelSpec& w : vs.wheels) {
      s << "wheel ";
      v(w.axle.point);
      v(w.axle.axis);
      const TireSpec& t = w.tire;
      s << " " << w.axle.stiffness << " " << w.axle.damping << " " << w.axle.travel << " " << w.axle.driven
        << " " << t.angle << " " << t.outer_radius << " " << t.inner_radius << " " << t.segments << " "
        << t.mass << " " << t.friction << " " << t.kinetic_friction << " " << t.pressure << " "
        << t.compliance.outer << " " << static_cast<int>(t.spokes) << " " << t.material_damping << " "
        << t.rolling_resistance << " " << t.restitution << "\n";
    }
  }
  for (const TireSpec& t : level.tires) {
    s << "tire ";
    v(t.position);
    v(t.velocity);
    s << " " << t.angle << " " << t.angular_velocity << " " << t.outer_radius << " " << t.inner_radius << " "
      << t.segments << " " << t.mass << " " << t.friction << " " << t.kinetic_friction << " " << t.pressure
      << " " << t.compliance.outer << " " << t.compliance.inner << " " << t.compliance.spoke << " "
      << t.compliance.pressure << " " << static_cast<int>(t.spokes) << " " << t.material_damping << " "
      << t.rolling_resistance << " " << t.player << " " << t.drive_acceleration << " " << t.jump_speed << " "
      << t.max_speed << "\n";
  }
  for (const Obstacle& o : level.obstacles) {
    s << "obstacle ";
    v(o.box.min);
    v(o.box.max);
    s << " " << o.friction << "\n";
  }
  for (const PropSpec& p : level.props) {
    s << "prop " << p.name << " " << static_cast<int>(p.shape) << " " << static_cast<int>(p.type) << " ";
    v(p.position);
    s << " " << p.angle << " ";
    v(p.size);
    s << " " << p.radius << " [";
    for (const Vec2 q : p.points) v(q);
    s << "] " << p.loop << " " << p.thickness << " " << p.density << " " << p.friction << " " << p.restitution
      << " ";
    v(p.velocity);
    s << " " << p.angular_velocity << " path [";
    for (const Vec2 q : p.path.waypoints) v(q);
    s << "] " << p.path.speed << " " << static_cast<int>(p.path.mode) << " " << p.path.running << "\n";
  }
  for (const Region& r : level.script.regions) {
    s << "region " << r.name << " ";
    v(r.box.min);
    v(r.box.max);
    s << "\n";
  }
  s << "goal " << level.script.goal.value_or(999) << " time_limit " << level.script.time_limit.value_or(-1)
    << " counters " << level.script.counters.size() << " triggers " << level.script.triggers.size() << "\n";
  return s.str();
}

std::uint64_t hash_after_ticks(const Level& level, int ticks) {
  auto session = make_session(level);
  run(*session, ticks);
  return session->state_hash();
}

// The first column of the first markdown table after `heading` in `file`: its keys, unquoted.
std::vector<std::string> reference_keys(const std::string& file, const std::string& heading) {
  std::ifstream in(source_path(file));
  std::string line;
  while (std::getline(in, line) && line != heading) {
  }
  std::vector<std::string> keys;
  int row = 0;
  while (std::getline(in, line)) {
    if (!line.starts_with("|")) {
      if (row > 0) break;  // the table ended
      continue;
    }
    if (row++ < 2) continue;  // the header and its rule
    const std::size_t end = line.find('|', 1);
    std::string cell = line.substr(1, end - 1);
    std::erase(cell, '`');
    std::erase(cell, ' ');
    keys.push_back(cell);
  }
  return keys;
}

std::vector<std::string> names(std::span<const LevelKey> keys) {
  std::vector<std::string> out;
  for (const LevelKey& k : keys) out.push_back(k.key);
  return out;
}

}  // namespace

TEST_CASE("level keys: the table is consistent with itself and the parameter table", "[unit][level_keys]") {
  for (const LevelObject object : kObjects) {
    INFO(object_name(object));
    REQUIRE(!level_keys(object).empty());
    for (const LevelKey& key : level_keys(object)) {
      INFO(key.key);
      CHECK(find_level_key(object, key.key) == &key);
      CHECK(!key.description.empty());
      CHECK(key.description.find('\n') == std::string::npos);
      CHECK(key.description.find('{') == std::string::npos);  // every placeholder filled
      if (key.required) CHECK(key.default_value.is_null());
      if (key.type == KeyType::choice) {
        CHECK(!key.choices.empty());
        if (!key.default_value.is_null())
          CHECK(std::find(key.choices.begin(), key.choices.end(), key.default_value.get<std::string>()) !=
                key.choices.end());
      }
      if (key.type == KeyType::number || key.type == KeyType::integer) {
        CHECK(std::isfinite(key.range.min));
        CHECK(std::isfinite(key.range.max));
        if (key.default_value.is_number()) CHECK(key.range.contains(key.default_value.get<double>()));
      }
      if (key.type == KeyType::points) CHECK(!key.point_counts.empty());
      if (key.nested) CHECK((key.type == KeyType::object || key.type == KeyType::array));
      if (!key.parameter.empty()) {
        REQUIRE(find_parameter(key.parameter) != nullptr);
        const Parameter& p = *find_parameter(key.parameter);
        if (p.is_tire() || std::string_view(p.key).starts_with("solver.")) {
          CHECK(p.field() == key.key);
          CHECK(key.type == (p.integer ? KeyType::integer : KeyType::number));
          CHECK(key.default_value == (p.default_follows ? json() : json(p.default_value)));
        }
        CHECK(key.range == p.range);
      }
    }
  }
  CHECK(find_level_key(LevelObject::prop, "no_such_key") == nullptr);
  // Every solver, tire and compliance row a level may set has its key.
  for (const Parameter& p : parameters()) {
    if (!p.may(by_level)) continue;
    const std::string_view key(p.key);
    const LevelObject object = key.starts_with("solver.")             ? LevelObject::solver
                               : key.starts_with("budgets.")          ? LevelObject::budgets
                               : key.starts_with("tires.compliance.") ? LevelObject::compliance
                                                                      : LevelObject::tire;
    INFO(p.key);
    const LevelKey* k = find_level_key(object, p.field());
    REQUIRE(k != nullptr);
    CHECK(k->parameter == std::string_view(p.key));
  }
  const LevelKey& points = *find_level_key(LevelObject::prop, "points");
  CHECK(applies_to_shape(points, "chain"));
  CHECK(!applies_to_shape(points, "box"));
  CHECK(applies_to_shape(*find_level_key(LevelObject::prop, "density"), "box"));
  CHECK(point_count(points, "polygon")->max == 8);
  CHECK(point_count(points, "box") == nullptr);
}

TEST_CASE("level keys: each object accepts exactly the table's keys", "[unit][level_keys]") {
  for (const LevelObject object : kObjects) {
    INFO(object_name(object));
    // An unknown key is refused, and the message lists the accepted keys: the table's, in order.
    Placed p = place(object);
    p.object()["zzzz_not_a_key"] = 1;
    const auto errors = errors_of(p.doc);
    INFO(joined(errors));
    CHECK(has(errors, "x.json: " + p.pointer + "/zzzz_not_a_key: unknown key; expected one of " +
                          quoted(names(level_keys(object)))));
    for (const LevelKey& key : level_keys(object)) {
      INFO(key.key);
      const json value = key.default_value.is_null() ? json(1) : key.default_value;
      const auto [doc, pointer] = with_key(object, key, value);
      const auto key_errors = errors_of(doc);
      INFO(joined(key_errors));
      CHECK(!has(key_errors, pointer + ": unknown key"));
    }
  }
}

TEST_CASE("level keys: numbers past the table's range are refused, at a closed bound accepted",
          "[unit][level_keys]") {
  int checked = 0;
  for (const LevelObject object : kObjects) {
    for (const LevelKey& key : level_keys(object)) {
      const bool scalar = key.type == KeyType::number || key.type == KeyType::integer;
      if (!scalar && key.type != KeyType::vec2) continue;
      INFO(object_name(object) << "." << key.key << " in " << key.range.text());
      const auto value = [&](double v) { return scalar ? json(v) : json::array({v, v}); };
      const auto refused = [&](double v) {
        const auto [doc, pointer] = with_key(object, key, value(v));
        const auto errors = errors_of(doc);
        INFO("value " << v << "\n" << joined(errors));
        CHECK(has(errors, "x.json: " + pointer + ": must be "));
        CHECK(has(errors, key.range.text()));
      };
      const auto accepted = [&](double v) {
        const auto [doc, pointer] = with_key(object, key, value(v));
        const auto errors = errors_of(doc);
        INFO("value " << v << "\n" << joined(errors));
        // Another key may object to the value (an inner radius not below the outer): the range may not.
        CHECK(!has(errors, pointer + ": must be a number in"));
        CHECK(!has(errors, pointer + ": must be an integer in"));
        CHECK(!has(errors, pointer + ": must be [x, y]"));
      };
      const bool integer = key.type == KeyType::integer;
      const double inf = std::numeric_limits<double>::infinity();
      if (std::isfinite(key.range.max)) {
        refused(integer ? key.range.max + 1 : std::nextafter(key.range.max, inf));
        if (key.range.max_open)
          refused(key.range.max);
        else
          accepted(key.range.max);
        ++checked;
      }
      if (std::isfinite(key.range.min)) {
        refused(integer ? key.range.min - 1 : std::nextafter(key.range.min, -inf));
        if (key.range.min_open)
          refused(key.range.min);
        else
          accepted(key.range.min);
      }
    }
  }
  CHECK(checked > 40);
}

TEST_CASE("level keys: point counts are the table's", "[unit][level_keys]") {
  for (const LevelObject object : {LevelObject::prop, LevelObject::path}) {
    for (const LevelKey& key : level_keys(object)) {
      for (const LevelKey::PointCount& count : key.point_counts) {
        INFO(object_name(object) << "." << key.key << " " << count.shape);
        const std::string shape = count.shape.empty() ? shape_for(key) : count.shape;
        const std::string expected = "must be an array of " + std::to_string(count.min) + " to " +
                                     std::to_string(count.max) + " points [x, y] in m, got ";
        for (const std::size_t n : {count.min - 1, count.max + 1}) {
          if (n > count.max + 1) continue;  // count.min - 1 wrapped: no fewer than none
          json points = json::array();
          for (std::size_t i = 0; i < n; ++i) points.push_back({static_cast<double>(i), 0.0});
          Placed p = place(object, shape);
          p.object()[key.key] = points;
          const auto errors = errors_of(p.doc);
          INFO(n << " points\n" << joined(errors));
          CHECK(has(errors, "x.json: " + p.pointer + "/" + key.key + ": " + expected));
        }
      }
    }
  }
}

TEST_CASE("level keys: a missing key loads as its default_value", "[unit][level_keys]") {
  int checked = 0;
  for (const LevelObject object : kObjects) {
    for (const LevelKey& key : level_keys(object)) {
      if (key.default_value.is_null()) continue;
      INFO(object_name(object) << "." << key.key << " = " << key.default_value.dump());
      Placed without = place(object, shape_for(key));
      const auto [with, pointer] = with_key(object, key, key.default_value);
      const LevelLoad a = load_level_text(without.doc.dump(), "a.json");
      const LevelLoad b = load_level_text(with.dump(), "b.json");
      INFO(joined(a.errors) << joined(b.errors));
      REQUIRE(a.level);
      REQUIRE(b.level);
      CHECK(dump(*a.level) == dump(*b.level));
      CHECK(hash_after_ticks(*a.level, 5) == hash_after_ticks(*b.level, 5));
      ++checked;
    }
  }
  CHECK(checked > 40);
}

TEST_CASE("level keys: the reference pages list each object's keys in the table's order",
          "[unit][level_keys]") {
  const std::pair<LevelObject, std::pair<const char*, const char*>> sections[] = {
      {LevelObject::root, {"levels/README.md", "## Root"}},
      {LevelObject::solver, {"levels/README.md", "## `solver`"}},
      {LevelObject::budgets, {"levels/README.md", "## `budgets`"}},
      {LevelObject::bounds, {"levels/README.md", "## `bounds`"}},
      {LevelObject::medals, {"levels/README.md", "## `medals`"}},
      {LevelObject::tire, {"levels/README.md", "## Tire"}},
      {LevelObject::compliance, {"levels/README.md", "### `compliance`"}},
      {LevelObject::obstacle, {"levels/README.md", "## Obstacle"}},
      {LevelObject::prop, {"levels/README.md", "## Prop"}},
      {LevelObject::path, {"levels/README.md", "### `path`"}},
      {LevelObject::region, {"levels/SCRIPTING.md", "### Region"}},
      {LevelObject::vehicle, {"levels/README.md", "## Vehicles"}},
      {LevelObject::chassis, {"levels/README.md", "### `chassis`"}},
      {LevelObject::wheel, {"levels/README.md", "### Wheel"}},
      {LevelObject::head, {"levels/README.md", "### `head`"}},
  };
  for (const auto& [object, where] : sections) {
    INFO(object_name(object) << ": " << where.first << " " << where.second);
    CHECK(reference_keys(where.first, where.second) == names(level_keys(object)));
  }
  // SCRIPTING.md's root keys are the root's last ones, from "regions" on.
  std::vector<std::string> root = names(level_keys(LevelObject::root));
  root.erase(root.begin(), std::find(root.begin(), root.end(), "regions"));
  CHECK(reference_keys("levels/SCRIPTING.md", "## Root keys") == root);
}

TEST_CASE("level keys: choice keys take exactly the table's choices", "[unit][level_keys]") {
  int checked = 0;
  for (const LevelObject object : kObjects) {
    for (const LevelKey& key : level_keys(object)) {
      if (key.type != KeyType::choice) continue;
      INFO(object_name(object) << "." << key.key);
      const auto [doc, pointer] = with_key(object, key, "zzzz_not_a_choice");
      const auto errors = errors_of(doc);
      INFO(joined(errors));
      CHECK(has(errors, "x.json: " + pointer + ": must be one of " + quoted(key.choices) +
                            ", got \"zzzz_not_a_choice\""));
      for (const std::string& choice : key.choices) {
        const auto [ok_doc, ok_pointer] = with_key(object, key, choice);
        const auto ok_errors = errors_of(ok_doc);
        INFO(choice << "\n" << joined(ok_errors));
        CHECK(!has(ok_errors, ok_pointer + ": must be one of"));
      }
      ++checked;
    }
  }
  CHECK(checked == 9);  // method, material, spokes, shape, type, mode; chassis shape, wheel material, spokes
}

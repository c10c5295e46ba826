// levels/schema.json gives editors completion and hover docs on level files. The level reader
// (engine/io/level_reader.cpp, with the parameter table engine/tire/include/tire/tire/parameters.h
// from which the schema's numeric solver and tire keys and the `set` action's keys are generated)
// stays the authority; these tests keep the schema in step with it: the
// same keys (script keys of levels/SCRIPTING.md included), defaults, ranges, choices, string lengths
// and prop shape rules. No schema validator is involved: the schema is read as plain JSON and each
// of its claims is checked against what the loader does.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "tire_fixtures.h"

using namespace tire;
using json = nlohmann::json;

namespace {

const char* const kFile = "probe.json";
const char* const kUnknown = "zzzzzz";  // an edit distance of 3 or more from every key: no did-you-mean

const json& schema() {
  static const json s = [] {
    std::ifstream in(test::source_path("levels/schema.json"));
    if (!in) throw std::runtime_error("cannot read levels/schema.json");
    return json::parse(in);
  }();
  return s;
}

const json& def(const std::string& name) { return schema().at("$defs").at(name); }

// A schema node with its local "$ref" ("#/$defs/x") resolved; the node's own keys override.
json resolved(const json& node) {
  if (!node.is_object() || !node.contains("$ref")) return node;
  const std::string ref = node.at("$ref").get<std::string>();
  if (ref.rfind("#/", 0) != 0) throw std::runtime_error("not a local $ref: " + ref);
  json out = resolved(schema().at(json::json_pointer(ref.substr(1))));
  for (const auto& [key, value] : node.items())
    if (key != "$ref") out[key] = value;
  return out;
}

// A value the schema itself offers for a property: its default, const or first example.
json sample(const json& property) {
  const json p = resolved(property);
  if (p.contains("default")) return p.at("default");
  if (p.contains("const")) return p.at("const");
  if (p.contains("examples") && !p.at("examples").empty()) return p.at("examples").at(0);
  throw std::runtime_error("schema property with no default, const or examples: " + p.dump());
}

std::vector<std::string> strings(const json& array) {
  std::vector<std::string> out;
  for (const json& s : array) out.push_back(s.get<std::string>());
  return out;
}

// An object with the schema's required keys at their samples. Of "exactly one of" alternatives
// (oneOf of required lists), the one that has `key`, else the first.
json required_base(const json& object_schema, const std::string& key) {
  json obj = json::object();
  std::vector<std::string> required = strings(object_schema.value("required", json::array()));
  if (const auto it = object_schema.find("oneOf"); it != object_schema.end()) {
    json pick = it->at(0);
    for (const json& alternative : *it)
      for (const std::string& r : strings(alternative.value("required", json::array())))
        if (r == key) pick = alternative;
    for (const std::string& r : strings(pick.value("required", json::array()))) required.push_back(r);
  }
  for (const std::string& r : required) obj[r] = sample(object_schema.at("properties").at(r));
  return obj;
}

// --- the prop's conditional rules (allOf of if/then) ---

// The "then" of the prop rule whose "if" selects `key` == `value`, or null.
json prop_rule(const std::string& key, const json& value, const char* branch = "then") {
  for (const json& rule : def("prop").at("allOf")) {
    const json& if_ = rule.at("if");
    if (if_.contains("properties") && if_.at("properties").contains(key) &&
        if_.at("properties").at(key).value("const", json()) == value)
      return rule.value(branch, json());
  }
  return json();
}

bool forbids(const json& branch, const std::string& key) {
  return branch.is_object() && branch.contains("properties") && branch.at("properties").contains(key) &&
         branch.at("properties").at(key) == json(false);
}

// A valid prop of `shape`: the shape's required keys at their samples.
json prop_of_shape(const std::string& shape) {
  json obj{{"shape", shape}};
  const json then = prop_rule("shape", shape);
  for (const std::string& r : strings(then.value("required", json::array())))
    obj[r] = sample(def("prop").at("properties").at(r));
  return obj;
}

// A valid prop in which `key` applies: the first shape that allows it, kinematic if only those may have it.
json prop_base(const std::string& key) {
  for (const std::string& shape : strings(def("prop").at("properties").at("shape").at("enum"))) {
    if (forbids(prop_rule("shape", shape), key)) continue;
    json obj = prop_of_shape(shape);
    if (forbids(prop_rule("type", "kinematic", "else"), key)) obj["type"] = "kinematic";
    return obj;
  }
  throw std::runtime_error("no prop shape allows " + key);
}

// The chassis' rules, as the prop's: the "then" of the rule selecting `shape`.
json chassis_rule(const std::string& shape) {
  for (const json& rule : def("chassis").at("allOf"))
    if (rule.at("if").at("properties").at("shape").value("const", json()) == shape) return rule.at("then");
  return json();
}

// A valid chassis in which `key` applies: the first shape that allows it.
json chassis_base(const std::string& key) {
  for (const std::string& shape : strings(def("chassis").at("properties").at("shape").at("enum"))) {
    const json then = chassis_rule(shape);
    if (forbids(then, key)) continue;
    json obj{{"shape", shape}};
    for (const std::string& r : strings(then.value("required", json::array())))
      obj[r] = sample(def("chassis").at("properties").at(r));
    return obj;
  }
  throw std::runtime_error("no chassis shape allows " + key);
}

// --- loading probe levels ---

struct Issue {
  std::string path;  // JSON pointer; "/" for the document
  std::string message;
};

std::vector<Issue> issues_of(const json& level) {
  const LevelLoad load = load_level_text(level.dump(), kFile);
  std::vector<Issue> out;
  const std::string prefix = std::string(kFile) + ": ";
  for (const std::string& e : load.errors) {
    const std::string rest = e.rfind(prefix, 0) == 0 ? e.substr(prefix.size()) : e;
    const auto colon = rest.find(": ");
    if (colon == std::string::npos)
      out.push_back({"", rest});
    else
      out.push_back({rest.substr(0, colon), rest.substr(colon + 2)});
  }
  if (!load.level && out.empty()) out.push_back({"", "not loaded, and no error given"});
  return out;
}

std::string joined(const std::vector<Issue>& issues) {
  std::string out;
  for (const Issue& i : issues) out += "  " + i.path + ": " + i.message + "\n";
  return out;
}

bool at_or_under(const Issue& issue, const std::string& path) {
  return issue.path == path || issue.path.rfind(path + "/", 0) == 0;
}

// The reader's complaint about a value outside a key's range.
bool is_range_message(const std::string& message) {
  return message.rfind("must be a number in", 0) == 0 || message.rfind("must be an integer in", 0) == 0 ||
         message.find("with each in") != std::string::npos;
}

bool range_issue_at(const std::vector<Issue>& issues, const std::string& path) {
  for (const Issue& i : issues)
    if (at_or_under(i, path) && is_range_message(i.message)) return true;
  return false;
}

const Issue* issue_at(const std::vector<Issue>& issues, const std::string& path) {
  for (const Issue& i : issues)
    if (i.path == path) return &i;
  return nullptr;
}

// The quoted names in a reader message such as `unknown key; expected one of "a", "b"`.
std::set<std::string> quoted_after(const std::string& message, const std::string& lead) {
  std::set<std::string> out;
  auto at = message.find(lead);
  if (at == std::string::npos) return out;
  at += lead.size();
  const auto end = message.find(", got ", at);  // "must be one of ..., got ..." stops there
  while (true) {
    const auto open = message.find('"', at);
    if (open == std::string::npos || open > end) break;
    const auto close = message.find('"', open + 1);
    if (close == std::string::npos) break;
    out.insert(message.substr(open + 1, close - open - 1));
    at = close + 1;
  }
  return out;
}

std::set<std::string> keys_of(const json& object) {
  std::set<std::string> out;
  for (const auto& [key, value] : object.items()) out.insert(key);
  return out;
}

std::string listed(const std::set<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// --- the kinds of object a level holds ---

struct Kind {
  std::string name;
  json schema;                                   // resolved object schema with "properties"
  std::string path;                              // JSON pointer of the object in the probe level
  std::function<json(const std::string&)> base;  // a minimal valid object in which the key applies
  std::function<json(const json&)> level;        // a probe level holding the object at `path`
  bool core;                                     // a part of levels/README.md, not of SCRIPTING.md
};

json named_level() { return {{"name", "Schema probe"}}; }

json with(json object, const std::string& key, json value) {
  object[key] = std::move(value);
  return object;
}

json region_sample() { return required_base(def("region"), ""); }

// A level that defines the names the schema's script examples use: region "finish", counter
// "coins" and the kinematic prop "crate".
json script_level(const json& trigger) {
  json level = named_level();
  level["regions"] = json::array({region_sample()});
  level["counters"] = {{"coins", 0}};
  level["props"] =
      json::array({{{"name", "crate"}, {"shape", "box"}, {"type", "kinematic"}, {"size", {1, 1}}}});
  level["triggers"] = json::array({trigger});
  return level;
}

std::vector<Kind> kinds() {
  std::vector<Kind> out;
  auto base_of = [](const std::string& name) {
    return [name](const std::string& key) { return required_base(def(name), key); };
  };
  const json tire_object = required_base(def("tire"), "");

  out.push_back({"root", schema(), "",
                 [](const std::string& key) {
                   json obj = required_base(schema(), key);
                   if (key == "goal") obj["regions"] = json::array({region_sample()});
                   return obj;
                 },
                 [](const json& obj) { return obj; }, true});
  out.push_back({"solver", def("solver"), "/solver", base_of("solver"),
                 [](const json& obj) { return with(named_level(), "solver", obj); }, true});
  out.push_back({"tire", def("tire"), "/tires/0", base_of("tire"),
                 [](const json& obj) { return with(named_level(), "tires", json::array({obj})); }, true});
  out.push_back({"compliance", def("compliance"), "/tires/0/compliance", base_of("compliance"),
                 [tire_object](const json& obj) {
                   return with(named_level(), "tires", json::array({with(tire_object, "compliance", obj)}));
                 },
                 true});
  out.push_back({"obstacle", def("obstacle"), "/obstacles/0", base_of("obstacle"),
                 [](const json& obj) { return with(named_level(), "obstacles", json::array({obj})); }, true});
  out.push_back({"prop", def("prop"), "/props/0", prop_base,
                 [](const json& obj) { return with(named_level(), "props", json::array({obj})); }, true});
  out.push_back({"path", def("path"), "/props/0/path", base_of("path"),
                 [](const json& obj) {
                   json prop = prop_of_shape("box");
                   prop["type"] = "kinematic";
                   prop["path"] = obj;
                   return with(named_level(), "props", json::array({prop}));
                 },
                 true});

  // A vehicle's parts, in a level of one vehicle: its chassis, its first wheel, its head.
  const json vehicle = required_base(def("vehicle"), "");
  const auto in_vehicle = [vehicle](const std::string& part) {
    return [vehicle, part](const json& obj) {
      json v = vehicle;
      if (part == "wheel")
        v["wheels"][0] = obj;
      else
        v[part] = obj;
      return with(named_level(), "vehicles", json::array({v}));
    };
  };
  out.push_back({"vehicle", def("vehicle"), "/vehicles/0", base_of("vehicle"),
                 [](const json& obj) { return with(named_level(), "vehicles", json::array({obj})); }, true});
  out.push_back({"chassis", resolved(def("chassis")), "/vehicles/0/chassis", chassis_base,
                 in_vehicle("chassis"), true});
  out.push_back({"wheel", def("wheel"), "/vehicles/0/wheels/0", base_of("wheel"), in_vehicle("wheel"), true});
  out.push_back({"head", def("head"), "/vehicles/0/head", base_of("head"), in_vehicle("head"), true});
  out.push_back({"bounds", def("bounds"), "/bounds", base_of("bounds"),
                 [](const json& obj) { return with(named_level(), "bounds", obj); }, true});
  out.push_back({"region", def("region"), "/regions/0", base_of("region"),
                 [](const json& obj) { return with(named_level(), "regions", json::array({obj})); }, false});
  out.push_back({"trigger", def("trigger"), "/triggers/0", base_of("trigger"),
                 [](const json& obj) { return script_level(obj); }, false});
  for (const json& ref : def("condition").at("oneOf")) {
    const json condition = resolved(ref);
    out.push_back({condition.at("properties").at("type").at("const").get<std::string>() + " condition",
                   condition, "/triggers/0/when",
                   [condition](const std::string& key) { return required_base(condition, key); },
                   [](const json& obj) {
                     return script_level({{"when", obj}, {"do", json::array()}});
                   },
                   false});
  }
  for (const json& ref : def("action").at("oneOf")) {
    const json action = resolved(ref);
    out.push_back({action.at("properties").at("action").at("const").get<std::string>() + " action", action,
                   "/triggers/0/do/0",
                   [action](const std::string& key) { return required_base(action, key); },
                   [](const json& obj) {
                     return script_level({{"when", {{"type", "start"}}}, {"do", json::array({obj})}});
                   },
                   false});
  }
  return out;
}

std::set<std::string> declared_keys(const Kind& kind) { return keys_of(kind.schema.at("properties")); }

// --- ranges ---

struct Bounds {
  std::string key;  // minimum, maximum, exclusiveMinimum or exclusiveMaximum
  double value;
};

std::vector<Bounds> bounds_of(const json& number_schema) {
  std::vector<Bounds> out;
  for (const char* k : {"minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum"})
    if (number_schema.contains(k)) out.push_back({k, number_schema.at(k).get<double>()});
  return out;
}

// Where a property's numbers are and how to write one into it: a number, a vec2 [v, v], or the
// first point of an array of vec2. Null `numbers` when the property holds no number.
struct NumericSlot {
  json numbers;
  std::function<json(const json&)> write;
};

NumericSlot numeric_slot(const json& property) {
  const json p = resolved(property);
  const std::string type = p.value("type", "");
  if (type == "number" || type == "integer") return {p, [](const json& v) { return v; }};
  if (type != "array" || !p.contains("items")) return {json(), nullptr};
  const json items = resolved(p.at("items"));
  const std::string item_type = items.value("type", "");
  if (item_type == "number" || item_type == "integer")
    return {items, [](const json& v) { return json::array({v, v}); }};
  if (item_type == "array" && items.contains("items")) {
    const json points = sample(property);
    return {resolved(items.at("items")), [points](const json& v) {
              json out = points;
              out[0] = json::array({v, v});
              return out;
            }};
  }
  return {json(), nullptr};
}

// Checks each bound of `numbers` against the loader: just outside is rejected, the bound itself
// accepted when inclusive (rejected when exclusive, with the number just inside accepted).
void check_bounds(const Kind& kind, const json& base, const std::string& key, const NumericSlot& slot) {
  const std::string path = kind.path + "/" + key;
  const bool integer = slot.numbers.value("type", "") == "integer";
  auto probe = [&](double v) {
    json object = base;
    object[key] = slot.write(integer ? json(static_cast<std::int64_t>(v)) : json(v));
    return issues_of(kind.level(object));
  };
  const double inf = std::numeric_limits<double>::infinity();
  for (const Bounds& b : bounds_of(slot.numbers)) {
    const bool lower = b.key == "minimum" || b.key == "exclusiveMinimum";
    const bool exclusive = b.key.rfind("exclusive", 0) == 0;
    const double outward = lower ? -inf : inf;
    const double outside = exclusive ? b.value
                           : integer ? b.value + (lower ? -1.0 : 1.0)
                                     : std::nextafter(b.value, outward);
    const double inside =
        exclusive ? (integer ? b.value - (lower ? -1.0 : 1.0) : std::nextafter(b.value, -outward)) : b.value;
    {
      const auto issues = probe(outside);
      INFO(kind.name << "." << key << " " << b.key << " " << b.value << ": " << outside
                     << " should be out of range\n"
                     << joined(issues));
      CHECK(range_issue_at(issues, path));
    }
    {
      const auto issues = probe(inside);
      INFO(kind.name << "." << key << " " << b.key << " " << b.value << ": " << inside
                     << " should be in range\n"
                     << joined(issues));
      CHECK_FALSE(range_issue_at(issues, path));
    }
  }
  const auto bounds = bounds_of(slot.numbers);
  if (!integer && bounds.size() == 2) {  // a number may have a fraction
    const double lo = std::min(bounds[0].value, bounds[1].value),
                 hi = std::max(bounds[0].value, bounds[1].value);
    double v = lo + (hi - lo) * 0.3712345;
    if (std::floor(v) == v) v += std::min(0.5, (hi - v) / 2.0);
    const auto issues = probe(v);
    INFO(kind.name << "." << key << ": " << v << " should be in range\n" << joined(issues));
    REQUIRE(std::floor(v) != v);
    CHECK_FALSE(range_issue_at(issues, path));
  }
  if (integer && !bounds.empty()) {  // a fraction is not an integer
    json object = base;
    object[key] = slot.write(json(bounds.front().value + 0.5));
    const auto issues = issues_of(kind.level(object));
    INFO(kind.name << "." << key << ": a fraction should be rejected\n" << joined(issues));
    CHECK(range_issue_at(issues, path));
  }
}

json vec(Vec2 v) { return json::array({v.x, v.y}); }

// The engine's defaults, by kind and key, as the schema writes them.
std::map<std::string, std::map<std::string, json>> engine_defaults() {
  const Level l;
  const SolverConfig s;
  const TireSpec t;
  const TireCompliance c;
  const Obstacle o;
  const PropSpec p;
  const KinematicPath k;
  const LevelBounds b;
  const Drivetrain d;
  const AxleSpec a;
  return {
      {"root", {{"description", l.description}, {"gravity", vec(l.gravity)}}},
      {"solver",
       {{"dt", s.dt},
        {"substeps", s.substeps},
        {"iterations", s.iterations},
        {"damping", s.damping},
        {"tunnel_clamp", s.tunnel_clamp},
        {"ground_normal_y", s.ground_normal_y},
        {"jump_grace", s.jump_grace},
        {"divergence_area", s.divergence_area},
        {"divergence_speed", s.divergence_speed},
        {"tire_neighbours", s.tire_neighbours},
        {"island_tires", s.island_tires},
        {"method", method_name(s.method)},
        {"sleep", s.sleep},
        {"rolling_hold", s.rolling_hold},
        {"restitution_threshold", s.restitution_threshold}}},
      {"tire",
       {{"velocity", vec(t.velocity)},
        {"angle", t.angle},
        {"angular_velocity", t.angular_velocity},
        {"outer_radius", t.outer_radius},
        {"inner_radius", t.inner_radius},
        {"segments", t.segments},
        {"mass", t.mass},
        {"friction", t.friction},
        {"pressure", t.pressure},
        {"spokes", t.spokes == SpokePattern::cross ? "cross" : "radial"},
        {"material_damping", t.material_damping},
        {"rolling_resistance", t.rolling_resistance},
        {"player", t.player},
        {"drive_acceleration", t.drive_acceleration},
        {"jump_speed", t.jump_speed},
        {"max_speed", t.max_speed},
        {"material", kMaterials.front().name},
        {"restitution", t.restitution},
        {"inflate_rate", t.inflate_rate},
        {"min_pressure", t.min_pressure},
        {"max_pressure", t.max_pressure}}},
      {"compliance", {{"outer", c.outer}, {"inner", c.inner}, {"spoke", c.spoke}, {"pressure", c.pressure}}},
      {"obstacle", {{"friction", o.friction}}},
      {"prop",
       {{"name", p.name},
        {"type", p.type == PropType::static_body    ? "static"
                 : p.type == PropType::dynamic_body ? "dynamic"
                                                    : "kinematic"},
        {"position", vec(p.position)},
        {"angle", p.angle},
        {"loop", p.loop},
        {"thickness", p.thickness},
        {"density", p.density},
        {"friction", p.friction},
        {"restitution", p.restitution},
        {"velocity", vec(p.velocity)},
        {"angular_velocity", p.angular_velocity}}},
      {"bounds", {{"margin", b.margin}}},
      {"vehicle",
       {{"player", false},
        {"motor_torque", d.motor_torque},
        {"motor_speed", d.motor_speed},
        {"brake_torque", d.brake_torque},
        {"lean_torque", d.lean_torque}}},
      {"chassis",
       {{"position", vec(p.position)},
        {"angle", p.angle},
        {"density", p.density},
        {"friction", p.friction},
        {"restitution", p.restitution},
        {"velocity", vec(p.velocity)},
        {"angular_velocity", p.angular_velocity}}},
      {"wheel",
       {{"axis", vec(a.axis)},
        {"stiffness", a.stiffness},
        {"damping", a.damping},
        {"travel", a.travel},
        {"driven", a.driven},
        {"material", kMaterials.front().name},
        {"angle", t.angle},
        {"outer_radius", t.outer_radius},
        {"inner_radius", t.inner_radius},
        {"segments", t.segments},
        {"mass", t.mass},
        {"friction", t.friction},
        {"pressure", t.pressure},
        {"spokes", t.spokes == SpokePattern::cross ? "cross" : "radial"},
        {"material_damping", t.material_damping},
        {"rolling_resistance", t.rolling_resistance},
        {"restitution", t.restitution}}},
      {"head", {}},
      {"path",
       {{"speed", k.speed},
        {"mode", k.mode == PathMode::loop   ? "loop"
                 : k.mode == PathMode::once ? "once"
                                            : "ping_pong"},
        {"running", k.running}}},
  };
}

bool empty_container(const json& v) { return (v.is_object() || v.is_array()) && v.empty(); }

}  // namespace

TEST_CASE("the schema is draft 2020-12 and every object in it forbids unknown keys",
          "[unit][level][schema]") {
  const json& s = schema();
  CHECK(s.at("$schema") == "https://json-schema.org/draft/2020-12/schema");
  CHECK(s.at("$id") == "levels/schema.json");
  for (const char* name :
       {"coordinate", "velocity", "solver", "tire", "compliance", "obstacle", "prop", "path"})
    CHECK(s.at("$defs").contains(name));
  // Every object schema with properties closes itself, and every property says what it is.
  std::function<void(const json&, const std::string&)> walk = [&](const json& node,
                                                                  const std::string& where) {
    if (node.is_array()) {
      for (std::size_t i = 0; i < node.size(); ++i) walk(node[i], where + "/" + std::to_string(i));
      return;
    }
    if (!node.is_object()) return;
    // Rules (if/then/else, oneOf alternatives, contains) only narrow an object declared elsewhere.
    const bool in_rule = where.find("/allOf/") != std::string::npos ||
                         where.find("/oneOf/") != std::string::npos ||
                         where.find("/contains") != std::string::npos;
    if (node.contains("properties") && !in_rule) {
      INFO(where);
      CHECK(node.value("additionalProperties", json(true)) == json(false));
      for (const auto& [key, property] : node.at("properties").items()) {
        INFO(key);
        CHECK(resolved(property).contains("description"));
      }
    }
    for (const auto& [key, child] : node.items()) walk(child, where + "/" + key);
  };
  walk(s, "");
}

TEST_CASE("every key the schema declares is accepted by the level reader", "[unit][level][schema]") {
  for (const Kind& kind : kinds()) {
    const std::set<std::string> declared = declared_keys(kind);
    for (const std::string& key : declared) {
      json object = kind.base(key);
      object[key] = sample(kind.schema.at("properties").at(key));
      const auto issues = issues_of(kind.level(object));
      INFO(kind.name << "." << key << " = " << object[key].dump() << " in " << kind.level(object).dump()
                     << "\n"
                     << joined(issues));
      CHECK(issues.empty());
    }
  }
}

TEST_CASE("every key the level reader accepts is declared in the schema", "[unit][level][schema]") {
  for (const Kind& kind : kinds()) {
    json object = kind.base("");
    object[kUnknown] = 0;
    const auto issues = issues_of(kind.level(object));
    const Issue* unknown = issue_at(issues, kind.path + "/" + kUnknown);
    INFO(kind.name << "\n" << joined(issues));
    REQUIRE(unknown != nullptr);
    const std::set<std::string> reader = quoted_after(unknown->message, "unknown key; expected one of ");
    CHECK(!reader.empty());
    const std::set<std::string> schema_keys = declared_keys(kind);
    INFO("reader: " << listed(reader) << "\nschema: " << listed(schema_keys));
    CHECK(reader == schema_keys);
  }
}

TEST_CASE("every choice the level reader offers is in the schema's enum", "[unit][level][schema]") {
  for (const Kind& kind : kinds()) {
    for (const std::string& key : declared_keys(kind)) {
      const json property = resolved(kind.schema.at("properties").at(key));
      if (!property.contains("enum")) continue;
      json object = kind.base(key);
      object[key] = kUnknown;
      const auto issues = issues_of(kind.level(object));
      const Issue* bad = issue_at(issues, kind.path + "/" + key);
      INFO(kind.name << "." << key << "\n" << joined(issues));
      REQUIRE(bad != nullptr);
      const auto enum_values = strings(property.at("enum"));
      CHECK(quoted_after(bad->message, "must be one of ") ==
            std::set<std::string>(enum_values.begin(), enum_values.end()));
    }
  }
  // The conditions' types and the actions' names, which select a branch of a oneOf.
  struct Selector {
    const char* definition;
    const char* key;
    std::function<json(const json&)> level;
    const char* path;
  };
  const std::vector<Selector> selectors{
      {"condition", "type",
       [](const json& when) {
         return script_level({{"when", when}, {"do", json::array()}});
       },
       "/triggers/0/when/type"},
      {"action", "action",
       [](const json& action) {
         return script_level({{"when", {{"type", "start"}}}, {"do", json::array({action})}});
       },
       "/triggers/0/do/0/action"}};
  for (const Selector& selector : selectors) {
    std::set<std::string> values;
    for (const json& ref : def(selector.definition).at("oneOf"))
      values.insert(resolved(ref).at("properties").at(selector.key).at("const").get<std::string>());
    const auto issues = issues_of(selector.level({{selector.key, kUnknown}}));
    const Issue* bad = issue_at(issues, selector.path);
    INFO(selector.definition << "\n" << joined(issues));
    REQUIRE(bad != nullptr);
    CHECK(quoted_after(bad->message, "must be one of ") == values);
  }
}

TEST_CASE("every default in the schema is the engine's default", "[unit][level][schema]") {
  const auto engine = engine_defaults();
  for (const Kind& kind : kinds()) {
    if (!kind.core) continue;
    const json& properties = kind.schema.at("properties");
    const auto known = engine.find(kind.name);
    REQUIRE(known != engine.end());
    for (const auto& [key, property] : properties.items()) {
      const json p = resolved(property);
      if (!p.contains("default") || empty_container(p.at("default")))
        continue;  // {} and []: all defaults, none
      INFO(kind.name << "." << key << ": schema default " << p.at("default").dump());
      REQUIRE(known->second.count(key) == 1);
      CHECK(p.at("default") == known->second.at(key));
    }
    for (const auto& [key, value] : known->second) {
      INFO(kind.name << "." << key << ": the engine default " << value.dump()
                     << " is missing from the schema");
      REQUIRE(properties.contains(key));
      CHECK(resolved(properties.at(key)).contains("default"));
    }
  }
  // kinetic_friction has no fixed default: it is the tire's friction unless given.
  CHECK_FALSE(def("tire").at("properties").at("kinetic_friction").contains("default"));
  const LevelLoad load =
      load_level_text(R"({"name": "x", "tires": [{"position": [0, 1], "friction": 0.3}]})", kFile);
  REQUIRE(load.level);
  CHECK(load.level->tires.at(0).kinetic_friction == 0.3);
}

TEST_CASE("every numeric range in the schema is the level reader's range", "[unit][level][schema]") {
  for (const Kind& kind : kinds()) {
    for (const std::string& key : declared_keys(kind)) {
      const NumericSlot slot = numeric_slot(kind.schema.at("properties").at(key));
      if (slot.numbers.is_null()) continue;
      const auto bounds = bounds_of(slot.numbers);
      // Every number the reader reads has a range, so the schema gives one: below and above, here
      // or (set's value) in a rule of the object.
      bool lower = false, upper = false;
      for (const Bounds& b : bounds) (b.key.find("inimum") != std::string::npos ? lower : upper) = true;
      const bool by_rule = kind.schema.contains("allOf") && !lower && !upper;
      INFO(kind.name << "." << key);
      CHECK(((lower && upper) || by_rule));
      check_bounds(kind, kind.base(key), key, slot);
    }
    // Ranges that depend on another key ("set": the range of the key it sets).
    if (!kind.schema.contains("allOf") || kind.name == "prop" || kind.name == "chassis") continue;
    for (const json& rule : kind.schema.at("allOf")) {
      const json& selector = rule.at("if").at("properties");
      REQUIRE(selector.size() == 1);
      const std::string selector_key = selector.begin().key();
      const json& choice = selector.begin().value();
      const std::vector<std::string> values =
          choice.contains("const") ? std::vector<std::string>{choice.at("const").get<std::string>()}
                                   : strings(choice.at("enum"));
      for (const auto& [key, numbers] : rule.at("then").at("properties").items()) {
        json number_schema = resolved(kind.schema.at("properties").at(key));
        for (const auto& [k, v] : numbers.items()) number_schema[k] = v;
        for (const std::string& value : values) {
          INFO("with " << selector_key << " = " << value);
          check_bounds(kind, with(kind.base(key), selector_key, value), key,
                       {number_schema, [](const json& v) { return v; }});
        }
      }
    }
  }
}

TEST_CASE("every string length limit in the schema is the level reader's", "[unit][level][schema]") {
  for (const Kind& kind : kinds()) {
    for (const std::string& key : declared_keys(kind)) {
      const json p = resolved(kind.schema.at("properties").at(key));
      if (p.value("type", "") != "string" || p.contains("enum")) continue;
      const std::string path = kind.path + "/" + key;
      auto probe = [&](const std::string& value) {
        return issues_of(kind.level(with(kind.base(key), key, value)));
      };
      auto too_long = [&](const std::vector<Issue>& issues) {
        for (const Issue& i : issues)
          if (i.path == path && i.message.rfind("must be a string of at most", 0) == 0) return true;
        return false;
      };
      INFO(kind.name << "." << key);
      if (p.contains("maxLength")) {
        const auto max = p.at("maxLength").get<std::size_t>();
        const auto at_max = probe(std::string(max, 'a'));
        const auto over = probe(std::string(max + 1, 'a'));
        INFO(joined(at_max) << joined(over));
        CHECK_FALSE(too_long(at_max));
        CHECK(too_long(over));
      }
      if (p.value("minLength", 0) == 1) {  // names and references: "" is refused
        const auto issues = probe("");
        INFO(joined(issues));
        CHECK(issue_at(issues, path) != nullptr);
      }
    }
  }
}

TEST_CASE("the schema's prop shape rules are the level reader's", "[unit][level][schema]") {
  const auto all = kinds();
  const auto found = std::find_if(all.begin(), all.end(), [](const Kind& k) { return k.name == "prop"; });
  REQUIRE(found != all.end());
  const Kind& prop = *found;
  const json& properties = def("prop").at("properties");
  auto issues_for = [&](const json& object) { return issues_of(prop.level(object)); };
  auto complaint_at = [](const std::vector<Issue>& issues, const std::string& key) {
    for (const Issue& i : issues)
      if (at_or_under(i, "/props/0/" + key)) return true;
    return false;
  };
  // A convex counter-clockwise n-gon, also a valid chain of n points.
  auto ngon = [](std::size_t n) {
    json points = json::array();
    for (std::size_t i = 0; i < n; ++i) {
      const double a = 2.0 * 3.141592653589793 * static_cast<double>(i) / static_cast<double>(n);
      points.push_back({std::cos(a), std::sin(a)});
    }
    return points;
  };

  for (const std::string& shape : strings(properties.at("shape").at("enum"))) {
    const json then = prop_rule("shape", shape);
    REQUIRE(then.is_object());
    const json valid = prop_of_shape(shape);
    {
      const auto issues = issues_for(valid);
      INFO(valid.dump() << "\n" << joined(issues));
      CHECK(issues.empty());
    }
    for (const std::string& key : strings(then.value("required", json::array()))) {
      json object = valid;
      object.erase(key);
      const auto issues = issues_for(object);
      INFO(shape << " without " << key << "\n" << joined(issues));
      CHECK(complaint_at(issues, key));
    }
    for (const auto& [key, rule] : then.at("properties").items()) {
      INFO(shape << "." << key << " " << rule.dump());
      if (rule == json(false)) {  // a key of other shapes
        const auto issues = issues_for(with(valid, key, sample(properties.at(key))));
        INFO(joined(issues));
        CHECK(complaint_at(issues, key));
      } else if (rule.contains("const")) {  // chains are static only
        const auto issues = issues_for(with(valid, key, rule.at("const")));
        INFO(joined(issues));
        CHECK(issues.empty());
        for (const std::string& other : strings(properties.at(key).at("enum"))) {
          if (other == rule.at("const")) continue;
          const auto wrong = issues_for(with(valid, key, other));
          INFO(other << "\n" << joined(wrong));
          CHECK(complaint_at(wrong, key));
        }
      } else if (key == "points") {  // how many points
        const auto min = rule.value("minItems", properties.at("points").at("minItems").get<std::size_t>());
        std::vector<std::pair<std::size_t, bool>> counts{{min - 1, false}, {min, true}};
        if (rule.contains("maxItems")) {
          const auto max = rule.at("maxItems").get<std::size_t>();
          counts.push_back({max, true});
          counts.push_back({max + 1, false});
        }
        for (const auto& [n, ok] : counts) {
          const auto issues = issues_for(with(valid, "points", ngon(n)));
          INFO(n << " points\n" << joined(issues));
          CHECK(complaint_at(issues, "points") == !ok);
        }
      } else {
        FAIL("a prop shape rule this test does not know: " << rule.dump());
      }
    }
  }

  // A closed chain needs 3 points.
  const json loop = prop_rule("loop", true);
  REQUIRE(loop.is_object());
  const auto loop_min = loop.at("properties").at("points").at("minItems").get<std::size_t>();
  json chain = with(prop_of_shape("chain"), "loop", true);
  CHECK(complaint_at(issues_for(with(chain, "points", ngon(loop_min - 1))), "points"));
  CHECK(issues_for(with(chain, "points", ngon(loop_min))).empty());

  // Only kinematic props have a path.
  REQUIRE(forbids(prop_rule("type", "kinematic", "else"), "path"));
  const json path = sample(properties.at("path"));
  for (const std::string& type : strings(properties.at("type").at("enum"))) {
    const auto issues = issues_for(with(with(prop_of_shape("box"), "type", type), "path", path));
    INFO(type << "\n" << joined(issues));
    CHECK(complaint_at(issues, "path") == (type != "kinematic"));
  }
}

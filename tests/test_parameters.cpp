// The parameter table (tire/parameters.h) is the one authority on the tunable numbers: each row's
// range is enforced the same way, with the same message, by every reader that may set it (the
// level reader, a script's `set` action, a replay's `set` input) and by World::set_parameter, and
// refused by those the row does not name. The tests loop over the table, so a new row is covered
// as soon as it is written.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tire/io/level_format.h"
#include "tire/replay/replay.h"
#include "tire/tire/parameters.h"
#include "tire_fixtures.h"

using namespace tire;
using json = nlohmann::json;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// In the row's range and, for an integer row, whole: written out here rather than through
// Parameter::accepts, so that the test does not take the table's word for it.
bool expected_ok(const Parameter& p, double v) {
  const Range& r = p.range;
  const bool above_min = r.min_open ? v > r.min : v >= r.min;
  const bool below_max = r.max_open ? v < r.max : v <= r.max;
  return above_min && below_max && (!p.integer || std::floor(v) == v);
}

// Values at, just past and between the ends of the row's range, and some fractions.
std::vector<double> probes(const Parameter& p) {
  const Range& r = p.range;
  std::vector<double> v{r.min,
                        r.max,
                        std::nextafter(r.min, -kInf),
                        std::nextafter(r.max, kInf),
                        (r.min + r.max) / 2,
                        r.min - 1,
                        r.max + 1,
                        0.0,
                        p.default_value};
  if (p.integer) v.insert(v.end(), {r.min + 0.5, r.max - 0.5});
  return v;
}

// The message every reader gives for a value out of the row's range.
std::string range_message(const Parameter& p) {
  if (p.integer) return "must be an integer in " + p.range.text() + ", got ";
  return "must be a number in " + p.range.text() + (*p.unit ? std::string(" ") + p.unit : "") + ", got ";
}

// The keys that name the row in a script or a replay: a tire row also as "player.<key>".
std::vector<std::string> keys_of(const Parameter& p) {
  std::vector<std::string> keys{p.key};
  if (p.is_tire()) keys.push_back("player." + std::string(p.key).substr(6));
  return keys;
}

// The errors, as "/path: message", of a level or replay file, without the file name.
std::vector<std::string> stripped(const std::vector<std::string>& errors, const std::string& file) {
  std::vector<std::string> out;
  for (const std::string& e : errors)
    out.push_back(e.rfind(file + ": ", 0) == 0 ? e.substr(file.size() + 2) : e);
  return out;
}

// Whether one of `errors` is at `path`; `message` its text there.
bool error_at(const std::vector<std::string>& errors, const std::string& path,
              std::string* message = nullptr) {
  for (const std::string& e : errors)
    if (e.rfind(path + ": ", 0) == 0) {
      if (message) *message = e.substr(path.size() + 2);
      return true;
    }
  return false;
}

std::vector<std::string> level_errors(const json& level) {
  return stripped(load_level_text(level.dump(), "probe.json").errors, "probe.json");
}

// A level holding the row's key at its place in a level file; `path` is set to that place.
json level_with(const Parameter& p, const json& value, std::string& path) {
  json level{{"name", "probe"}};
  const std::string key(p.key), field(p.field());
  if (key.starts_with("solver.")) {
    level["solver"][field] = value;
    path = "/solver/" + field;
  } else if (key.starts_with("budgets.")) {
    level["budgets"][field] = value;
    path = "/budgets/" + field;
  } else if (key.starts_with("tires.compliance.")) {
    level["tires"] = json::array({{{"position", {0, 1}}, {"compliance", {{field, value}}}}});
    path = "/tires/0/compliance/" + field;
  } else {
    REQUIRE(key.starts_with("tires."));
    level["tires"] = json::array({{{"position", {0, 1}}, {field, value}}});
    path = "/tires/0/" + field;
  }
  return level;
}

json script_level(const std::string& key, const json& value) {
  return {{"name", "probe"},
          {"tires", json::array({{{"position", {0, 1}}}})},
          {"triggers",
           json::array({{{"when", {{"type", "start"}}},
                         {"do", json::array({{{"action", "set"}, {"key", key}, {"value", value}}})}}})}};
}

std::vector<std::string> replay_errors(const json& inputs) {
  const json replay{{"format", kReplayFormat},
                    {"level", "probe-level.json"},
                    {"level_sha256", std::string(64, '0')},
                    {"ticks", 10},
                    {"inputs", inputs}};
  return stripped(load_replay_text(replay.dump(), "probe.json").errors, "probe.json");
}

json set_input(const std::string& key, const json& value) {
  return json::array({{{"tick", 0}, {"set", {{"key", key}, {"value", value}}}}});
}

World probe_world() { return test::flat_world(test::tire_at({0, 0.5}, true)); }

}  // namespace

TEST_CASE("the parameter table: one row a key, its default the engine's, its setters consistent",
          "[unit][parameters]") {
  // A world built from a level that gives nothing holds every row's default.
  const LevelLoad load =
      load_level_text(R"({"name": "defaults", "tires": [{"position": [0, 1]}]})", "defaults.json");
  REQUIRE(load.level);
  const std::unique_ptr<LevelSession> session = make_session(*load.level);
  const World* const world = &session->world();
  for (const Parameter& p : parameters()) {
    INFO(p.key);
    CHECK(find_parameter(p.key) == &p);
    CHECK(&parameter(p.id) == &p);
    CHECK(world->parameter(p.key) == p.default_value);
    CHECK(p.accepts(p.default_value));
    // What the panel, a script or a replay sets is set while the world runs, so World takes it.
    CHECK(p.runtime() == (p.may(by_script) || p.may(by_replay) || p.may(by_panel)));
    if (p.is_tire())
      CHECK(find_parameter("player." + std::string(p.key).substr(6)) == &p);
    else
      CHECK(find_parameter("player." + std::string(p.key)) == nullptr);
  }
  CHECK(find_parameter("tires.colour") == nullptr);
  CHECK(find_parameter("player.solver.substeps") == nullptr);
  // The defaults are TireSpec's and SolverConfig's.
  CHECK(parameter(ParamId::tire_mass).default_value == TireSpec{}.mass);
  CHECK(parameter(ParamId::tire_compliance_spoke).default_value == TireSpec{}.compliance.spoke);
  CHECK(parameter(ParamId::solver_substeps).default_value == SolverConfig{}.substeps);
  CHECK(Level{}.gravity ==
        Vec2{parameter(ParamId::gravity_x).default_value, parameter(ParamId::gravity_y).default_value});
}

TEST_CASE(
    "every row's range is enforced identically by the level, script and replay readers and "
    "World::set_parameter",
    "[unit][parameters]") {
  for (const Parameter& p : parameters()) {
    const std::string want = range_message(p);
    for (const double v : probes(p)) {
      const bool ok = expected_ok(p, v);
      INFO(p.key << " = " << json(v).dump() << (ok ? " (in range)" : " (out of range)"));

      // The level reader, where a level may give the key.
      if (p.may(by_level)) {
        std::string path, message;
        const auto errors = level_errors(level_with(p, v, path));
        INFO("level: " << path);
        // tires.inner_radius may also be refused for not being less than outer_radius, and
        // tires.max_pressure for being below min_pressure.
        const bool refused = error_at(errors, path, &message) && message.rfind("must be less than", 0) != 0 &&
                             message.rfind("must be at least min_pressure", 0) != 0;
        CHECK(refused == !ok);
        if (refused) CHECK(message == want + json(v).dump());
      }

      for (const std::string& key : keys_of(p)) {
        INFO("key " << key);
        // A script's set action.
        {
          const auto errors = level_errors(script_level(key, v));
          std::string message;
          if (p.may(by_script)) {
            CHECK_FALSE(error_at(errors, "/triggers/0/do/0/key"));
            CHECK(error_at(errors, "/triggers/0/do/0/value", &message) == !ok);
            if (!ok) CHECK(message == want + json(v).dump());
          } else {
            CHECK(error_at(errors, "/triggers/0/do/0/key"));
          }
        }
        // A replay's set input.
        {
          const auto errors = replay_errors(set_input(key, v));
          std::string message;
          if (p.may(by_replay)) {
            CHECK_FALSE(error_at(errors, "/inputs/0/set/key"));
            CHECK(error_at(errors, "/inputs/0/set/value", &message) == !ok);
            if (!ok) CHECK(message == want + json(v).dump());
          } else {
            CHECK(error_at(errors, "/inputs/0/set/key"));
          }
        }
        // World::set_parameter: the rows set while the world runs; false, changing nothing, otherwise.
        {
          World world = probe_world();
          const std::optional<double> before = world.parameter(key);
          const bool set = world.set_parameter(key, v);
          CHECK(set == (ok && p.runtime()));
          if (set)
            CHECK(world.parameter(key).value_or(kInf) == Approx(v).margin(1e-12));
          else
            CHECK(world.parameter(key) == before);
        }
      }
    }
    // Numbers JSON cannot spell reach World::set_parameter only from code: refused all the same.
    for (const double v : {std::numeric_limits<double>::quiet_NaN(), kInf, -kInf}) {
      World world = probe_world();
      INFO(p.key << " = " << v);
      CHECK_FALSE(world.set_parameter(p.key, v));
    }
  }
}

TEST_CASE("the gravity rows' range is the level's, a set_gravity action's and a replay gravity input's",
          "[unit][parameters]") {
  const Parameter& g = parameter(ParamId::gravity_x);
  REQUIRE(parameter(ParamId::gravity_y).range == g.range);
  const std::string want = "must be [x, y] with each in " + g.range.text() + " " + g.unit + ", got ";
  for (const double v :
       {g.range.min, g.range.max, std::nextafter(g.range.min, -kInf), std::nextafter(g.range.max, kInf)}) {
    const bool ok = expected_ok(g, v);
    const json gravity{0.0, v};
    INFO(gravity.dump());
    std::string message;
    CHECK(error_at(level_errors({{"name", "probe"}, {"gravity", gravity}}), "/gravity", &message) == !ok);
    if (!ok) CHECK(message == want + gravity.dump());
    const json action{{"action", "set_gravity"}, {"gravity", gravity}};
    const json level{
        {"name", "probe"},
        {"triggers", json::array({{{"when", {{"type", "start"}}}, {"do", json::array({action})}}})}};
    CHECK(error_at(level_errors(level), "/triggers/0/do/0/gravity") == !ok);
    CHECK(error_at(replay_errors(json::array({{{"tick", 0}, {"gravity", gravity}}})), "/inputs/0/gravity") ==
          !ok);
  }
}

TEST_CASE("a replay that sets tires.mass_scale to 0 is refused, and so is the world's set_parameter",
          "[unit][parameters]") {
  // The tire would divide by its mass: 2n / (spawn mass x 0) is infinite, and it diverged every tick.
  const std::string file = test::source_path("tests/replays-bad/mass-scale-zero.json");
  const ReplayLoad load = load_replay_file(file);
  CHECK_FALSE(load.replay);
  CHECK(load.errors ==
        std::vector<std::string>{
            file +
            ": /inputs/0/set/value: must be a number in [0.01, 10] (times the tire's spawn mass), got 0"});
  // The same replay with a scale in range is a valid replay.
  CHECK(replay_errors(set_input("tires.mass_scale", 0.5)).empty());
  CHECK(replay_errors(set_input("player.mass_scale", 10)).empty());
  CHECK_FALSE(replay_errors(set_input("player.mass_scale", 1e-320)).empty());

  World world = probe_world();
  const double mass = world.tires()[0].spec.mass;
  CHECK_FALSE(world.set_parameter("tires.mass_scale", 0.0));
  CHECK_FALSE(world.set_parameter("player.mass_scale", 1e-320));
  CHECK_FALSE(world.set_parameter("tires.mass", 0.0));
  CHECK(world.tires()[0].spec.mass == mass);
  test::run(world, 30);
  CHECK(world.warnings().empty());  // no divergence
  CHECK(is_finite(world.tires()[0].centroid()));
}

TEST_CASE("the public description of the parameters and the material presets reads the table's rows",
          "[unit][parameters]") {
  REQUIRE(tunable_parameters().size() == parameters().size());
  for (std::size_t i = 0; i < parameters().size(); ++i) {
    const Parameter& p = parameters()[i];
    const TunableParameter& d = tunable_parameters()[i];
    INFO(p.key);
    CHECK(d.key == p.key);
    CHECK(d.unit == p.unit);
    CHECK(d.range == p.range);
    CHECK(d.integer == p.integer);
    CHECK(d.default_value == p.default_value);
    CHECK(d.default_follows == (p.default_follows ? p.default_follows : ""));
    CHECK(d.description == p.description);
    CHECK(d.by_level == p.may(by_level));
    CHECK(d.by_script == p.may(by_script));
    CHECK(d.by_replay == p.may(by_replay));
    CHECK(d.by_panel == p.may(by_panel));
    CHECK(find_tunable_parameter(p.key) == &d);
    CHECK(d.accepts(p.range.min) == p.accepts(p.range.min));
  }
  CHECK(find_tunable_parameter("player.friction") == find_tunable_parameter("tires.friction"));
  CHECK(find_tunable_parameter("tires.nonsense") == nullptr);
  REQUIRE(material_presets().size() == kMaterials.size());
  for (std::size_t i = 0; i < kMaterials.size(); ++i) {
    const Material& m = kMaterials[i];
    const MaterialPreset& d = material_presets()[i];
    INFO(m.name);
    CHECK(d.name == m.name);
    CHECK(d.description == m.description);
    CHECK(find_material_preset(m.name) == &d);
    for (const Parameter& p : parameters()) CHECK(d.value(p.key) == m.value_of(p.id));
  }
  CHECK(find_material_preset("granite") == nullptr);
}

// Level files are untrusted: every problem is found in one pass and named by its JSON path.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "error_messages.h"
#include "tire_fixtures.h"

using tire_test::has;
using tire_test::joined;

using namespace tire;
using namespace tire::test;

namespace {
std::vector<std::string> errors_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return load_level_text(text, "x.json", overrides).errors;
}
}  // namespace

TEST_CASE("every shipped level is valid", "[unit][level]") {
  for (const auto& entry : std::filesystem::directory_iterator(source_path("levels"))) {
    if (entry.path().extension() != ".json" || entry.path().filename() == "schema.json") continue;
    const LevelLoad load = load_level_file(entry.path());
    INFO(entry.path() << "\n" << joined(load.errors));
    CHECK(load.level.has_value());
  }
}

TEST_CASE("the default level reads as written", "[unit][level]") {
  const Level level = default_level();
  CHECK(level.name == "First roll");
  CHECK(level.solver.method == SolverMethod::global);
  CHECK(level.solver.substeps == 2);
  REQUIRE(level.tires.size() == 1);
  CHECK(level.tires[0].segments == 28);
  CHECK(level.tires[0].compliance.inner == 1e-7);
  CHECK(level.obstacles.size() >= 1);
}

TEST_CASE("all problems are reported in one pass with their JSON paths", "[unit][level]") {
  const auto errors = errors_of(R"({
    "name": "bad",
    "solver": { "dt": 0, "substeps": 2.5, "iterations": "many" },
    "tires": [ { "position": [0, 1], "segments": 2, "masss": 3, "inner_radius": 0.6 },
               { "segments": 300, "mass": -1, "player": true },
               { "position": [0, 1e9], "player": true, "spokes": "wire" } ],
    "obstacles": [ { "min": [0, 0], "max": [0, 1] }, { "min": [0, 0] } ],
    "extra": 1 })");
  INFO(joined(errors));
  CHECK(has(errors, "x.json: /solver/dt: must be a number in [0.0001, 0.1] s, got 0"));
  CHECK(has(errors, "x.json: /solver/substeps: must be an integer in [1, 256], got 2.5"));
  CHECK(has(errors, "x.json: /solver/iterations: must be an integer in [1, 64], got \"many\""));
  CHECK(has(errors, "x.json: /tires/0/segments: must be an integer in [6, 256], got 2"));
  CHECK(has(errors, "x.json: /tires/0/masss: unknown key; did you mean \"mass\"?"));
  CHECK(has(errors, "x.json: /tires/0/inner_radius: must be less than outer_radius (0.5), got 0.6"));
  CHECK(has(errors, "x.json: /tires/1/position: is required"));
  CHECK(has(errors, "x.json: /tires/1/segments: must be an integer in [6, 256], got 300"));
  CHECK(has(errors, "x.json: /tires/1/mass: must be a number in [0.001, 1e+06] kg, got -1"));
  CHECK(
      has(errors,
          "x.json: /tires/2/position: must be [x, y] with each in [-10000, 10000] m, got [0,1000000000.0]"));
  CHECK(has(errors, "x.json: /tires/2/player: only one tire may be the player, and /tires/1 already is"));
  CHECK(has(errors, "x.json: /tires/2/spokes: must be one of \"radial\", \"cross\", got \"wire\""));
  CHECK(has(errors, "x.json: /obstacles/0/max: must be greater than min on both axes"));
  CHECK(has(errors, "x.json: /obstacles/1/max: is required"));
  CHECK(has(errors, "x.json: /extra: unknown key; expected one of"));
  CHECK(errors.size() == 15);
}

TEST_CASE("wrong shapes and missing names are reported, not crashed on", "[unit][level]") {
  CHECK(has(errors_of("[]"), "x.json: /: must be an object, got []"));
  CHECK(has(errors_of("{}"), "x.json: /name: is required: a string"));
  CHECK(has(errors_of(R"({"name": "n", "tires": {}})"), "/tires: must be an array, got an object"));
  CHECK(has(errors_of(R"({"name": "n", "tires": [7]})"), "/tires/0: must be an object, got 7"));
  CHECK(has(errors_of(R"({"name": "n", "gravity": [1]})"), "/gravity: must be [x, y]"));
  CHECK(has(errors_of(R"({"name": "n", "tires": [{"position": [0, 1], "compliance": {"outr": 1}}]})"),
            "/tires/0/compliance/outr: unknown key; did you mean \"outer\"?"));
}

TEST_CASE("invalid JSON is reported with line and column", "[unit][level]") {
  const auto errors = errors_of("{\n  \"name\": \"x\",\n  \"tires\": [ }\n}");
  REQUIRE(errors.size() == 1);
  CHECK(has(errors, "x.json: invalid JSON: parse error at line 3, column 14"));
  CHECK(has(errors_of(""), "x.json: invalid JSON"));
}

TEST_CASE("nesting deeper than the limit is refused while parsing", "[unit][level]") {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const auto errors = errors_of(deep);
  REQUIRE(errors.size() == 1);
  CHECK(has(errors, "nesting deeper than 64"));
}

TEST_CASE("a missing or oversized file is refused before it is read", "[unit][level]") {
  CHECK(has(load_level_file("/nonexistent/level.json").errors, "/nonexistent/level.json: no such file"));
  const auto big = std::filesystem::temp_directory_path() / "tire-oversized-level.json";
  {
    std::ofstream out(big, std::ios::binary);
    out.seekp(static_cast<std::streamoff>(LevelLimits::max_file_bytes));
    out.put(' ');
  }
  CHECK(has(load_level_file(big).errors, "the limit is 67108864"));
  std::filesystem::remove(big);
}

TEST_CASE("set overrides numeric keys by dotted path, and validation judges the result", "[unit][level]") {
  const std::string text = R"({"name": "n", "tires": [{"position": [0, 1]}]})";
  LevelLoad load =
      load_level_text(text, "x.json", {"solver.substeps=16", "tires.0.mass=20", "tires.0.position.1=3"});
  REQUIRE(load.level);
  CHECK(load.level->solver.substeps == 16);
  CHECK(load.level->tires[0].mass == 20);
  CHECK(load.level->tires[0].position.y == 3);
  CHECK(
      has(errors_of(text, {"solver.substeps=0"}), "/solver/substeps: must be an integer in [1, 256], got 0"));
  CHECK(has(errors_of(text, {"solver.substepz=4"}),
            "/solver/substepz: unknown key; did you mean \"substeps\"?"));
  CHECK(has(errors_of(text, {"tires.3.mass=1"}), "\"3\" is not an index of the 1-entry array"));
  CHECK(has(errors_of(text, {"tires.0.mass=heavy"}), "value must be a number, got \"heavy\""));
  CHECK(has(errors_of(text, {"tires=1"}), "is an object or array, not a number"));
  CHECK(has(errors_of(text, {"nonsense"}), "expected key=value"));
}

TEST_CASE("a --set key with an empty part is refused, naming the key", "[unit][level]") {
  const std::string text = R"({"name": "n", "tires": [{"position": [0, 1]}]})";
  // "solver.dt." was once read as solver.dt: a leading, trailing or doubled dot is a mistake.
  for (const std::string key : {"solver.dt.", ".solver.dt", "solver..dt", "tires.0.mass.", "."}) {
    const auto errors = errors_of(text, {key + "=0.01"});
    INFO(key << "\n" << joined(errors));
    REQUIRE(errors.size() == 1);
    CHECK(errors[0] == "x.json: --set " + key + "=0.01: the key \"" + key +
                           "\" has an empty part (a leading, trailing or doubled dot); expected names and "
                           "indices joined by single dots, e.g. tires.0.mass");
  }
  CHECK(errors_of(text, {"solver.dt=0.01"}).empty());
}

TEST_CASE("a file name or --set with a newline cannot forge a line of the messages", "[unit][level]") {
  const auto bad = load_level_text(R"({"name": 3})", "x\nlevels/01.json: ok").errors;
  REQUIRE_FALSE(bad.empty());
  for (const std::string& e : bad) {
    CHECK(e.rfind("x\\nlevels/01.json: ok: /", 0) == 0);
    CHECK(e.find('\n') == std::string::npos);
  }
  const auto set = errors_of(R"({"name": "n", "tires": [{"position": [0, 1]}]})", {"solver\n.dt=x"});
  REQUIRE(set.size() == 1);
  CHECK(set[0].find('\n') == std::string::npos);
  CHECK(has(set, "--set solver\\n.dt=x: value must be a number"));
  // A key of the file's own, unknown, with a newline in it.
  const auto key = errors_of(R"({"name": "n", "ok\nx.json: ok": 1, "tires": [{"position": [0, 1]}]})");
  CHECK(has(key, "x.json: /ok\\nx.json: ok: unknown key"));
  for (const std::string& e : key) CHECK(e.find('\n') == std::string::npos);
}

TEST_CASE("solver.sleep is read as a boolean, true unless the level says false", "[unit][level]") {
  const auto solver_of = [](const std::string& solver) {
    const std::string text = R"({"name": "n", )" + solver + R"("tires": [{"position": [0, 1]}]})";
    LevelLoad load = load_level_text(text, "x.json");
    INFO(text << "\n" << joined(load.errors));
    REQUIRE(load.level);
    return load.level->solver;
  };
  CHECK(SolverConfig{}.sleep);
  CHECK(solver_of("").sleep);
  CHECK(solver_of(R"("solver": {"substeps": 4}, )").sleep);
  CHECK(solver_of(R"("solver": {"sleep": true}, )").sleep);
  const SolverConfig off = solver_of(R"("solver": {"sleep": false, "method": "global"}, )");
  CHECK_FALSE(off.sleep);
  CHECK(off.method == SolverMethod::global);
}

TEST_CASE("a solver.sleep that is not a boolean is reported with its path", "[unit][level]") {
  const std::string before = R"({"name": "n", "solver": {"sleep": )";
  const std::string after = R"(}, "tires": [{"position": [0, 1]}]})";
  for (const auto& [value, got] : std::vector<std::pair<std::string, std::string>>{
           {"\"no\"", "\"no\""}, {"0", "0"}, {"1", "1"}, {"null", "null"}, {"[true]", "[true]"}}) {
    const auto errors = errors_of(before + value + after);
    INFO(value << "\n" << joined(errors));
    CHECK(errors.size() == 1);
    CHECK(has(errors, "x.json: /solver/sleep: must be true or false, got " + got));
  }
  // A --set gives a number, never a boolean: refused like the file's.
  CHECK(has(errors_of(R"({"name": "n", "tires": [{"position": [0, 1]}]})", {"solver.sleep=0"}),
            "x.json: /solver/sleep: must be true or false, got 0"));
}

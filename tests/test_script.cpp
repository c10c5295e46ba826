// Level scripts: the reader finds every problem with its path; the runner fires triggers at the
// documented ticks, in file order, and its state is in the hash.
#include <catch2/catch.hpp>

#include "fake_script_host.h"
#include "script_reader.h"
#include "tire/script/script_runner.h"

using namespace tire;
using namespace tire::test;

namespace {

struct ScriptRead {
  ScriptSpec spec;
  std::vector<JsonIssue> issues;
};

ScriptRead read(const std::string& text, const std::vector<std::string>& props = {"crate", "lift"}) {
  ScriptRead out;
  JsonReader r(out.issues);
  out.spec = read_script(r, nlohmann::json::parse(text), props);
  return out;
}

std::string joined(const std::vector<JsonIssue>& issues) {
  std::string out;
  for (const JsonIssue& i : issues) out += i.path + ": " + i.message + "\n";
  return out;
}

bool has(const std::vector<JsonIssue>& issues, const std::string& path, const std::string& message) {
  for (const JsonIssue& i : issues)
    if (i.path == path && i.message == message) return true;
  return false;
}

// A runner for a script that must be valid.
ScriptRunner runner_for(const std::string& text) {
  ScriptRead r = read(text);
  INFO(joined(r.issues));
  REQUIRE(r.issues.empty());
  return ScriptRunner(std::move(r.spec));
}

std::uint64_t hash_of(const ScriptRunner& runner) {
  StateHash h;
  runner.hash_into(h);
  return h.digest();
}

}  // namespace

TEST_CASE("the reader accepts a script using every trigger and action", "[unit][script]") {
  const ScriptRead r = read(R"({
    "name": "all", "tires": [],
    "regions": [ { "name": "finish", "min": [40, 0], "max": [44, 5] },
                 { "name": "pit", "min": [10, -5], "max": [12, -1] },
                 { "name": "bin", "min": [0, 0], "max": [1, 1] } ],
    "goal": "finish",
    "time_limit": 60,
    "counters": { "coins": 0, "lives": 3 },
    "triggers": [
      { "name": "hello", "when": { "type": "start" },
        "do": [ { "action": "message", "text": "Roll right!", "seconds": 3 },
                { "action": "spawn_tire", "tire": { "position": [2, 1], "outer_radius": 0.4, "inner_radius": 0.2 } },
                { "action": "spawn_prop", "prop": { "name": "ball", "shape": "circle", "type": "dynamic",
                                                    "position": [3, 2], "radius": 0.2 } } ] },
      { "when": { "type": "time", "at": 5.0 },
        "do": [ { "action": "set_gravity", "gravity": [0, -5] }, { "action": "checkpoint", "position": [20, 1] } ] },
      { "when": { "type": "every", "period": 2.0, "start": 1.0, "count": 10 },
        "do": [ { "action": "impulse", "target": "player", "impulse": [0, 10] },
                { "action": "impulse", "target": "all_tires", "impulse": [1, 0] },
                { "action": "impulse", "target": "ball", "impulse": [1, 0] } ] },
      { "when": { "type": "enter", "region": "pit", "who": "player" }, "do": [ { "action": "lose" } ] },
      { "when": { "type": "leave", "region": "bin", "who": "any" }, "once": true,
        "do": [ { "action": "set", "key": "solver.substeps", "value": 16 },
                { "action": "set", "key": "tires.max_speed", "value": 20 },
                { "action": "path", "prop": "lift", "command": "reverse" } ] },
      { "when": { "type": "prop_enter", "region": "bin", "prop": "crate" },
        "do": [ { "action": "counter", "counter": "coins", "add": 1 }, { "action": "remove_prop", "prop": "crate" } ] },
      { "when": { "type": "counter", "counter": "coins", "value": 3 },
        "do": [ { "action": "counter", "counter": "lives", "set": 5 }, { "action": "win" }, { "action": "next_level" } ] }
    ] })");
  INFO(joined(r.issues));
  REQUIRE(r.issues.empty());
  const ScriptSpec& s = r.spec;
  REQUIRE(s.regions.size() == 3);
  CHECK(s.regions[1].name == "pit");
  CHECK(s.regions[0].box.max == Vec2{44, 5});
  CHECK(s.goal == std::optional<std::size_t>{0});
  CHECK(s.time_limit == std::optional<double>{60.0});
  REQUIRE(s.counters.size() == 2);
  CHECK(s.counters[1].name == "lives");
  CHECK(s.counters[1].initial == 3);
  REQUIRE(s.triggers.size() == 7);
  CHECK(s.triggers[0].name == "hello");
  CHECK(s.triggers[0].once);
  REQUIRE(s.triggers[0].actions.size() == 3);
  CHECK(std::get<SpawnTire>(s.triggers[0].actions[1]).tire.outer_radius == 0.4);
  CHECK(std::get<SpawnProp>(s.triggers[0].actions[2]).prop.name == "ball");
  const auto& every = std::get<Every>(s.triggers[2].when);
  CHECK(every.period == 2.0);
  CHECK(every.start == 1.0);
  CHECK(every.count == std::optional<int>{10});
  CHECK_FALSE(s.triggers[2].once);
  CHECK(std::get<ApplyImpulse>(s.triggers[2].actions[2]).target == ImpulseTarget::prop);
  CHECK_FALSE(s.triggers[3].once);  // enter repeats unless told otherwise
  CHECK(std::get<RegionCrossing>(s.triggers[4].when).who == Who::any);
  CHECK(s.triggers[4].once);
  CHECK(std::get<SetParameter>(s.triggers[4].actions[0]).value == 16);
  CHECK(std::get<ControlPath>(s.triggers[4].actions[2]).command == PathCommand::reverse);
  CHECK(std::get<CounterReaches>(s.triggers[6].when).counter == 0);
  CHECK(std::get<ChangeCounter>(s.triggers[6].actions[0]).set);
}

TEST_CASE("every script problem is reported in one pass with its exact path", "[unit][script]") {
  const ScriptRead r = read(R"({
    "regions": [ { "name": "finish", "min": [4, 0], "max": [4, 5] },
                 { "name": "finish", "min": [0, 0], "max": [1, 1] } ],
    "goal": "finsh",
    "time_limit": 0,
    "counters": { "coins": 0.5 },
    "triggers": [
      { "when": { "type": "enter", "region": "pitt", "who": "everyone" }, "do": [] },
      { "when": { "type": "start" }, "do": [ { "action": "message", "txt": "hi" } ] },
      { "when": { "type": "time", "at": 1 } },
      { "when": { "type": "start" }, "do": [ { "action": "set", "key": "solver.dt", "value": 0.01 },
                                               { "action": "set", "key": "player.pressure", "value": 9 } ] },
      { "when": { "type": "counter", "counter": "coin", "value": 1 },
        "do": [ { "action": "impulse", "target": "crat", "impulse": [0, 1] },
                { "action": "counter", "counter": "coins" },
                { "action": "jump" } ] },
      { "when": { "type": "sometimes" }, "do": [] }
    ] })");
  INFO(joined(r.issues));
  CHECK(has(r.issues, "/regions/0/max", "must be greater than min on both axes, got [4,5] with min [4,0]"));
  CHECK(has(r.issues, "/regions/1/name", "must be unique, got \"finish\", which /regions/0 already has"));
  CHECK(has(r.issues, "/goal", "must name a region, got \"finsh\"; did you mean \"finish\"?"));
  CHECK(has(r.issues, "/time_limit", "must be a number in (0, 86400] s, got 0"));
  CHECK(has(r.issues, "/counters/coins", "must be an integer in [-1e+09, 1e+09], got 0.5"));
  CHECK(has(r.issues, "/triggers/0/when/region", "must name a region (one of \"finish\"), got \"pitt\""));
  CHECK(has(r.issues, "/triggers/0/when/who", "must be one of \"player\", \"any\", got \"everyone\""));
  CHECK(has(r.issues, "/triggers/1/do/0/txt", "unknown key; did you mean \"text\"?"));
  CHECK(has(r.issues, "/triggers/1/do/0/text", "is required: a string"));
  CHECK(has(r.issues, "/triggers/2/do", "is required: an array of actions"));
  CHECK(has(
      r.issues, "/triggers/3/do/0/key",
      "must be one of \"solver.substeps\", \"solver.iterations\", \"solver.damping\", \"player.friction\", "
      "\"player.kinetic_friction\", \"player.pressure\", \"player.material_damping\", "
      "\"player.rolling_resistance\", \"player.drive_acceleration\", \"player.jump_speed\", "
      "\"player.max_speed\", \"player.restitution\", \"player.inflate_rate\", \"player.min_pressure\", "
      "\"player.max_pressure\", \"tires.friction\", \"tires.kinetic_friction\", \"tires.pressure\", "
      "\"tires.material_damping\", \"tires.rolling_resistance\", \"tires.drive_acceleration\", "
      "\"tires.jump_speed\", \"tires.max_speed\", \"tires.restitution\", \"tires.inflate_rate\", "
      "\"tires.min_pressure\", \"tires.max_pressure\", got \"solver.dt\""));
  CHECK(has(r.issues, "/triggers/3/do/1/value",
            "must be a number in [0.1, 4] (fraction of the rest area), got 9"));
  CHECK(has(r.issues, "/triggers/4/when/counter",
            "must name a counter, got \"coin\"; did you mean \"coins\"?"));
  CHECK(has(r.issues, "/triggers/4/do/0/target",
            "must name \"player\", \"all_tires\" or a prop, got \"crat\"; did you mean \"crate\"?"));
  CHECK(has(r.issues, "/triggers/4/do/1", "must have exactly one of \"add\" or \"set\", got neither"));
  CHECK(has(
      r.issues, "/triggers/4/do/2/action",
      "must be one of \"spawn_tire\", \"spawn_prop\", \"remove_prop\", \"set_gravity\", \"impulse\", "
      "\"set\", "
      "\"path\", \"message\", \"checkpoint\", \"counter\", \"win\", \"lose\", \"next_level\", got \"jump\""));
  CHECK(
      has(r.issues, "/triggers/5/when/type",
          "must be one of \"start\", \"time\", \"every\", \"enter\", \"leave\", \"prop_enter\", \"counter\", "
          "got \"sometimes\""));
  CHECK(r.issues.size() == 17);
}

TEST_CASE("a script's shape errors are reported, not crashed on", "[unit][script]") {
  CHECK(has(read(R"({"regions": {}})").issues, "/regions", "must be an array, got an object"));
  CHECK(has(read(R"({"regions": [{"min": [0, 0], "max": [1, 1]}]})").issues, "/regions/0/name",
            "is required: a string"));
  CHECK(has(read(R"({"counters": [1]})").issues, "/counters",
            "must be an object of counter names to integers, got [1]"));
  CHECK(has(read(R"({"triggers": [{"do": []}]})").issues, "/triggers/0/when",
            "is required: an object with a \"type\""));
  CHECK(has(read(R"({"triggers": [{"when": {}, "do": []}]})").issues, "/triggers/0/when/type",
            "is required: one of \"start\", \"time\", \"every\", \"enter\", \"leave\", \"prop_enter\", "
            "\"counter\""));
  CHECK(has(read(R"({"triggers": [{"when": {"type": "start", "at": 1}, "do": []}]})").issues,
            "/triggers/0/when/at", "unknown key; expected one of \"type\""));
  CHECK(has(
      read(R"({"triggers": [{"when": {"type": "start"}, "do": [{"action": "win", "now": true}]}]})").issues,
      "/triggers/0/do/0/now", "unknown key; expected one of \"action\""));
  CHECK(has(read(R"({"triggers": [{"when": {"type": "every"}, "do": []}]})").issues,
            "/triggers/0/when/period", "is required: a number in (0, 86400] s"));
  CHECK(has(read(R"({"triggers": [{"when": {"type": "enter", "region": "x"}, "do": []}]})").issues,
            "/triggers/0/when/region", "must name a region, got \"x\", and the level defines none"));
  CHECK(has(read(R"({"triggers": [{"when": {"type": "start"},
                                   "do": [{"action": "remove_prop", "prop": "ghost"}]}]})")
                .issues,
            "/triggers/0/do/0/prop", "must name a prop (one of \"crate\", \"lift\"), got \"ghost\""));
  CHECK(has(
      read(R"({"triggers": [{"when": {"type": "start"},
                                   "do": [{"action": "set", "key": "player.fricton", "value": 1}]}]})")
          .issues,
      "/triggers/0/do/0/key",
      "must be one of \"solver.substeps\", \"solver.iterations\", \"solver.damping\", "
      "\"player.friction\", \"player.kinetic_friction\", \"player.pressure\", \"player.material_damping\", "
      "\"player.rolling_resistance\", \"player.drive_acceleration\", \"player.jump_speed\", "
      "\"player.max_speed\", \"player.restitution\", \"player.inflate_rate\", \"player.min_pressure\", "
      "\"player.max_pressure\", \"tires.friction\", \"tires.kinetic_friction\", \"tires.pressure\", "
      "\"tires.material_damping\", \"tires.rolling_resistance\", \"tires.drive_acceleration\", "
      "\"tires.jump_speed\", \"tires.max_speed\", \"tires.restitution\", \"tires.inflate_rate\", "
      "\"tires.min_pressure\", \"tires.max_pressure\", got \"player.fricton\"; did you mean "
      "\"player.friction\"?"));
  CHECK(has(read(R"({"triggers": [{"when": {"type": "start"},
                                   "do": [{"action": "set", "key": "solver.substeps", "value": 2.5}]}]})")
                .issues,
            "/triggers/0/do/0/value", "must be an integer in [1, 256], got 2.5"));
  CHECK(
      read(R"({"name": "other root keys are the level reader's", "tires": [], "props": []})").issues.empty());
}

TEST_CASE("a prop spawned by the script may be named by its other actions", "[unit][script]") {
  const ScriptRead r = read(R"({"triggers": [
      { "when": { "type": "start" }, "do": [ { "action": "remove_prop", "prop": "ball" } ] },
      { "when": { "type": "time", "at": 1 },
        "do": [ { "action": "spawn_prop", "prop": { "name": "ball", "shape": "circle", "position": [0, 1], "radius": 0.2 } } ] } ]})",
                            {});
  INFO(joined(r.issues));
  CHECK(r.issues.empty());
}

TEST_CASE("times convert to ticks by the documented rule", "[unit][script]") {
  CHECK(tick_at(0.0, 0.1) == 0);
  CHECK(tick_at(0.5, 0.1) == 5);   // 0.5/0.1 rounds to 5.000000000000001: the tolerance keeps it 5
  CHECK(tick_at(0.55, 0.1) == 6);  // the first tick whose end time is at or after 0.55 s
  CHECK(tick_at(5.0, 1.0 / 60.0) == 300);
  CHECK(tick_at(5.0, 0.0166667) == 300);  // the shipped levels' dt
  CHECK(tick_at(0.3, 0.1) == 3);
}

TEST_CASE("a start trigger fires once, at tick 0", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({"triggers": [
      { "when": { "type": "start" }, "once": false, "do": [ { "action": "message", "text": "go", "seconds": 2 } ] } ]})");
  FakeScriptHost host;
  runner.update(host);  // tick 0
  CHECK(host.calls == std::vector<std::string>{"message go 2"});
  for (int i = 0; i < 5; ++i) host.advance(runner);
  CHECK(host.calls.size() == 1);
}

TEST_CASE("a time trigger fires on the first tick whose time reaches it", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({"triggers": [
      { "when": { "type": "time", "at": 0.55 }, "do": [ { "action": "next_level" } ] } ]})");
  FakeScriptHost host;  // dt 0.1
  runner.update(host);
  std::vector<std::uint64_t> fired_at;
  for (int i = 0; i < 20; ++i) {
    host.advance(runner);
    if (host.calls.size() > fired_at.size()) fired_at.push_back(host.now);
  }
  CHECK(fired_at == std::vector<std::uint64_t>{tick_at(0.55, 0.1)});
  CHECK(fired_at == std::vector<std::uint64_t>{6});
}

TEST_CASE("an every trigger fires at start, start + period, ... and stops after count", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({"triggers": [
      { "when": { "type": "every", "period": 0.3, "start": 0.2, "count": 4 },
        "do": [ { "action": "impulse", "target": "player", "impulse": [0, 1] } ] } ]})");
  FakeScriptHost host;
  runner.update(host);
  std::vector<std::uint64_t> fired_at;
  for (int i = 0; i < 40; ++i) {
    host.advance(runner);
    if (host.calls.size() > fired_at.size()) fired_at.push_back(host.now);
  }
  CHECK(fired_at == std::vector<std::uint64_t>{2, 5, 8, 11});
}

TEST_CASE("an every trigger without a count keeps firing", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({"triggers": [
      { "when": { "type": "every", "period": 1.0 }, "do": [ { "action": "next_level" } ] } ]})");
  FakeScriptHost host;
  runner.update(host);  // start defaults to 0: fires at tick 0
  for (int i = 0; i < 100; ++i) host.advance(runner);
  CHECK(host.calls.size() == 11);  // ticks 0, 10, ..., 100
}

TEST_CASE("enter and leave fire on transitions only, for the player", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({
    "regions": [ { "name": "zone", "min": [0, 0], "max": [10, 10] } ],
    "triggers": [
      { "when": { "type": "enter", "region": "zone" }, "do": [ { "action": "message", "text": "in" } ] },
      { "when": { "type": "leave", "region": "zone" }, "do": [ { "action": "message", "text": "out" } ] } ]})");
  FakeScriptHost host;
  const TireId player = host.add_tire({-5, 1});
  const TireId other = host.add_tire({-5, 1});
  runner.update(host);
  host.advance(runner);
  CHECK(host.calls.empty());
  host.move_tire(other, {5, 5});  // not the player: ignored
  host.advance(runner);
  CHECK(host.calls.empty());
  host.move_tire(player, {5, 5});
  host.advance(runner);
  CHECK(host.calls == std::vector<std::string>{"message in 3"});
  for (int i = 0; i < 10; ++i) host.advance(runner);  // sitting inside does not re-fire
  CHECK(host.calls.size() == 1);
  host.move_tire(player, {15, 5});
  host.advance(runner);
  host.advance(runner);
  CHECK(host.calls == std::vector<std::string>{"message in 3", "message out 3"});
  host.move_tire(player, {5, 5});
  host.advance(runner);
  CHECK(host.calls.back() == "message in 3");  // enter is not once by default
  CHECK(host.count("message in") == 2);
}

TEST_CASE("enter with who any fires once for each tire that enters", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({
    "regions": [ { "name": "zone", "min": [0, 0], "max": [10, 10] } ],
    "counters": { "inside": 0 },
    "triggers": [
      { "when": { "type": "enter", "region": "zone", "who": "any" },
        "do": [ { "action": "counter", "counter": "inside", "add": 1 } ] },
      { "when": { "type": "leave", "region": "zone", "who": "any" },
        "do": [ { "action": "counter", "counter": "inside", "add": -1 } ] } ]})");
  FakeScriptHost host;
  const TireId a = host.add_tire({-5, 1});
  const TireId b = host.add_tire({-5, 1});
  host.add_tire({-5, 1});
  runner.update(host);
  host.move_tire(b, {1, 1});
  host.advance(runner);
  CHECK(runner.counter("inside") == 1);
  host.move_tire(a, {2, 1});
  host.advance(runner);
  host.advance(runner);
  CHECK(runner.counter("inside") == 2);
  host.move_tire(a, {-2, 1});
  host.move_tire(b, {-2, 1});
  host.advance(runner);
  CHECK(runner.counter("inside") == 0);
}

TEST_CASE("a once enter trigger fires for the first entry only", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({
    "regions": [ { "name": "zone", "min": [0, 0], "max": [10, 10] } ],
    "triggers": [ { "when": { "type": "enter", "region": "zone" }, "once": true, "do": [ { "action": "next_level" } ] } ]})");
  FakeScriptHost host;
  const TireId player = host.add_tire({-5, 1});
  for (int i = 0; i < 3; ++i) {
    host.move_tire(player, {5, 5});
    host.advance(runner);
    host.move_tire(player, {-5, 5});
    host.advance(runner);
  }
  CHECK(host.calls.size() == 1);
}

TEST_CASE("prop_enter fires when the prop's origin enters the region", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({
    "regions": [ { "name": "bin", "min": [0, 0], "max": [1, 1] } ],
    "triggers": [ { "when": { "type": "prop_enter", "region": "bin", "prop": "crate" },
                    "do": [ { "action": "remove_prop", "prop": "crate" } ] } ]})");
  FakeScriptHost host;
  host.props.push_back({"lift", {0.5, 0.5}});  // another prop inside: not the one watched
  host.props.push_back({"crate", {3, 0.5}});
  runner.update(host);
  host.advance(runner);
  CHECK(host.calls.empty());
  host.move_prop("crate", {0.5, 0.5});
  host.advance(runner);
  CHECK(host.calls == std::vector<std::string>{"remove_prop crate"});
  host.props.push_back({"crate", {0.5, 0.5}});  // back again: once by default
  host.advance(runner);
  CHECK(host.calls.size() == 1);
}

TEST_CASE("a counter trigger fires once when an action makes the counter reach its value", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({
    "counters": { "coins": 0 },
    "triggers": [
      { "when": { "type": "counter", "counter": "coins", "value": 3 }, "do": [ { "action": "message", "text": "three" } ] },
      { "when": { "type": "every", "period": 0.1 }, "do": [ { "action": "counter", "counter": "coins", "add": 1 } ] },
      { "when": { "type": "time", "at": 1.0 }, "do": [ { "action": "counter", "counter": "coins", "set": 3 } ] } ]})");
  FakeScriptHost host;
  runner.update(host);  // tick 0: coins 1
  CHECK(runner.counter("coins") == 1);
  host.advance(runner);
  CHECK(host.calls.empty());
  host.advance(runner);  // tick 2: coins 3, and the counter trigger, though earlier in the file, fires now
  CHECK(runner.counter("coins") == 3);
  CHECK(host.calls == std::vector<std::string>{"message three 3"});
  for (int i = 0; i < 20; ++i) host.advance(runner);  // set back to 3 at tick 10: once
  CHECK(host.calls.size() == 1);
  REQUIRE(runner.counters().size() == 1);
  CHECK(runner.counters()[0].name == "coins");
}

TEST_CASE("counter triggers chain within one tick", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({
    "counters": { "a": 0, "b": 0 },
    "triggers": [
      { "when": { "type": "counter", "counter": "b", "value": 1 }, "do": [ { "action": "win" } ] },
      { "when": { "type": "counter", "counter": "a", "value": 1 }, "do": [ { "action": "counter", "counter": "b", "add": 1 } ] },
      { "when": { "type": "start" }, "do": [ { "action": "counter", "counter": "a", "set": 1 } ] } ]})");
  FakeScriptHost host;
  runner.update(host);
  CHECK(runner.status() == ScriptStatus::won);
}

TEST_CASE("the player's centroid in the goal region wins", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({
    "regions": [ { "name": "finish", "min": [40, 0], "max": [44, 5] } ], "goal": "finish" })");
  FakeScriptHost host;
  const TireId player = host.add_tire({0, 0.5});
  const TireId other = host.add_tire({0, 0.5});
  runner.update(host);
  host.move_tire(other, {42, 1});  // only the player counts
  host.advance(runner);
  CHECK(runner.status() == ScriptStatus::running);
  host.move_tire(player, {42, 1});
  host.advance(runner);
  CHECK(runner.status() == ScriptStatus::won);
  CHECK(std::string(to_string(runner.status())) == "won");
}

TEST_CASE("reaching the time limit while running loses", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({ "time_limit": 2.0 })");
  FakeScriptHost host;
  runner.update(host);
  for (int i = 0; i < 19; ++i) host.advance(runner);
  CHECK(runner.status() == ScriptStatus::running);
  host.advance(runner);  // tick 20: 2.0 s
  CHECK(runner.status() == ScriptStatus::lost);
  CHECK(std::string(to_string(runner.status())) == "lost");
}

TEST_CASE("once won, neither lose nor the time limit changes the status, and the script stops",
          "[unit][script]") {
  ScriptRunner runner = runner_for(R"({
    "time_limit": 1.0,
    "triggers": [
      { "when": { "type": "time", "at": 0.5 }, "do": [ { "action": "win" }, { "action": "lose" },
                                                     { "action": "message", "text": "well done" } ] },
      { "when": { "type": "time", "at": 0.5 }, "do": [ { "action": "lose" } ] },
      { "when": { "type": "every", "period": 0.1 }, "do": [ { "action": "next_level" } ] } ]})");
  FakeScriptHost host;
  runner.update(host);
  for (int i = 0; i < 20; ++i) host.advance(runner);
  CHECK(runner.status() == ScriptStatus::won);
  CHECK(host.calls.back() == "message well done 3");  // the winning trigger's own actions still run
  CHECK(host.count("next_level") == 5);               // ticks 0 to 4; from tick 5 on the script has stopped
}

TEST_CASE("actions run in list order and triggers in file order", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({
    "counters": { "n": 0 },
    "triggers": [
      { "when": { "type": "time", "at": 0.1 }, "do": [ { "action": "message", "text": "second", "seconds": 1 } ] },
      { "when": { "type": "start" },
        "do": [ { "action": "set_gravity", "gravity": [0, -5] },
                { "action": "spawn_tire", "tire": { "position": [1, 2] } },
                { "action": "impulse", "target": "all_tires", "impulse": [2, 0] },
                { "action": "impulse", "target": "crate", "impulse": [0, 3] },
                { "action": "set", "key": "player.max_speed", "value": 20 },
                { "action": "path", "prop": "lift", "command": "stop" },
                { "action": "checkpoint", "position": [7, 1] },
                { "action": "message", "text": "first", "seconds": 1 } ] } ]})");
  FakeScriptHost host;
  runner.update(host);
  host.advance(runner);
  CHECK(host.calls == std::vector<std::string>{"set_gravity 0 -5", "spawn_tire 1 2", "impulse all_tires 2 0",
                                               "impulse crate 0 3", "set player.max_speed 20",
                                               "path lift stop", "checkpoint 7 1", "message first 1",
                                               "message second 1"});
}

TEST_CASE("a tire spawned inside a region enters it", "[unit][script]") {
  ScriptRunner runner = runner_for(R"({
    "regions": [ { "name": "zone", "min": [0, 0], "max": [10, 10] } ],
    "triggers": [
      { "when": { "type": "start" }, "do": [ { "action": "spawn_tire", "tire": { "position": [5, 5] } } ] },
      { "when": { "type": "enter", "region": "zone", "who": "any" }, "do": [ { "action": "next_level" } ] } ]})");
  FakeScriptHost host;
  runner.update(host);
  CHECK(host.calls == std::vector<std::string>{"spawn_tire 5 5", "next_level"});
}

TEST_CASE("the script's hash follows its state", "[unit][script]") {
  const std::string script = R"({
    "regions": [ { "name": "zone", "min": [0, 0], "max": [10, 10] } ],
    "counters": { "n": 0 },
    "triggers": [
      { "when": { "type": "every", "period": 0.5 }, "do": [ { "action": "counter", "counter": "n", "add": 1 } ] },
      { "when": { "type": "enter", "region": "zone", "who": "any" }, "do": [] } ]})";
  ScriptRunner a = runner_for(script);
  ScriptRunner b = runner_for(script);
  FakeScriptHost host_a, host_b;
  host_a.add_tire({-1, 1});
  host_b.add_tire({-1, 1});
  CHECK(hash_of(a) == hash_of(b));
  a.update(host_a);
  CHECK(hash_of(a) != hash_of(b));  // the every trigger fired and the counter moved
  b.update(host_b);
  CHECK(hash_of(a) == hash_of(b));
  for (int i = 0; i < 3; ++i) host_a.advance(a), host_b.advance(b);
  CHECK(hash_of(a) == hash_of(b));
  const std::uint64_t before = hash_of(a);
  host_a.move_tire(host_a.tires[0].id, {1, 1});  // occupancy alone changes the hash
  host_a.now = 4;
  a.update(host_a);
  CHECK(hash_of(a) != before);
  host_b.now = 4;
  b.update(host_b);
  CHECK(hash_of(a) != hash_of(b));
}

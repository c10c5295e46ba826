// Level scripts running in a LevelSession: its script host does what SCRIPTING.md promises.
#include <catch2/catch.hpp>

#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {
LevelSession load(const std::string& text) {
  LevelLoad l = load_level_text(text, "script.json");
  if (!l.level) throw std::runtime_error(l.errors.front());
  return std::move(*make_session(*l.level));
}
const char* kBase = R"({
  "name": "scripted",
  "tires": [ { "position": [0, 0.5] } ],
  "obstacles": [ { "min": [-50, -1], "max": [50, 0] } ],
  "props": [ { "name": "crate", "shape": "box", "type": "dynamic", "size": [0.5, 0.5], "position": [-5, 0.25] },
             { "name": "lift", "shape": "box", "type": "kinematic", "size": [1, 0.2], "position": [-10, 1],
               "path": { "waypoints": [[-10, 1], [-10, 5]], "speed": 1, "running": false } } ],
  "regions": [ { "name": "finish", "min": [5, 0], "max": [7, 3] } ],
  "goal": "finish",)";
}  // namespace

TEST_CASE("start actions run before the first step, and the goal wins", "[unit][script][world]") {
  LevelSession session = load(std::string(kBase) + R"(
    "triggers": [ { "when": { "type": "start" }, "do": [
      { "action": "spawn_tire", "tire": { "position": [-2, 3] } },
      { "action": "message", "text": "Go right", "seconds": 1 },
      { "action": "set", "key": "player.max_speed", "value": 4 } ] } ] })");
  World& world = session.world();
  CHECK(world.tires().size() == 2);  // spawned at tick 0
  REQUIRE(session.messages().size() == 1);
  CHECK(session.messages().front().text == "Go right");
  CHECK(world.player()->spec.max_speed == 4);
  run(session, 61);
  CHECK(session.messages().empty());  // shown for 1 s
  CHECK(session.status() == ScriptStatus::running);
  for (int i = 0; i < 600 && session.status() == ScriptStatus::running; ++i) session.step({1.0, false});
  CHECK(session.status() == ScriptStatus::won);
  CHECK(std::abs(world.player()->velocity().x) <= 4.0 + 1e-9);
}

TEST_CASE("the time limit loses and actions reach props, gravity and paths", "[unit][script][world]") {
  LevelSession session = load(std::string(kBase) + R"(
    "time_limit": 2,
    "triggers": [ { "when": { "type": "time", "at": 0.5 }, "do": [
      { "action": "impulse", "target": "crate", "impulse": [0, 50] },
      { "action": "path", "prop": "lift", "command": "start" },
      { "action": "set_gravity", "gravity": [0, -5] } ] } ] })");
  World& world = session.world();
  run(session, 60);
  CHECK(world.gravity().y == -5);
  const auto crate = *world.rigid().find_prop("crate");
  CHECK(world.rigid().current_pose(crate).position.y > 0.5);  // thrown up
  const auto lift = *world.rigid().find_prop("lift");
  CHECK(world.rigid().current_pose(lift).position.y > 1.2);  // started moving
  run(session, 60);
  CHECK(session.status() == ScriptStatus::lost);
}

TEST_CASE("the script's state is part of the hash", "[unit][script][world]") {
  const std::string level = std::string(kBase) + R"(
    "counters": { "hits": 0 },
    "triggers": [ { "when": { "type": "every", "period": 0.5 }, "do": [ { "action": "counter", "counter": "hits", "add": 1 } ] } ] })";
  LevelSession a = load(level), b = load(level);
  run(a, 100);
  run(b, 100);
  CHECK(a.state_hash() == b.state_hash());
  CHECK(a.script()->counter("hits") == 4);
}

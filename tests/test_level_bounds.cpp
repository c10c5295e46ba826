// A level's bounds (levels/README.md "bounds", tire/io/level_bounds.h): the box computed from the
// level's geometry when the level names none, the one it names, how LevelSession ends a level (or
// puts the player back) when the player leaves it, and the validator's messages.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "error_messages.h"
#include "tire_fixtures.h"

using tire_test::has;
using tire_test::joined;

using namespace tire;
using namespace tire::test;

namespace {

// A shelf over nothing, 10 m wide, its top at y = 0; the tire at its middle.
const std::string kLedge = R"({
  "name": "ledge",
  "tires": [ { "position": [0, 0.5] } ],
  "obstacles": [ { "min": [-5, -1], "max": [5, 0] } ])";

Level level_of(const std::string& text) {
  LevelLoad l = load_level_text(text, "bounds.json");
  INFO(joined(l.errors));
  REQUIRE(l.level);
  return *l.level;
}

std::vector<std::string> errors_of(const std::string& text) { return load_level_text(text, "b.json").errors; }

// Steps until the level ends or `ticks` have run; returns the ticks run.
int run_until_over(LevelSession& session, int ticks, TickInput input) {
  int n = 0;
  while (n < ticks && session.status() == ScriptStatus::running) {
    session.step(input);
    ++n;
  }
  return n;
}

}  // namespace

TEST_CASE("bounds: computed from the geometry, margin below and beside it, open above", "[unit][bounds]") {
  const Level level = level_of(kLedge + "}");
  const LevelBounds& b = level.bounds;
  CHECK_FALSE(b.min);
  CHECK_FALSE(b.max);
  CHECK(b.margin == 10.0);
  // The obstacle spans [-5, 5] x [-1, 0]; the tire [-0.5, 0.5] x [0, 1].
  CHECK(b.box.min.x == -15.0);
  CHECK(b.box.min.y == -11.0);
  CHECK(b.box.max.x == 15.0);
  CHECK(std::isinf(b.box.max.y));
  CHECK(b.contains({0, 1000}));
  CHECK_FALSE(b.contains({0, -11.5}));
  CHECK_FALSE(b.contains({15.5, 0}));

  // What the script places counts too: a spawned tire, a spawned prop, a checkpoint; and regions.
  const Level scripted = level_of(kLedge + R"(,
    "regions": [ { "name": "deep", "min": [-2, -30], "max": [2, -20] } ],
    "triggers": [ { "when": { "type": "start" }, "do": [
      { "action": "spawn_tire", "tire": { "position": [40, 5], "outer_radius": 1, "inner_radius": 0.5 } },
      { "action": "spawn_prop", "prop": { "shape": "circle", "radius": 2, "position": [-40, 0] } },
      { "action": "checkpoint", "position": [0, 60] } ] } ] })");
  const Aabb extent = level_extent(scripted);
  CHECK(extent.min.x == -42.0);
  CHECK(extent.max.x == 41.0);
  CHECK(extent.min.y == -30.0);
  CHECK(extent.max.y == 60.0);
  CHECK(scripted.bounds.box.min.x == -52.0);
  CHECK(scripted.bounds.box.min.y == -40.0);
  CHECK(scripted.bounds.box.max.x == 51.0);

  // A kinematic prop along its path, a rotated box by its corners, a chain with its thickness.
  const Level props = level_of(R"({ "name": "p", "props": [
    { "shape": "box", "type": "kinematic", "size": [2, 2], "position": [0, 0],
      "path": { "waypoints": [[0, 0], [0, -50]] } },
    { "shape": "box", "size": [2, 2], "position": [20, 0], "angle": 0.7853981633974483 },
    { "shape": "chain", "points": [[-30, 0], [-20, 0]], "thickness": 0.5 } ] })");
  const Aabb e = level_extent(props);
  CHECK(e.min.y == Approx(-50.0 - std::sqrt(2.0)));
  CHECK(e.max.x == Approx(20.0 + std::sqrt(2.0)));
  CHECK(e.min.x == -30.5);
}

TEST_CASE("bounds: a level names its corners and its margin", "[unit][bounds]") {
  const Level named = level_of(kLedge + R"(, "bounds": { "min": [-8, -4], "max": [30, 20] } })");
  CHECK(named.bounds.box.min == Vec2{-8, -4});
  CHECK(named.bounds.box.max == Vec2{30, 20});
  const Level margin = level_of(kLedge + R"(, "bounds": { "margin": 2 } })");
  CHECK(margin.bounds.box.min == Vec2{-7, -3});
  CHECK(margin.bounds.box.max.x == 7.0);
  // One corner named, the other computed.
  const Level top = level_of(kLedge + R"(, "bounds": { "max": [6, 5] } })");
  CHECK(top.bounds.box.min == Vec2{-15, -11});
  CHECK(top.bounds.box.max == Vec2{6, 5});
}

TEST_CASE("bounds: a tire driven off a ledge into nothing loses the level within seconds",
          "[unit][bounds][session]") {
  // No bounds named: the computed ones, 10 m under the shelf.
  const Level level = level_of(kLedge + "}");
  const std::unique_ptr<LevelSession> session = make_session(level);
  const int ticks = run_until_over(*session, 600, {1.0, false});
  CHECK(session->status() == ScriptStatus::lost);
  CHECK(session->end_reason() == EndReason::out_of_bounds);
  REQUIRE(session->end_tick());
  CHECK(*session->end_tick() == static_cast<std::uint64_t>(ticks));
  // 5 m to the edge, then a fall of at most 11.5 m (1.5 s) or a flight past the side: well within
  // five seconds.
  CHECK(ticks < 300);
  const Vec2 c = session->world().player()->centroid();
  CHECK((c.y < -11.0 || c.x > 15.0));
  CHECK(c.y < 0.0);
  CHECK(session->respawns() == 0);
  // It stays lost, and the world goes on.
  run(*session, 30);
  CHECK(session->status() == ScriptStatus::lost);
  CHECK(session->end_tick() == static_cast<std::uint64_t>(ticks));
  // Standing still, it never leaves.
  const std::unique_ptr<LevelSession> still = make_session(level);
  run(*still, 300);
  CHECK(still->status() == ScriptStatus::running);
  CHECK_FALSE(still->end_tick());
}

TEST_CASE("bounds: leaving them ends the level the same way every run, in the hash",
          "[unit][bounds][session]") {
  const Level level = level_of(kLedge + "}");
  const auto a = make_session(level), b = make_session(level), c = make_session(level);
  run(*a, 240, {1.0, false});
  run(*b, 240, {1.0, false});
  CHECK(a->state_hash() == b->state_hash());
  // The same world with unbounded sides: the physics is identical, the ending is not.
  const Level wide = level_of(kLedge + R"(, "bounds": { "min": [-1000, -1000], "max": [1000, 1000] } })");
  const auto d = make_session(wide);
  run(*d, 240, {1.0, false});
  CHECK(a->status() == ScriptStatus::lost);
  CHECK(d->status() == ScriptStatus::running);
  CHECK(a->state_hash() != d->state_hash());
  // While neither has ended, the bounds add nothing to the digest.
  run(*c, 60, {1.0, false});
  const auto e = make_session(wide);
  run(*e, 60, {1.0, false});
  CHECK(c->state_hash() == e->state_hash());
}

TEST_CASE("bounds: in a level with checkpoints, leaving them puts the player back",
          "[unit][bounds][session]") {
  const Level level = level_of(kLedge + R"(,
    "triggers": [ { "when": { "type": "time", "at": 0.2 }, "do": [ { "action": "checkpoint", "position": [-2, 0.5] } ] } ] })");
  const std::unique_ptr<LevelSession> session = make_session(level);
  CHECK(session->respawns_out_of_bounds());
  int first = 0;
  for (int i = 0; i < 600 && session->respawns() == 0; ++i, ++first) session->step({1.0, false});
  CHECK(session->respawns() == 1);
  CHECK(first < 300);
  CHECK(session->status() == ScriptStatus::running);
  // Back at the checkpoint, at rest.
  const Tire& player = *session->world().player();
  CHECK(player.centroid().x == Approx(-2.0).margin(1e-6));
  CHECK(player.centroid().y == Approx(0.5).margin(0.05));
  CHECK(length(player.velocity()) < 1e-9);
  // And again, each time it falls.
  run(*session, 600, {1.0, false});
  CHECK(session->respawns() >= 2);
  CHECK(session->status() == ScriptStatus::running);
}

TEST_CASE("bounds: a named top, and the script's own endings named", "[unit][bounds][session]") {
  // A jump through a low ceiling of bounds loses.
  const Level low = level_of(kLedge + R"(, "bounds": { "max": [15, 1.2] } })");
  const auto session = make_session(low);
  run(*session, 30);
  session->step({0.0, true});
  run_until_over(*session, 120, {});
  CHECK(session->end_reason() == EndReason::out_of_bounds);
  // The time limit, the goal, a lose action.
  const auto timed = make_session(level_of(kLedge + R"(, "time_limit": 1 })"));
  CHECK(run_until_over(*timed, 600, {}) == 60);
  CHECK(timed->status() == ScriptStatus::lost);
  CHECK(timed->end_reason() == EndReason::time_limit);
  CHECK(timed->end_tick() == std::uint64_t{60});
  const auto goal = make_session(level_of(kLedge + R"(,
    "regions": [ { "name": "flag", "min": [2, 0], "max": [4, 2] } ], "goal": "flag" })"));
  run_until_over(*goal, 600, {1.0, false});
  CHECK(goal->status() == ScriptStatus::won);
  CHECK(goal->end_reason() == EndReason::goal);
  const auto lose = make_session(level_of(kLedge + R"(,
    "triggers": [ { "when": { "type": "time", "at": 0.5 }, "do": [ { "action": "lose" } ] } ] })"));
  run_until_over(*lose, 600, {});
  CHECK(lose->end_reason() == EndReason::lose_action);
  CHECK(std::string(to_string(EndReason::out_of_bounds)) == "out_of_bounds");
}

TEST_CASE("bounds: the validator names the file, the path and what was expected", "[unit][bounds][level]") {
  const auto check = [](const std::string& tail, const std::string& expected) {
    const auto errors = errors_of(kLedge + ", " + tail + " }");
    INFO(tail << "\n" << joined(errors));
    CHECK(has(errors, expected));
  };
  check(R"("bounds": { "min": [10, 0], "max": [0, 20] })",
        "b.json: /bounds/max: must be greater than min on both axes, got [0,20] with min [10,0]");
  check(R"("bounds": { "min": [1, 0] })",
        "b.json: /bounds/min: must be below and left of the player's start [0,0.5] (/tires/0/position), got "
        "[1,0]");
  check(R"("bounds": { "max": [10, 0.25] })",
        "b.json: /bounds/max: must be above and right of the player's start [0,0.5] (/tires/0/position), got "
        "[10,0.25]");
  check(R"("bounds": { "min": [-9, -9], "max": [9, 9], "margin": 3 })",
        "b.json: /bounds/margin: has no effect when min and max are both given");
  check(R"("bounds": { "margin": -1 })", "b.json: /bounds/margin: must be a number in [0, 1000] m, got -1");
  check(R"("bounds": { "min": [0] })", "b.json: /bounds/min: must be [x, y]");
  check(R"("bounds": { "mni": [0, 0] })", "b.json: /bounds/mni: unknown key");
  check(R"("bounds": [0, 0])", "b.json: /bounds: must be an object");
  // Without a player to be inside, a corner is still checked against the computed one.
  const auto no_player = errors_of(R"({ "name": "n", "obstacles": [ { "min": [-5, -1], "max": [5, 0] } ],
    "bounds": { "min": [20, 0] } })");
  INFO(joined(no_player));
  CHECK(has(no_player, "b.json: /bounds/min: must be left of the computed right side x = 15"));
  const auto no_player_max = errors_of(R"({ "name": "n", "obstacles": [ { "min": [-5, -1], "max": [5, 0] } ],
    "bounds": { "max": [-20, 0] } })");
  INFO(joined(no_player_max));
  CHECK(has(no_player_max, "b.json: /bounds/max: must be above and right of the computed lower-left corner"));
}

// Run-time budgets (issue 34, run_budgets.h): what scripts, replays and the player add while a
// level runs is bounded, the excess dropped the same way every run, each budget reported once.
// The floods are the hostile audit's, each run for 600 ticks; work is bounded by the budgets'
// counts, never timed.
#include <catch2/catch.hpp>
#include <string>

#include "tire/io/level.h"
#include "tire/session/level_session.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {

std::unique_ptr<LevelSession> session_of(const std::string& text) {
  LevelLoad load = load_level_text(text, "budgets.json");
  INFO((load.errors.empty() ? std::string() : load.errors.front()));
  REQUIRE(load.level);
  return make_session(*load.level);
}

std::vector<std::string> errors_of(const std::string& text) { return load_level_text(text, "b.json").errors; }

const World::BudgetReached* reached(const World& world, ParamId budget) {
  for (const World::BudgetReached& b : world.budgets_reached())
    if (b.budget == budget) return &b;
  return nullptr;
}

std::string repeat(const std::string& item, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += (i ? "," : "") + item;
  return out;
}

// Ground under a 20 m box, so that what is spawned stays near.
const std::string kGround =
    R"("obstacles": [{"min": [-10, -1], "max": [10, 0]}, {"min": [-11, -1], "max": [-10, 20]},
                                  {"min": [10, -1], "max": [11, 20]}])";

}  // namespace

TEST_CASE("budgets: a trigger that spawns every tick stops at the level's live tires", "[unit][budgets]") {
  const auto session = session_of(R"({"name": "flood", )" + kGround + R"(, "budgets": {"tires": 40},
    "triggers": [{"when": {"type": "every", "period": 0.001},
                  "do": [{"action": "spawn_tire", "tire": {"position": [0, 5], "segments": 8}}]}]})");
  for (int tick = 0; tick < 600; ++tick) session->step({});
  const World& world = session->world();
  CHECK(world.tires().size() == 40);
  const World::BudgetReached* b = reached(world, ParamId::budget_tires);
  REQUIRE(b != nullptr);
  // One spawn a tick: at load (tick 0) and after each of the 600 steps; the 41st was the first dropped.
  CHECK(b->first_tick == 40);
  CHECK(b->dropped == 601 - 40);
}

TEST_CASE("budgets: no tick adds more than spawns_per_tick, whoever adds", "[unit][budgets]") {
  const auto session = session_of(R"({"name": "clicks", )" + kGround + "}");
  World& world = session->world();
  int added = 0;
  for (int i = 0; i < 20; ++i) {
    TireSpec spec = tire_at({-8.0 + 0.8 * i, 3});
    spec.segments = 8;
    added += world.spawn_tire(spec).has_value();
  }
  CHECK(added == 16);
  session->step({});
  TireSpec spec = tire_at({0, 8});
  CHECK(world.spawn_tire(spec).has_value());  // a new tick, a new allowance
  const World::BudgetReached* b = reached(world, ParamId::budget_spawns_per_tick);
  REQUIRE(b != nullptr);
  CHECK(b->dropped == 4);
  // Reported once, however much it drops.
  int lines = 0;
  for (const std::string& w : world.warnings())
    lines += w.starts_with("budgets.spawns_per_tick (16) reached");
  CHECK(lines == 1);
}

TEST_CASE("budgets: a trigger whose spawns land in its own region does not multiply without end",
          "[unit][budgets]") {
  // Each tire entering the region fires once and spawns another inside it: doubling every tick.
  const auto session = session_of(R"({"name": "feedback", )" + kGround + R"(, "budgets": {"tires": 200},
    "regions": [{"name": "nest", "min": [-9, 0], "max": [9, 12]}],
    "tires": [{"position": [0, 1]}],
    "triggers": [{"when": {"type": "enter", "region": "nest", "who": "any"},
                  "do": [{"action": "spawn_tire", "tire": {"position": [0, 6], "segments": 8}},
                         {"action": "spawn_tire", "tire": {"position": [3, 6], "segments": 8}}]}]})");
  for (int tick = 0; tick < 600; ++tick) session->step({});
  const World& world = session->world();
  CHECK(world.tires().size() <= 200);
  CHECK(reached(world, ParamId::budget_tires) != nullptr);
}

TEST_CASE("budgets: a flood of messages keeps at most the budgets on screen", "[unit][budgets]") {
  const std::string message =
      R"({"action": "message", "text": ")" + std::string(500, 'x') + R"(", "seconds": 60})";
  const auto session = session_of(R"({"name": "shouting", "tires": [{"position": [0, 1]}],
    "triggers": [{"when": {"type": "every", "period": 0.001}, "do": [)" +
                                  repeat(message, 10) + "]}]}");
  std::size_t most = 0, most_bytes = 0;
  for (int tick = 0; tick < 600; ++tick) {
    session->step({});
    std::size_t bytes = 0;
    for (const ScriptMessage& m : session->messages()) bytes += m.text.size();
    most = std::max(most, session->messages().size());
    most_bytes = std::max(most_bytes, bytes);
  }
  CHECK(most == 16);
  CHECK(most_bytes <= 8192);
  CHECK(reached(session->world(), ParamId::budget_messages) != nullptr);
  CHECK(reached(session->world(), ParamId::budget_message_bytes) == nullptr);  // 16 × 500 bytes fit
}

TEST_CASE("budgets: the text of the messages on screen together is bounded", "[unit][budgets]") {
  const std::string message =
      R"({"action": "message", "text": ")" + std::string(400, 'y') + R"(", "seconds": 60})";
  // On the ground: a tire falling for ten seconds would leave the level's bounds and end it.
  const auto session = session_of(R"({"name": "long", "tires": [{"position": [0, 1]}], )" + kGround + R"(,
    "budgets": {"message_bytes": 1000},
    "triggers": [{"when": {"type": "every", "period": 1}, "do": [)" +
                                  message + "]}]}");
  for (int tick = 0; tick < 600; ++tick) session->step({});
  CHECK(session->messages().size() == 2);  // 800 bytes; a third would pass 1000
  const World::BudgetReached* b = reached(session->world(), ParamId::budget_message_bytes);
  REQUIRE(b != nullptr);
  CHECK(b->first_tick == 120);
}

TEST_CASE("budgets: trigger firings in one tick", "[unit][budgets]") {
  const std::string trigger =
      R"({"when": {"type": "start"}, "do": [{"action": "counter", "counter": "c", "add": 1}]})";
  const auto session =
      session_of(R"({"name": "many", "tires": [{"position": [0, 1]}], "budgets": {"firings_per_tick": 100},
    "counters": {"c": 0}, "triggers": [)" +
                 repeat(trigger, 150) + "]}");
  const World::BudgetReached* b = reached(session->world(), ParamId::budget_firings_per_tick);
  REQUIRE(b != nullptr);
  CHECK(b->first_tick == 0);
  CHECK(b->dropped == 50);
}

TEST_CASE("budgets: the same drops every run, so a replay of a flood matches",
          "[unit][budgets][determinism]") {
  const std::string level =
      R"({"name": "flood", )" + kGround + R"(, "budgets": {"tires": 30, "spawns_per_tick": 3},
    "triggers": [{"when": {"type": "every", "period": 0.001},
                  "do": [)" +
      repeat(R"({"action": "spawn_tire", "tire": {"position": [0, 5], "segments": 8}})", 3) + "]}]}";
  const auto a = session_of(level), b = session_of(level);
  for (int tick = 0; tick < 300; ++tick) {
    a->step({});
    b->step({});
  }
  CHECK(a->world().tires().size() == 30);
  CHECK(a->state_hash() == b->state_hash());
}

TEST_CASE("budgets: a level may lower them, never raise them, and the validator counts a firing",
          "[unit][budgets]") {
  CHECK(errors_of(R"({"name": "x", "budgets": {"tires": 10001}})") ==
        std::vector<std::string>{"b.json: /budgets/tires: must be an integer in [1, 10000], got 10001"});
  CHECK(errors_of(R"({"name": "x", "budgets": {"spawns_per_tick": 17}})") ==
        std::vector<std::string>{"b.json: /budgets/spawns_per_tick: must be an integer in [0, 16], got 17"});
  CHECK(errors_of(R"({"name": "x", "budgets": {"tirs": 3}})")
            .front()
            .starts_with("b.json: /budgets/tirs: unknown key"));
  // The level's own tires against its own budget.
  CHECK(
      errors_of(
          R"({"name": "x", "budgets": {"tires": 1}, "tires": [{"position": [0, 1]}, {"position": [3, 1]}]})") ==
      std::vector<std::string>{"b.json: /tires/1: the level's own tires are more than budgets.tires (1)"});
  // One firing that alone passes a budget of a tick.
  const std::string spawn = R"({"action": "spawn_tire", "tire": {"position": [0, 5]}})";
  CHECK(errors_of(R"({"name": "x", "budgets": {"spawns_per_tick": 2},
    "triggers": [{"when": {"type": "start"}, "do": [)" +
                  repeat(spawn, 3) + "]}]}") ==
        std::vector<std::string>{
            "b.json: /triggers/0/do: one firing adds 3 tires and props, more than "
            "budgets.spawns_per_tick (2) allows: the rest would be dropped every time it fires"});
  const std::string message = R"({"action": "message", "text": "hello"})";
  CHECK(errors_of(R"({"name": "x", "budgets": {"messages": 1},
    "triggers": [{"when": {"type": "start"}, "do": [)" +
                  repeat(message, 2) + "]}]}") ==
        std::vector<std::string>{
            "b.json: /triggers/0/do: one firing adds 2 messages, more than budgets.messages "
            "(1) allows: the rest would be dropped every time it fires"});
}

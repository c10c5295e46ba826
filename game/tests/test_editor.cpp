// The level editor's model without a window: open and save (every shipped level round-trips to
// the same simulation), the key order and layout of what it writes, the undo history, changes the
// validator refuses, picking, and the edits the mouse makes.
#define CATCH_CONFIG_MAIN
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "editor/level_document.h"
#include "editor/level_edits.h"
#include "editor/level_format.h"
#include "tire/io/level.h"
#include "tire/io/level_format.h"
#include "tire/session/level_session.h"
#include "tire/world/world.h"

using namespace editor;
namespace fs = std::filesystem;

namespace {

// A folder of this process's own: ctest runs the test cases side by side, each in its process, and
// with one shared folder one case read crate.json while another was writing it.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("tire-editor-tests-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

// The state hash after `ticks` ticks of the level in `file`, with no input.
std::uint64_t hash_after(const fs::path& file, int ticks) {
  const tire::LevelLoad load = tire::load_level_file(file);
  REQUIRE(load.errors.empty());
  auto session = tire::make_session(*load.level);
  for (int i = 0; i < ticks; ++i) session->step({});
  return session->state_hash();
}

constexpr const char* kCrateLevel = R"({
  "name": "Crate",
  "tires": [ { "position": [0, 0.5] } ],
  "obstacles": [ { "min": [-10, -1], "max": [10, 0] } ],
  "props": [ { "name": "crate", "shape": "box", "type": "dynamic", "size": [1, 1], "position": [3, 0.5] } ],
  "regions": [ { "name": "flag", "min": [8, 0], "max": [10, 2] } ],
  "goal": "flag"
})";

LevelDocument crate_document() {
  const fs::path file = scratch("crate.json");
  write(file, kCrateLevel);
  LevelDocument doc;
  REQUIRE(doc.open(file).empty());
  REQUIRE(doc.errors().empty());
  return doc;
}

Vec2 crate_position(const LevelDocument& doc) { return vec2_at(doc.json()["props"][0], "position", {}); }

}  // namespace

TEST_CASE("every shipped level opened and saved unchanged validates and steps to the same state hash",
          "[unit][editor]") {
  int levels = 0;
  for (const auto& entry : fs::directory_iterator(TIRE_LEVELS_DIR)) {
    if (entry.path().extension() != ".json" || entry.path().filename() == "schema.json") continue;
    INFO(entry.path());
    const fs::path copy = scratch(entry.path().filename().string());
    fs::copy_file(entry.path(), copy, fs::copy_options::overwrite_existing);
    LevelDocument doc;
    REQUIRE(doc.open(copy).empty());
    REQUIRE(doc.errors().empty());
    REQUIRE_FALSE(doc.modified());
    REQUIRE(doc.save().empty());
    CHECK(tire::load_level_file(copy).errors.empty());
    CHECK(hash_after(copy, 300) == hash_after(entry.path(), 300));
    // Saving what was saved changes nothing.
    const std::string once = read(copy);
    LevelDocument again;
    REQUIRE(again.open(copy).empty());
    REQUIRE(again.save().empty());
    CHECK(read(copy) == once);
    ++levels;
  }
  CHECK(levels >= 8);
}

TEST_CASE("a saved level has its keys in reference order, two-space indents and its script as written",
          "[unit][editor]") {
  const fs::path file = scratch("order.json");
  write(file, R"({"triggers": [{"do": [{"text": "hi", "action": "message"}], "when": {"type": "start"}}],
    "props": [{"density": 2, "position": [1, 2], "shape": "box", "size": [1, 1], "type": "dynamic", "name": "c"}],
    "tires": [{"mass": 10.0, "position": [0, 0.5]}], "name": "Order", "$schema": "schema.json"})");
  LevelDocument doc;
  REQUIRE(doc.open(file).empty());
  REQUIRE(doc.save().empty());
  const std::string text = read(file);
  // Root keys in the table's order; a prop's keys in its order; the trigger's keys as they came.
  const auto at = [&](const std::string& s) { return text.find(s); };
  CHECK(at("\"$schema\"") < at("\"name\""));
  CHECK(at("\"name\"") < at("\"tires\""));
  CHECK(at("\"tires\"") < at("\"props\""));
  CHECK(at("\"props\"") < at("\"triggers\""));
  CHECK(at("\"name\": \"c\"") < at("\"shape\": \"box\""));
  CHECK(at("\"shape\": \"box\"") < at("\"position\": [1, 2]"));
  CHECK(at("\"size\"") < at("\"density\""));
  CHECK(at("\"do\"") < at("\"when\""));
  CHECK(at("\"text\": \"hi\"") < at("\"action\": \"message\""));
  CHECK(text.starts_with("{\n  \"$schema\""));
  CHECK(at("\"mass\": 10.0") != std::string::npos);  // a number as written, shortest round trip
  // The table's order is the one the writer used for every object.
  for (const tire::LevelKey& key : tire::level_keys(tire::LevelObject::root)) CHECK_FALSE(key.key.empty());
}

TEST_CASE("moving a crate is one step of the history: undo puts it back, redo moves it again",
          "[unit][editor]") {
  LevelDocument doc = crate_document();
  const Selection crate{{ItemKind::prop, 0}};
  REQUIRE(doc.change(moved(doc.json(), crate, {2.5, 0})).empty());
  CHECK(crate_position(doc) == Vec2{5.5, 0.5});
  CHECK(doc.modified());
  REQUIRE(doc.undo());
  CHECK(crate_position(doc) == Vec2{3, 0.5});
  CHECK_FALSE(doc.modified());
  REQUIRE(doc.redo());
  CHECK(crate_position(doc) == Vec2{5.5, 0.5});
  CHECK_FALSE(doc.redo());
  // Unbounded: a thousand nudges, all undone.
  for (int i = 0; i < 1000; ++i) REQUIRE(doc.change(moved(doc.json(), crate, {0.001, 0})).empty());
  CHECK(doc.history_size() == 1001);
  while (doc.undo()) {
  }
  CHECK(crate_position(doc) == Vec2{3, 0.5});
}

TEST_CASE("a drag shows every step and becomes one history step, and a refused one puts the level back",
          "[unit][editor]") {
  LevelDocument doc = crate_document();
  const Json start = doc.json();
  const Selection crate{{ItemKind::prop, 0}};
  doc.begin_gesture();
  for (int i = 1; i <= 10; ++i) {
    doc.preview(moved(start, crate, {0.1 * i, 0}));
    CHECK(crate_position(doc).x == Approx(3 + 0.1 * i));
  }
  CHECK(doc.end_gesture().empty());
  CHECK(doc.history_size() == 1);
  CHECK(crate_position(doc) == Vec2{4, 0.5});  // 3 + 10 × 0.1, written tidy

  // A box corner dragged past the opposite one makes a box of no width: refused, put back.
  const Json before = doc.json();
  doc.begin_gesture();
  doc.preview(with_corner(before, {ItemKind::obstacle, 0}, 2, {-10, 5}));
  CHECK_FALSE(doc.errors().empty());
  const std::string refusal = doc.end_gesture();
  CHECK_THAT(refusal, Catch::Contains("/obstacles/0/max"));
  CHECK(doc.json() == before);
  CHECK(doc.errors().empty());
}

TEST_CASE("a value the validator refuses is not set, and the validator's message says why",
          "[unit][editor]") {
  LevelDocument doc = crate_document();
  Json next = doc.json();
  next["props"][0]["density"] = -1;
  const std::string e = doc.change(next);
  CHECK_THAT(e, Catch::Contains("/props/0/density"));
  CHECK_THAT(e, Catch::Contains("(0, 100000]"));
  CHECK_FALSE(doc.json()["props"][0].contains("density"));
  // Deleting the goal region while the goal names it is refused too.
  CHECK_THAT(doc.change(removed(doc.json(), {{ItemKind::region, 0}})), Catch::Contains("/goal"));
  CHECK(count(doc.json(), ItemKind::region) == 1);
  CHECK(doc.history_size() == 0);
}

TEST_CASE("a save writes only a level that validates, atomically", "[unit][editor]") {
  LevelDocument doc = crate_document();
  const std::string on_disk = read(doc.file());
  doc.begin_gesture();
  doc.preview(with_corner(doc.json(), {ItemKind::obstacle, 0}, 2, {-10, 5}));
  CHECK_FALSE(doc.save().empty());
  doc.cancel_gesture();
  CHECK(read(doc.file()) == on_disk);
  REQUIRE(doc.change(moved(doc.json(), {{ItemKind::prop, 0}}, {1, 0})).empty());
  CHECK(doc.save().empty());
  CHECK_FALSE(doc.modified());
  CHECK(tire::load_level_file(doc.file()).level->props[0].position.x == 4.0);
  CHECK_FALSE(fs::exists(doc.file().string() + ".tmp"));
}

TEST_CASE("a missing file opens as a new level named after it, built and saved", "[unit][editor]") {
  const fs::path file = scratch("brand-new.json");
  fs::remove(file);
  LevelDocument doc;
  REQUIRE(doc.open(file).empty());
  CHECK(doc.json()["name"] == "brand-new");
  CHECK(doc.errors().empty());
  CHECK(doc.modified());  // not on disk yet
  Pick added;
  REQUIRE(doc.change(with_item(doc.json(), ItemKind::obstacle,
                               {{"min", vec2({-5, -1})}, {"max", vec2({5, 0})}}, added))
              .empty());
  REQUIRE(doc.change(with_item(doc.json(), ItemKind::tire, {{"position", vec2({-4, 0.5})}}, added)).empty());
  REQUIRE(doc.change(with_item(doc.json(), ItemKind::region,
                               {{"name", "goal"}, {"min", vec2({3, 0})}, {"max", vec2({5, 2})}}, added))
              .empty());
  Json with_goal = doc.json();
  with_goal["goal"] = "goal";
  REQUIRE(doc.change(with_goal).empty());
  REQUIRE(doc.save().empty());
  const tire::LevelLoad load = tire::load_level_file(file);
  REQUIRE(load.level);
  CHECK(load.level->tires.size() == 1);
  CHECK(load.level->script.goal.has_value());
}

TEST_CASE("picking finds the topmost item under the point, and the points of chains", "[unit][editor]") {
  LevelDocument doc = crate_document();
  CHECK(pick_item(doc.json(), {0, 0.5}, 0.01) == Pick{ItemKind::tire, 0});
  CHECK(pick_item(doc.json(), {3.2, 0.8}, 0.01) == Pick{ItemKind::prop, 0});
  CHECK(pick_item(doc.json(), {9, 1}, 0.01) == Pick{ItemKind::region, 0});
  CHECK(pick_item(doc.json(), {-5, -0.5}, 0.01) == Pick{ItemKind::obstacle, 0});
  CHECK_FALSE(pick_item(doc.json(), {-5, 5}, 0.01));
  // A chain is picked near its line only.
  Pick chain;
  Json j = with_item(
      doc.json(), ItemKind::prop,
      {{"shape", "chain"}, {"position", vec2({0, 3})}, {"points", Json::array({vec2({0, 0}), vec2({4, 0})})}},
      chain);
  CHECK(pick_item(j, {2, 3.05}, 0.1) == chain);
  CHECK_FALSE(pick_item(j, {2, 3.5}, 0.1));
  // Its points, and a path's waypoints, are picked on their own.
  CHECK(pick_point(j, {4.05, 3}, 0.1) == Pick{ItemKind::prop, chain.index, PointSet::points, 1});
  CHECK_FALSE(pick_point(j, {2, 3}, 0.1));
  Pick w;
  j = with_waypoint(j, {ItemKind::prop, 0}, {6, 0.5}, w);
  CHECK(pick_point(j, {6, 0.55}, 0.1) == w);
  // Box selection takes what lies wholly inside.
  CHECK(items_inside(doc.json(), {{2, 0}, {4, 1.5}}) == Selection{{ItemKind::prop, 0}});
}

TEST_CASE("duplicates get fresh names and no second player, and points are deleted and inserted",
          "[unit][editor]") {
  LevelDocument doc = crate_document();
  Selection copies;
  Json j = duplicated(doc.json(), {{ItemKind::prop, 0}, {ItemKind::tire, 0}}, {0, 2}, copies);
  CHECK(copies == Selection{{ItemKind::prop, 1}, {ItemKind::tire, 1}});  // sorted: props before tires
  CHECK(j["props"][1]["name"] == "crate2");
  CHECK(vec2_at(j["props"][1], "position", {}) == Vec2{3, 2.5});
  REQUIRE(doc.change(j).empty());
  j = duplicated(doc.json(), {{ItemKind::prop, 1}}, {0, 2}, copies);
  CHECK(j["props"][2]["name"] == "crate3");

  // A rotated box's points are written in its own frame.
  Pick poly;
  Json p = with_item(doc.json(), ItemKind::prop,
                     {{"shape", "polygon"},
                      {"position", vec2({0, 5})},
                      {"angle", std::numbers::pi / 2},
                      {"points", Json::array({vec2({-1, -1}), vec2({1, -1}), vec2({0, 1})})}},
                     poly);
  const Pick third{poly.kind, poly.index, PointSet::points, 2};
  p = with_point(p, third, {-2, 5});  // local (0, 2) once turned a quarter back
  CHECK(vec2_at(Json{{"v", p["props"][poly.index]["points"][2]}}, "v", {}) == Vec2{0, 2});
  p = with_point_inserted(p, {poly.kind, poly.index, PointSet::points, 1}, {0, 4});
  CHECK(p["props"][poly.index]["points"].size() == 4);
  p = removed(p, {{poly.kind, poly.index, PointSet::points, 1}});
  CHECK(p["props"][poly.index]["points"].size() == 3);
}

TEST_CASE("edits write tidy numbers: whole ones as integers, no 0.30000000000000004", "[unit][editor]") {
  CHECK(number(0.1 + 0.2).dump() == "0.3");
  CHECK(number(9.0).dump() == "9");
  CHECK(number(-1e-7).dump() == "-1e-07");
  LevelDocument doc = crate_document();
  Json j = moved(doc.json(), {{ItemKind::prop, 0}}, {0.1, 0.2});
  j = moved(j, {{ItemKind::prop, 0}}, {0.2, 0.1});
  CHECK(j["props"][0]["position"].dump() == "[3.3,0.8]");
}

TEST_CASE("a waypoint makes a prop kinematic with a path, moved with the prop", "[unit][editor]") {
  LevelDocument doc = crate_document();
  Pick w;
  Json j = with_waypoint(doc.json(), {ItemKind::prop, 0}, {6, 0.5}, w);
  CHECK(j["props"][0]["type"] == "kinematic");
  CHECK(w == Pick{ItemKind::prop, 0, PointSet::waypoints, 0});
  REQUIRE(doc.change(j).empty());
  j = moved(doc.json(), {{ItemKind::prop, 0}}, {1, 0});
  CHECK(j["props"][0]["path"]["waypoints"][0].dump() == "[7,0.5]");
}

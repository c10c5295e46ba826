// The editor's model with vehicles: one placed from the palette's default car validates and drives,
// moves whole (its wheels and head with it), an axle point dragged moves only its wheel and stays in
// the chassis' frame, a rotated chassis turns its parts, deleting a wheel or the vehicle, undo and
// redo, and a vehicle saved and read back.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "editor/level_document.h"
#include "editor/level_edits.h"
#include "editor/level_format.h"
#include "tire/io/level.h"
#include "tire/session/level_session.h"
#include "tire/world/world.h"

using namespace editor;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("tire-editor-vehicle-tests-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

// A new level with ground and, when `with_vehicle`, the editor's default car on it at x = 0.
LevelDocument ground_document(const std::string& name, bool with_vehicle) {
  const fs::path file = scratch(name);
  fs::remove(file);
  LevelDocument doc;
  REQUIRE(doc.open(file).empty());
  Pick added;
  REQUIRE(doc.change(with_item(doc.json(), ItemKind::obstacle,
                               {{"min", vec2({-20, -1})}, {"max", vec2({60, 0})}}, added))
              .empty());
  if (with_vehicle) {
    REQUIRE(
        doc.change(with_item(doc.json(), ItemKind::vehicle, default_vehicle({0, 0.7}, true), added)).empty());
    REQUIRE(added == Pick{ItemKind::vehicle, 0});
  }
  return doc;
}

Vec2 chassis_position(const LevelDocument& doc) {
  return vec2_at(doc.json()["vehicles"][0]["chassis"], "position", {});
}
Vec2 axle(const LevelDocument& doc, std::size_t w) {
  return vec2_at(doc.json()["vehicles"][0]["wheels"][w], "axle", {});
}

bool near(Vec2 a, Vec2 b) { return tire::length(a - b) < 1e-9; }

}  // namespace

TEST_CASE("a vehicle placed from the palette validates, is the player and drives right", "[unit][editor]") {
  LevelDocument doc = ground_document("placed.json", true);
  CHECK(doc.errors().empty());
  REQUIRE(doc.level());
  REQUIRE(doc.info().vehicles == 1);
  CHECK(doc.info().player_vehicle);
  // It is the car of tests/levels/vehicle-car.json: two wheels on axles 1.2 m apart, a head.
  const auto shape = shape_of(doc.json(), ItemKind::vehicle, 0);
  REQUIRE(shape);
  REQUIRE(shape->axles.size() == 2);
  CHECK(near(shape->axles[0], {-0.6, 0.4}));
  CHECK(near(shape->axles[1], {0.6, 0.4}));
  REQUIRE(shape->head);
  CHECK(near(*shape->head, {0.3, 1.05}));
  // Picked on its chassis, a wheel or its head; a box around it selects it.
  CHECK(pick_item(doc.json(), {0, 0.7}, 0.01) == Pick{ItemKind::vehicle, 0});
  CHECK(pick_item(doc.json(), {-0.6, 0.2}, 0.01) == Pick{ItemKind::vehicle, 0});
  CHECK(pick_item(doc.json(), {0.3, 1.15}, 0.01) == Pick{ItemKind::vehicle, 0});
  CHECK(items_inside(doc.json(), {{-1.5, -0.5}, {1.5, 1.5}}) == Selection{{ItemKind::vehicle, 0}});
  CHECK(items_inside(doc.json(), {{-0.8, -0.5}, {1.5, 1.5}}).empty());  // the rear wheel sticks out
  // A second one is not the player: the level has one.
  CHECK_FALSE(default_vehicle({5, 0.7}, false).contains("player"));
  CHECK(names_a_player(doc.json()));
  // Played: full throttle drives it to the right.
  auto session = tire::make_session(*doc.level());
  for (int i = 0; i < 120; ++i) session->step({1.0});
  CHECK(session->world().rigid().prop_state(0).center.x > 1.0);
}

TEST_CASE("a vehicle moves whole, and an axle point moves its wheel alone in the chassis' frame",
          "[unit][editor]") {
  LevelDocument doc = ground_document("moved.json", true);
  const Selection vehicle{{ItemKind::vehicle, 0}};
  REQUIRE(doc.change(moved(doc.json(), vehicle, {2.5, 1})).empty());
  CHECK(near(chassis_position(doc), {2.5, 1.7}));
  CHECK(near(axle(doc, 0), {-0.6, -0.3}));  // the wheels hang where they did on the chassis
  const auto shape = shape_of(doc.json(), ItemKind::vehicle, 0);
  CHECK(near(shape->axles[0], {1.9, 1.4}));
  CHECK(near(*shape->head, {2.8, 2.05}));

  // The rear axle dragged 0.2 m further back: only it moves, written in the chassis' frame.
  const Pick rear{ItemKind::vehicle, 0, PointSet::axles, 0};
  REQUIRE(doc.change(with_point(doc.json(), rear, {1.7, 1.4})).empty());
  CHECK(near(axle(doc, 0), {-0.8, -0.3}));
  CHECK(near(axle(doc, 1), {0.6, -0.3}));
  CHECK(near(chassis_position(doc), {2.5, 1.7}));
  // Nudged as a selected point, the same.
  REQUIRE(doc.change(moved(doc.json(), {rear}, {0, -0.1})).empty());
  CHECK(near(axle(doc, 0), {-0.8, -0.4}));
  // The head is a point too.
  REQUIRE(doc.change(with_point(doc.json(), {ItemKind::vehicle, 0, PointSet::head, 0}, {2.5, 2.1})).empty());
  CHECK(near(vec2_at(doc.json()["vehicles"][0]["head"], "position", {}), {0, 0.4}));

  // Turned a quarter: its parts turn with it, the axles' keys unchanged.
  REQUIRE(doc.change(with_angle(doc.json(), {ItemKind::vehicle, 0}, std::numbers::pi / 2)).empty());
  const auto turned = shape_of(doc.json(), ItemKind::vehicle, 0);
  CHECK(near(turned->axles[1], Vec2{2.5, 1.7} + Vec2{0.3, 0.6}));
  CHECK(near(axle(doc, 1), {0.6, -0.3}));
  // A dragged axle on the turned chassis is still written in its frame.
  REQUIRE(doc.change(with_point(doc.json(), {ItemKind::vehicle, 0, PointSet::axles, 1},
                                Vec2{2.5, 1.7} + Vec2{0.3, 0.8}))
              .empty());
  CHECK(near(axle(doc, 1), {0.8, -0.3}));

  // Every step undoes, back to the car as placed.
  while (doc.history_size() > 2) REQUIRE(doc.undo());
  CHECK(near(chassis_position(doc), {0, 0.7}));
  CHECK(near(axle(doc, 0), {-0.6, -0.3}));
  REQUIRE(doc.redo());
  CHECK(near(chassis_position(doc), {2.5, 1.7}));
}

TEST_CASE("a polygon chassis' points are dragged, added and deleted in the chassis' frame",
          "[unit][editor]") {
  LevelDocument doc = ground_document("polygon.json", true);
  Json poly = doc.json();
  Json& chassis = poly["vehicles"][0]["chassis"];
  chassis.erase("size");
  chassis["shape"] = "polygon";
  chassis["points"] =
      Json::array({vec2({-0.8, -0.15}), vec2({0.8, -0.15}), vec2({0.5, 0.15}), vec2({-0.8, 0.15})});
  REQUIRE(doc.change(poly).empty());
  REQUIRE(doc.change(with_angle(doc.json(), {ItemKind::vehicle, 0}, std::numbers::pi / 2)).empty());
  const auto points = [&] { return doc.json()["vehicles"][0]["chassis"]["points"]; };
  const auto point = [&](std::size_t k) {
    const Json p = points()[k];
    return Vec2{p[0].get<double>(), p[1].get<double>()};
  };

  // Point 2 (the nose's top corner, at (0.5, 0.15) in the chassis' frame; the chassis at (0, 0.7)
  // turned a quarter) dragged 0.2 m along the chassis' x, which is the world's y now.
  const auto shape = shape_of(doc.json(), ItemKind::vehicle, 0);
  REQUIRE(shape->outline.size() == 4);
  CHECK(near(shape->outline[2], Vec2{0, 0.7} + Vec2{-0.15, 0.5}));
  const Pick nose{ItemKind::vehicle, 0, PointSet::points, 2};
  REQUIRE(doc.change(with_point(doc.json(), nose, shape->outline[2] + Vec2{0, 0.2})).empty());
  CHECK(near(point(2), {0.7, 0.15}));
  CHECK(near(chassis_position(doc), {0, 0.7}));  // the chassis stays, and its wheels with it
  CHECK(near(axle(doc, 0), {-0.6, -0.3}));
  // Nudged as a selected point, the same frame.
  REQUIRE(doc.change(moved(doc.json(), {nose}, {0.1, 0})).empty());
  CHECK(near(point(2), {0.7, 0.05}));
  // A point added below the edge after point 0 (kept convex), then deleted.
  REQUIRE(doc.change(with_point_inserted(doc.json(), {ItemKind::vehicle, 0, PointSet::points, 1},
                                         Vec2{0, 0.7} + Vec2{0.2, 0.0}))
              .empty());
  REQUIRE(points().size() == 5);
  CHECK(near(point(1), {0.0, -0.2}));
  REQUIRE(doc.change(removed(doc.json(), {{ItemKind::vehicle, 0, PointSet::points, 1}})).empty());
  CHECK(points().size() == 4);
  // The level still validates and the vehicle loads with its new shape.
  const tire::LevelLoad load = tire::load_level_text(level_text(doc.json()), "polygon.json");
  REQUIRE(load.errors.empty());
  CHECK(near(load.level->vehicles.at(0).spec.chassis.points.at(2), {0.7, 0.05}));
}

TEST_CASE("a car keeps two wheels at least, and a wheel, the head or the whole vehicle is deleted and undone",
          "[unit][editor]") {
  LevelDocument doc = ground_document("deleted.json", true);
  // Two wheels at least: taking one of two is refused, and the car stays.
  const std::string refused = doc.change(removed(doc.json(), {{ItemKind::vehicle, 0, PointSet::axles, 1}}));
  CHECK(refused.find("/vehicles/0/wheels") != std::string::npos);
  CHECK(doc.json()["vehicles"][0]["wheels"].size() == 2);
  // A third wheel added, then deleted by its point.
  Json three = doc.json();
  Json wheel = three["vehicles"][0]["wheels"][1];
  wheel["axle"] = vec2({0.0, -0.3});
  three["vehicles"][0]["wheels"].push_back(wheel);
  REQUIRE(doc.change(three).empty());
  REQUIRE(doc.change(removed(doc.json(), {{ItemKind::vehicle, 0, PointSet::axles, 1}})).empty());
  CHECK(doc.json()["vehicles"][0]["wheels"].size() == 2);
  CHECK(near(axle(doc, 1), {0.0, -0.3}));
  // The head is optional.
  REQUIRE(doc.change(removed(doc.json(), {{ItemKind::vehicle, 0, PointSet::head, 0}})).empty());
  CHECK_FALSE(doc.json()["vehicles"][0].contains("head"));
  // The whole vehicle; a level without a player then is one the validator takes (no player).
  REQUIRE(doc.change(removed(doc.json(), {{ItemKind::vehicle, 0}})).empty());
  CHECK(doc.json()["vehicles"].empty());
  REQUIRE(doc.undo());
  CHECK(doc.json()["vehicles"].size() == 1);
}

TEST_CASE("a vehicle saved and read back is the same vehicle, and the file validates", "[unit][editor]") {
  LevelDocument doc = ground_document("saved.json", true);
  REQUIRE(doc.change(moved(doc.json(), {{ItemKind::vehicle, 0}}, {1, 0})).empty());
  REQUIRE(
      doc.change(with_point(doc.json(), {ItemKind::vehicle, 0, PointSet::axles, 1}, {1.75, 0.4})).empty());
  Json tuned = doc.json();
  tuned["vehicles"][0]["motor_torque"] = 90;
  tuned["vehicles"][0]["wheels"][0]["material"] = "soft";
  REQUIRE(doc.change(tuned).empty());
  REQUIRE(doc.save().empty());
  CHECK_FALSE(doc.modified());

  const tire::LevelLoad load = tire::load_level_file(doc.file());
  REQUIRE(load.errors.empty());
  REQUIRE(load.level->vehicles.size() == 1);
  const tire::LevelVehicle& v = load.level->vehicles[0];
  CHECK(v.player);
  CHECK(v.spec.chassis.position == Vec2{1, 0.7});
  CHECK(v.spec.chassis.size == Vec2{1.6, 0.3});
  REQUIRE(v.spec.wheels.size() == 2);
  CHECK(v.spec.wheels[0].axle.point == Vec2{-0.6, -0.3});
  CHECK(v.spec.wheels[1].axle.point == Vec2{0.75, -0.3});
  CHECK_FALSE(v.spec.wheels[1].axle.driven);
  CHECK(v.spec.wheels[1].axle.stiffness == 6000);
  CHECK(v.spec.drivetrain.motor_torque == 90);
  REQUIRE(v.head);
  CHECK(v.head->radius == 0.15);

  // Opened again it is the document that was saved (its keys in reference order), and saving it
  // again changes nothing.
  LevelDocument again;
  REQUIRE(again.open(doc.file()).empty());
  CHECK(again.json() == in_reference_order(doc.json()));
  CHECK_FALSE(again.modified());
  const std::string text = level_text(again.json());
  std::ifstream in(doc.file());
  const std::string on_disk((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text == on_disk);
  // Keys in reference order: the chassis before the wheels, a wheel's axle first.
  CHECK(on_disk.find("\"chassis\"") < on_disk.find("\"wheels\""));
  CHECK(on_disk.find("\"axle\"") < on_disk.find("\"outer_radius\""));
  fs::remove_all(doc.file().parent_path());
}

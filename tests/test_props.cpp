// Props: the contact geometry of each shape, and the physics of tires against Box2D bodies.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "tire/rigid/prop_geometry.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {
// A dynamic box named "crate".
PropSpec crate_spec(Vec2 size, double density, double friction, Vec2 position) {
  PropSpec crate;
  crate.name = "crate";
  crate.type = PropType::dynamic_body;
  crate.size = size;
  crate.density = density;
  crate.friction = friction;
  crate.position = position;
  return crate;
}

PropSpec shape_spec(PropShape shape) {
  PropSpec s;
  s.shape = shape;
  return s;
}
}  // namespace

TEST_CASE("a polygon pushes a particle out through the face it came in by", "[unit][props][contact]") {
  PropSpec spec = shape_spec(PropShape::box);
  spec.size = {4, 2};
  const PropGeometry g = PropGeometry::from_spec(spec);
  // Started inside: least overlap (near the right face).
  auto c = local_contact(g, {1.9, 0.0}, {1.95, 0.0});
  REQUIRE(c);
  CHECK(c->normal.x == Approx(1.0));
  CHECK(c->depth == Approx(0.05));
  // Came down through the top, although the left face is nearer.
  c = local_contact(g, {-1.95, 1.2}, {-1.95, 0.5});
  REQUIRE(c);
  CHECK(c->normal.y == Approx(1.0));
  CHECK(c->depth == Approx(0.5));
  // Crossed a thin polygon entirely in one substep: sent back to the entry face.
  spec.size = {0.05, 4};
  const PropGeometry wall = PropGeometry::from_spec(spec);
  c = local_contact(wall, {-0.5, 0.0}, {0.5, 0.0});
  REQUIRE(c);
  CHECK(c->normal.x == Approx(-1.0));
  CHECK(c->depth == Approx(0.525));
  CHECK_FALSE(local_contact(g, {3, 0}, {2.5, 0}));
}

TEST_CASE("the polygon contact's gradient is its normal", "[unit][props][contact]") {
  PropSpec spec = shape_spec(PropShape::polygon);
  spec.points = {{0, 0}, {3, 0}, {2, 2}, {0, 1}};
  const PropGeometry g = PropGeometry::from_spec(spec);
  const double eps = 1e-7;
  for (const Vec2 p : {Vec2{1.5, 0.1}, Vec2{0.05, 0.5}, Vec2{2.2, 1.0}, Vec2{1.0, 1.2}}) {
    const auto c = local_contact(g, p, p);
    REQUIRE(c);
    const auto C = [&](Vec2 q) { return -local_contact(g, q, q)->depth; };
    CHECK((C(p + Vec2{eps, 0}) - C(p - Vec2{eps, 0})) / (2 * eps) == Approx(c->normal.x).margin(1e-6));
    CHECK((C(p + Vec2{0, eps}) - C(p - Vec2{0, eps})) / (2 * eps) == Approx(c->normal.y).margin(1e-6));
  }
}

TEST_CASE("a circle pushes out radially and catches a particle that crossed it", "[unit][props][contact]") {
  PropSpec spec = shape_spec(PropShape::circle);
  spec.radius = 1.0;
  const PropGeometry g = PropGeometry::from_spec(spec);
  auto c = local_contact(g, {0.6, 0.8}, {0.48, 0.64});
  REQUIRE(c);
  CHECK(c->normal.x == Approx(0.6));
  CHECK(c->normal.y == Approx(0.8));
  CHECK(c->depth == Approx(0.2));
  c = local_contact(g, {-1.5, 0.1}, {1.5, 0.1});  // straight through
  REQUIRE(c);
  CHECK(c->normal.x < 0.0);
  CHECK_FALSE(local_contact(g, {2, 0}, {1.5, 0}));
}

TEST_CASE("a chain is one-sided: solid on the right of its points, as thick as it says",
          "[unit][props][contact]") {
  PropSpec spec = shape_spec(PropShape::chain);
  spec.points = {{-5, 0}, {0, 0}, {5, -1}};  // terrain drawn left to right: solid below
  spec.thickness = 0.5;
  const PropGeometry g = PropGeometry::from_spec(spec);
  auto c = local_contact(g, {-1, 0.1}, {-1, -0.05});
  REQUIRE(c);
  CHECK(c->normal.y == Approx(1.0));
  CHECK(c->depth == Approx(0.05));
  c = local_contact(g, {-1, -0.3}, {-1, -0.2});  // already under the line, within the thickness
  REQUIRE(c);
  CHECK(c->depth == Approx(0.2));
  // The same particle when no surface held it the substep before: it came up from behind the
  // solid, and passes (pushed out, it would be thrown 0.2 m in one substep).
  CHECK_FALSE(local_contact(g, {-1, -0.3}, {-1, -0.2}, false));
  CHECK_FALSE(local_contact(g, {-1, -0.6}, {-1, -0.4}, false));
  CHECK(local_contact(g, {-1, 0.1}, {-1, -0.05}, false));  // crossing from the front: a contact all the same
  CHECK_FALSE(local_contact(g, {-1, -0.9}, {-1, -0.8}));   // deeper than the thickness: not this chain
  CHECK_FALSE(local_contact(g, {-1, 0.5}, {-1, 0.2}));     // above: free
  // On the sloped edge the normal is the edge's.
  c = local_contact(g, {2.5, 0.0}, {2.5, -0.6});
  REQUIRE(c);
  CHECK(c->normal.x == Approx(1.0 / std::sqrt(26.0)));
  CHECK(c->normal.y == Approx(5.0 / std::sqrt(26.0)));
  // A closed chain is solid inside whichever way its points go.
  spec.points = {{0, 0}, {0, 2}, {2, 2}, {2, 0}};  // clockwise
  spec.loop = true;
  for (int flip = 0; flip < 2; ++flip) {
    const PropGeometry ring = PropGeometry::from_spec(spec);
    c = local_contact(ring, {1, 2.2}, {1, 1.9});
    REQUIRE(c);
    CHECK(c->normal.y == Approx(1.0));
    std::reverse(spec.points.begin(), spec.points.end());
  }
}

TEST_CASE("convexity is checked: counter-clockwise, no dents, one turn", "[unit][props]") {
  CHECK(is_convex_ccw({{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
  CHECK_FALSE(is_convex_ccw({{0, 0}, {0, 1}, {1, 1}, {1, 0}}));            // clockwise
  CHECK_FALSE(is_convex_ccw({{0, 0}, {2, 0}, {1, 0.5}, {2, 2}, {0, 2}}));  // dented
  CHECK_FALSE(is_convex_ccw({{0, 0}, {1, 0}, {2, 0}, {1, 1}}));            // three in a line
  std::vector<Vec2> star;
  for (int i = 0; i < 5; ++i) {
    const double a = 4.0 * std::numbers::pi * i / 5;
    star.push_back({std::cos(a), std::sin(a)});
  }
  CHECK_FALSE(is_convex_ccw(star));  // turns left everywhere, but twice round
}

namespace {

// A slope of angle θ (rad, downhill towards +x) as a long static prop whose top surface passes
// through the origin, and a tire resting on it, its flat bottom segment along the slope.
World slope_world(double theta, PropShape shape, double friction, double rolling_resistance = 0.0,
                  SolverMethod method = SolverConfig{}.method, int segments = TireSpec{}.segments) {
  SolverConfig config;
  config.substeps = 16;
  config.method = method;
  World world(config, {0, -9.81});
  const Pose slope = Pose::make({}, -theta);
  PropSpec prop;
  prop.shape = shape;
  prop.friction = 1.0;
  if (shape == PropShape::chain) {
    prop.points = {slope.to_world({-30, 0}), slope.to_world({30, 0})};
  } else {
    prop.shape = PropShape::box;
    prop.size = {60, 2};
    prop.position = slope.to_world({0, -1});
    prop.angle = -theta;
  }
  world.add_prop(prop);
  TireSpec tire;
  tire.segments = segments;
  tire.angle = -theta;
  tire.friction = tire.kinetic_friction = friction;
  tire.rolling_resistance = rolling_resistance;
  tire.position = slope.to_world({0, tire.outer_radius * std::cos(std::numbers::pi / tire.segments) + 0.002});
  world.add_tire(tire);
  return world;
}

// A free wheel (no rolling resistance) of `segments` segments resting on a 20 m belt, a kinematic
// platform that starts at once at kBeltSpeed along +x.
constexpr double kBeltSpeed = 1.5;  // m/s
TireSpec belt_tire(int segments) {
  TireSpec spec = tire_at({0, 0.5});
  spec.segments = segments;
  spec.rolling_resistance = 0.0;
  return spec;
}
World belt_world(const SolverConfig& config, const TireSpec& tire) {
  World world(config, {0, -9.81});
  PropSpec platform;
  platform.name = "belt";
  platform.type = PropType::kinematic_body;
  platform.size = {20, 0.4};
  platform.position = {0, -0.2};
  platform.path.waypoints = {{0, -0.2}, {50, -0.2}};
  platform.path.speed = kBeltSpeed;
  platform.path.mode = PathMode::once;
  world.add_prop(platform);
  world.add_tire(tire);
  return world;
}

// A round wheel of the default tire's rings rolling down a slope of angle θ without slipping:
// g sin θ / (1 + I/(M R²)), with equal masses on both rings, I = M (R² + r²) / 2 about the hub.
double round_wheel_slope_acceleration(double theta) {
  const TireSpec spec;
  const double i_ratio = (1.0 + std::pow(spec.inner_radius / spec.outer_radius, 2)) / 2.0;
  return 9.81 * std::sin(theta) / (1.0 + i_ratio);
}

// A free round wheel on a belt started at kBeltSpeed: it rolls without slipping at V·I/(I + M R²),
// I its measured inertia about the hub.
double round_wheel_belt_speed(const RigidMotion& m, const TireSpec& spec) {
  const double i_ratio = m.inertia / (spec.mass * spec.outer_radius * spec.outer_radius);
  return kBeltSpeed * i_ratio / (1.0 + i_ratio);
}

// Acceleration along the slope, from the velocity gained between 0.5 s and 1.5 s.
double downhill_acceleration(World& world, double theta) {
  const Vec2 downhill{std::cos(theta), -std::sin(theta)};
  run(world, 30);
  const double v0 = dot(world.tires().front().velocity(), downhill);
  run(world, 60);
  return (dot(world.tires().front().velocity(), downhill) - v0) / 1.0;
}

}  // namespace

TEST_CASE("gauss-seidel: a tire rolls down a slope at g sin(theta) / (1 + I/(M R^2))",
          "[unit][props][physics]") {
  // Gauss–Seidel at 16 substeps, whose softness rounds the 28-sided tire; the global method holds it
  // as stiff as its material, a polygon, and meets the round wheel as its segments grow (below).
  const double theta = 20.0 * std::numbers::pi / 180.0;
  const double expected = round_wheel_slope_acceleration(theta);
  for (const PropShape shape : {PropShape::box, PropShape::chain}) {
    World world = slope_world(theta, shape, 0.9, 0.0, SolverMethod::gauss_seidel);
    const double a = downhill_acceleration(world, theta);
    INFO((shape == PropShape::chain ? "chain" : "box") << " slope: " << a << " m/s², expected " << expected);
    CHECK(a == Approx(expected).epsilon(0.10));
    CHECK(world.tires().front().angular_velocity() < -1.0);  // it is rolling, not sliding
  }
}

TEST_CASE("global: a tire rolls down a slope as a round wheel does once its polygon is fine enough",
          "[unit][props][physics][global]") {
  // g sin θ / (1 + I/(M R²)) is a round wheel's. The global method holds the default tire as stiff as
  // its material (0.11 mm rest sag), so at this speed it rolls as the rigid 28-sided polygon it is:
  // each tread particle lands in turn, and the landing keeps only the angular momentum about the new
  // corner, (I + M R² cos 2π/N) / (I + M R²) of the spin (98.5 % at N = 28). That loss falls as 1/N,
  // so the acceleration must rise towards the round wheel's as the segments double.
  const double theta = 20.0 * std::numbers::pi / 180.0;
  const double expected = round_wheel_slope_acceleration(theta);
  double previous = 0.0;
  for (const int segments : {28, 56, 112}) {
    World world = slope_world(theta, PropShape::box, 0.9, 0.0, SolverMethod::global, segments);
    const double a = downhill_acceleration(world, theta);
    INFO(segments << " segments: " << a << " m/s², a round wheel " << expected);
    CHECK(a > previous);  // rounder rolls faster
    CHECK(a < expected * 1.02);
    if (segments == 112) CHECK(a == Approx(expected).epsilon(0.05));
    previous = a;
  }
}

TEST_CASE("a tire with no friction slides down a slope at g sin(theta) without turning",
          "[unit][props][physics]") {
  const double theta = 20.0 * std::numbers::pi / 180.0;
  for (const PropShape shape : {PropShape::box, PropShape::chain}) {
    World world = slope_world(theta, shape, 0.0);
    const double a = downhill_acceleration(world, theta);
    INFO((shape == PropShape::chain ? "chain" : "box") << " slope: " << a << " m/s²");
    CHECK(a == Approx(9.81 * std::sin(theta)).epsilon(0.03));
    CHECK(std::abs(world.tires().front().angular_velocity()) < 0.05);
  }
}

TEST_CASE("a tire rests stably on a gentle slope with enough friction", "[unit][props][physics]") {
  // Resting on its flat patch, a tire stays put on a slope gentler than the patch can tip over.
  const double theta = 3.0 * std::numbers::pi / 180.0;
  for (const PropShape shape : {PropShape::box, PropShape::chain}) {
    World world = slope_world(theta, shape, 0.9, 0.01);
    run(world, 180);
    const Vec2 start = world.tires().front().centroid();
    double max_speed = 0.0;
    for (int i = 0; i < 120; ++i)
      world.step({}), max_speed = std::max(max_speed, length(world.tires().front().velocity()));
    INFO((shape == PropShape::chain ? "chain" : "box") << " slope");
    CHECK(max_speed < 1e-3);
    CHECK(length(world.tires().front().centroid() - start) < 2e-3);
    // Without friction the same tire slides away.
    World slippery = slope_world(theta, shape, 0.0, 0.01);
    run(slippery, 120);
    CHECK(length(slippery.tires().front().velocity()) > 0.5);
  }
}

TEST_CASE("momentum is conserved when a tire hits a crate", "[unit][props][physics]") {
  SolverConfig config;
  config.method = GENERATE(SolverMethod::gauss_seidel, SolverMethod::global);
  World world(config, {0, 0});
  TireSpec tire;
  tire.position = {0, 0};
  tire.velocity = {6, 0.3};
  world.add_tire(tire);
  PropSpec crate;
  crate.name = "crate";
  crate.type = PropType::dynamic_body;
  crate.size = {0.6, 0.6};
  crate.density = 25;  // 9 kg
  crate.position = {1.5, 0.1};
  crate.angle = 0.3;
  world.add_prop(crate);
  const auto momentum = [&] {
    const Prop& p = world.rigid().props().front();
    const double m_crate = 1.0 / p.inverse_mass;
    return world.tires().front().velocity() * tire.mass + p.velocity * m_crate;
  };
  world.step({});
  const Vec2 before = momentum();
  run(world, 60);
  const Vec2 after = momentum();
  const Prop& p = world.rigid().props().front();
  INFO("crate velocity after: " << p.velocity.x << ", " << p.velocity.y);
  CHECK(p.velocity.x > 1.0);  // they did collide
  CHECK(after.x == Approx(before.x).epsilon(1e-4));
  CHECK(after.y == Approx(before.y).margin(1e-4 * std::abs(before.x)));
}

TEST_CASE("global: a crate lying on a tire rests on it at any substep count", "[unit][props][physics]") {
  // The crate touches nothing but the tire, so it moves within the tick as the tire pushes it, and
  // the tire's solve holds it as one rigid body: all its contacts move it together. (Each contact
  // taking the crate's give alone, as if the others were not there, moved it by their sum: at 2
  // substeps it bounced on the tire by 1.3 cm for ever.)
  SolverConfig config;
  config.method = SolverMethod::global;
  config.substeps = GENERATE(1, 2, 8);
  config.sleep = false;  // asleep, it would rest whatever the coupling did
  CAPTURE(config.substeps);
  TireSpec tire;
  tire.position = {0, 0.5};
  World world = flat_world(tire, config);
  world.add_prop(crate_spec({1.0, 0.3}, 20, 0.5, {0, 1.17}));  // 6 kg
  run(world, 180);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, fastest = 0.0;
  for (int i = 0; i < 60; ++i) {
    world.step({});
    const PropState s = world.rigid().prop_state(0);
    lo = std::min(lo, s.center.y);
    hi = std::max(hi, s.center.y);
    fastest = std::max(fastest, length(s.velocity));
  }
  INFO("crate height " << lo << " to " << hi << " m, fastest " << fastest << " m/s");
  CHECK(lo > 1.0);  // on the tire, not through it
  CHECK(hi - lo < 1e-4);
  CHECK(fastest < 1e-3);
}

TEST_CASE("a driving tire pushes a crate along the ground", "[unit][props][physics]") {
  TireSpec tire;
  tire.position = {0, 0.5};
  World world = flat_world(tire);
  // Taller than the tire, so it cannot climb it (a driven tire climbs a low box by the friction
  // on its face), and light enough for the drive's torque to beat its friction on the ground.
  world.add_prop(crate_spec({1.0, 1.2}, 5, 0.4, {1.5, 0.6}));  // 6 kg
  run(world, 240, {1.0, false});
  const double crate_x = world.rigid().props().front().start_pose.position.x;
  const Tire& t = world.tires().front();
  INFO("crate at " << crate_x << ", tire at " << t.centroid().x);
  CHECK(crate_x > 2.5);                                // pushed more than a metre
  CHECK(t.centroid().x < crate_x - 0.5);               // from behind: not over, not through
  CHECK(t.centroid().y == Approx(0.49).margin(0.02));  // still on the ground
}

TEST_CASE("global: a driven tire pushes a crate as far at 2, 8 and 32 substeps", "[unit][props][physics]") {
  // Box2D steps with the substeps (rigid_world.h), so the crate meets the tire at the substeps' rate
  // as the tire's constraints do: the push is the material's and the friction's, not the solver's.
  // (With Box2D stepping once a tick, this start moved the crate 3.8, 13.1 and 9.8 m at 2, 8 and 32
  // substeps.)
  const auto pushed = [](int substeps) {
    SolverConfig config;
    config.method = SolverMethod::global;
    config.substeps = substeps;
    TireSpec tire;
    tire.position = {0, 0.5};
    World world = flat_world(tire, config);
    world.add_prop(crate_spec({1.0, 1.2}, 5, 0.4, {2.1, 0.6}));  // 6 kg, 1.1 m ahead of the tread
    run(world, 240, {1.0, false});
    return world.rigid().props().front().start_pose.position.x - 2.1;
  };
  const double at2 = pushed(2), at8 = pushed(8), at32 = pushed(32);
  INFO("crate pushed " << at2 << " / " << at8 << " / " << at32 << " m at 2 / 8 / 32 substeps");
  CHECK(at2 > 1.0);  // it was pushed
  CHECK(at2 == Approx(at32).epsilon(0.10));
  CHECK(at8 == Approx(at32).epsilon(0.10));
}

TEST_CASE("gauss-seidel: a moving platform carries a tire by friction, as a free wheel",
          "[unit][props][physics]") {
  // A free wheel on a platform that starts moving at V: friction acts at the contact, so the
  // wheel's angular momentum about the contact point stays 0 and it settles rolling without
  // slipping at v = V·I/(I + M R²), turning backwards relative to the platform.
  const TireSpec spec = belt_tire(TireSpec{}.segments);
  // Gauss–Seidel 8 × 1; the global method's polygon meets the round wheel as its segments grow (below).
  World world = belt_world(SolverConfig::gauss_seidel_8x1(), spec);
  run(world, 60);
  const Tire& t = world.tires().front();
  const RigidMotion m = t.rigid_motion();
  INFO("hub " << m.velocity.x << " m/s, tread at the contact " << m.velocity.x + m.omega * spec.outer_radius);
  CHECK(m.velocity.x == Approx(round_wheel_belt_speed(m, spec)).epsilon(0.10));
  CHECK(m.velocity.x + m.omega * spec.outer_radius ==
        Approx(kBeltSpeed).epsilon(0.05));  // no slip on the belt
  CHECK(t.grounded());
}

TEST_CASE("global: a moving platform carries a free wheel as a round wheel once its polygon is fine enough",
          "[unit][props][physics][global]") {
  // As above for the belt (v = V·I/(I + M R²)): the 28-sided polygon's landings drain its spin and
  // it creeps towards the belt's speed; with 112 segments it keeps the round wheel's speed.
  double previous = std::numeric_limits<double>::infinity();
  for (const int segments : {28, 112}) {
    SolverConfig config;
    config.method = SolverMethod::global;
    const TireSpec spec = belt_tire(segments);
    World world = belt_world(config, spec);
    run(world, 60);
    const RigidMotion m = world.tires().front().rigid_motion();
    const double expected = round_wheel_belt_speed(m, spec);
    INFO(segments << " segments: hub " << m.velocity.x << " m/s, a round wheel " << expected);
    CHECK(m.velocity.x < previous);
    CHECK(m.velocity.x + m.omega * spec.outer_radius == Approx(kBeltSpeed).epsilon(0.05));  // no slip
    if (segments == 112) CHECK(m.velocity.x == Approx(expected).epsilon(0.05));
    previous = m.velocity.x;
  }
}

TEST_CASE("an elevator lifts a tire", "[unit][props][physics]") {
  World world(SolverConfig{}, {0, -9.81});
  PropSpec lift;
  lift.name = "lift";
  lift.type = PropType::kinematic_body;
  lift.size = {2, 0.2};
  lift.position = {0, -0.1};
  lift.path.waypoints = {{0, 3}};
  lift.path.speed = 1.0;
  lift.path.mode = PathMode::once;
  world.add_prop(lift);
  world.add_tire(tire_at({0, 0.5}));
  run(world, 120);
  const Tire& t = world.tires().front();
  CHECK(t.velocity().y == Approx(1.0).epsilon(0.05));
  CHECK(t.centroid().y == Approx(0.5 + 1.9).margin(0.1));
  run(world, 240);  // arrived and stopped (tossing the tire up a little): it settles on top
  CHECK(t.centroid().y == Approx(3.0 + 0.1 + 0.49).margin(0.05));
  CHECK(std::abs(t.velocity().y) < 0.01);
}

TEST_CASE("a kinematic path loops, ping-pongs, stops and reverses", "[unit][props]") {
  World world(SolverConfig{}, {0, 0});
  PropSpec p;
  p.name = "shuttle";
  p.type = PropType::kinematic_body;
  p.path.waypoints = {{0, 0}, {1, 0}};
  p.path.speed = 2.0;
  p.path.mode = PathMode::ping_pong;
  world.add_prop(p);
  const auto x = [&] {
    world.step({});
    return world.rigid().props().front().alive ? world.rigid().props().front().start_pose.position.x : 0.0;
  };
  double max_x = 0.0, min_x_after = 1.0;
  for (int i = 0; i < 60; ++i) max_x = std::max(max_x, x());
  for (int i = 0; i < 30; ++i) min_x_after = std::min(min_x_after, x());
  CHECK(max_x == Approx(1.0).margin(1e-5));  // reached the end and turned back, never overshooting
  CHECK(min_x_after < 0.5);
  world.rigid().path_command("shuttle", PathCommand::stop);
  const double stopped = x();
  CHECK(x() == stopped);
  CHECK(world.rigid().path_command("shuttle", PathCommand::start));
  CHECK_FALSE(world.rigid().path_command("nobody", PathCommand::start));
}

TEST_CASE("props are read with every mistake reported at its path", "[unit][props][level]") {
  const auto errors = load_level_text(R"({
    "name": "props",
    "props": [
      { "name": "a", "shape": "polygon", "points": [[0, 0], [0, 1], [1, 1], [1, 0]] },
      { "name": "a", "shape": "box", "radius": 2 },
      { "shape": "chain", "type": "dynamic", "points": [[0, 0], [0.001, 0]] },
      { "shape": "circle" },
      { "shape": "wedge" },
      { "shape": "box", "type": "static", "path": { "waypoints": [[0, 0]] } },
      { "shape": "polygon", "points": [[0, 0], [1, 0], [2, "x"]] }
    ] })",
                                      "p.json")
                          .errors;
  std::string all;
  for (const std::string& e : errors) all += e + "\n";
  INFO(all);
  const auto has = [&](const std::string& s) { return all.find(s) != std::string::npos; };
  CHECK(has("p.json: /props/0/points: must be a convex polygon in counter-clockwise order"));
  CHECK(has("p.json: /props/1/radius: applies only to circle props, and this one is a box"));
  CHECK(has("p.json: /props/1/size: is required"));
  CHECK(has("p.json: /props/1/name: must be unique, and /props/0 is already \"a\""));
  CHECK(has("p.json: /props/2/type: a chain can only be static"));
  CHECK(has("p.json: /props/2/points/1: must be at least 0.01 m from the point before it"));
  CHECK(has("p.json: /props/3/radius: is required"));
  CHECK(has(
      "p.json: /props/4/shape: must be one of \"box\", \"circle\", \"polygon\", \"chain\", got \"wedge\""));
  CHECK(has("p.json: /props/5/path: applies only to kinematic props, and this one is static"));
  CHECK(has("p.json: /props/6/points/2: must be [x, y]"));
  CHECK_FALSE(has("/props/6/points: must be a convex"));  // no knock-on error from the bad point
}

TEST_CASE("tires and Box2D bodies stand on the same side of a chain", "[unit][props][physics]") {
  // A chain drawn left to right is solid below, for the tire's contacts and for Box2D's alike.
  World world(SolverConfig{}, {0, -9.81});
  PropSpec ground;
  ground.shape = PropShape::chain;
  ground.points = {{-10, 0}, {0, -0.5}, {10, -0.5}};
  world.add_prop(ground);
  PropSpec crate;
  crate.name = "crate";
  crate.type = PropType::dynamic_body;
  crate.size = {0.6, 0.6};
  crate.position = {4, 1};
  world.add_prop(crate);
  world.add_tire(tire_at({-4, 1.5}));
  run(world, 180);
  const Pose crate_pose = world.rigid().current_pose(*world.rigid().find_prop("crate"));
  CHECK(crate_pose.position.y == Approx(-0.5 + 0.3).margin(0.03));
  CHECK(world.tires().front().centroid().y > -0.5);
  // And a closed chain is solid inside for both: the crate dropped onto it stays on top.
  World ring(SolverConfig{}, {0, -9.81});
  PropSpec box;
  box.shape = PropShape::chain;
  box.loop = true;
  box.points = {{-3, -1}, {3, -1}, {3, 0}, {-3, 0}};
  ring.add_prop(box);
  crate.position = {0, 1};
  ring.add_prop(crate);
  ring.add_tire(tire_at({-1.5, 1.0}));
  run(ring, 180);
  CHECK(ring.rigid().current_pose(*ring.rigid().find_prop("crate")).position.y == Approx(0.3).margin(0.03));
  CHECK(ring.tires().front().centroid().y > 0.4);
}

TEST_CASE("a ball spinning fast meets only the particles that come near it", "[unit][props][contact]") {
  // A ball of radius 0.15 m that turns 1.5 rad in a substep (90 rad/s at one substep) and a tread
  // particle that stays 4 cm above it. Met in the ball's turning frame, the particle's path is the
  // chord of an arc about the ball's centre, 14 cm from it: it crossed the ball, was pushed out and
  // threw it (the tire rolled over the small ball gained up to 8 kJ so, docs/at-rest.md). A circle is
  // met in a frame that only moves.
  PropSpec spec = shape_spec(PropShape::circle);
  spec.radius = 0.15;
  const PropGeometry ball = PropGeometry::from_spec(spec);
  const Vec2 particle{0.0, 0.19};
  PropFrame frame{0, Pose::make({}, 0.0), Pose::make({}, 1.5), true};
  CHECK_FALSE(local_contact(ball, frame.start_local(particle), frame.end.to_local(particle)));
  frame.round = false;  // the turning frame: the phantom crossing
  CHECK(local_contact(ball, frame.start_local(particle), frame.end.to_local(particle)));
  // The frame that only moves still sees the ball move: a particle it runs into is met.
  frame = PropFrame{0, Pose::make({0.0, 0.0}, 0.0), Pose::make({0.0, 0.1}, 1.5), true};
  const auto hit = local_contact(ball, frame.start_local(particle), frame.end.to_local(particle));
  REQUIRE(hit);
  CHECK(hit->depth == Approx(0.06));
}

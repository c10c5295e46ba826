// How a whole tire moves: falling, resting, rolling, jumping, and the safety clamps.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

TEST_CASE("free fall matches the discrete solution exactly", "[unit][motion][physics]") {
  // Semi-implicit Euler per substep: after k substeps, y = y0 + v0·k·h + g·h²·k(k+1)/2.
  // 40 ticks stay under the anti-tunneling clamp even at one substep (one segment per 1/60 s).
  for (const int substeps : {1, 8, 32}) {
    SolverConfig config;
    config.substeps = substeps;
    World world(config, {0, -9.81});
    TireSpec spec;
    spec.position = {0, 100};
    spec.velocity = {0.5, 2.0};
    world.add_tire(spec);
    run(world, 40);
    const double h = config.dt / substeps;
    const double k = 40.0 * substeps;
    const Tire& t = world.tires().front();
    INFO("substeps " << substeps);
    CHECK(t.centroid().x == Approx(0.5 * k * h).epsilon(1e-9));
    CHECK(t.centroid().y == Approx(100 + 2.0 * k * h - 9.81 * h * h * k * (k + 1) / 2).epsilon(1e-9));
    CHECK(t.velocity().y == Approx(2.0 - 9.81 * k * h).epsilon(1e-9));
  }
}

TEST_CASE("free fall under the default settings is not clamped below 30 m/s", "[unit][motion]") {
  const Level level = default_level();
  World world(level.solver, level.gravity);
  TireSpec spec = level.tires.front();
  spec.position = {0, 1000};
  world.add_tire(spec);
  const int ticks = static_cast<int>(3.2 / level.solver.dt);  // ~31 m/s
  run(world, ticks);
  CHECK(-world.tires().front().velocity().y == Approx(9.81 * ticks * level.solver.dt).epsilon(1e-9));
  CHECK(-world.tires().front().velocity().y > 30.0);
}

TEST_CASE("a tire resting on the ground does not creep or jitter", "[unit][motion][physics]") {
  World world(default_level().solver, {0, -9.81});
  populate_world(default_level(), world);
  run(world, 300);  // settle for 5 s
  const Vec2 start = world.tires().front().centroid();
  double max_speed = 0.0;
  for (int i = 0; i < 120; ++i) {
    world.step({});
    max_speed = std::max(max_speed, length(world.tires().front().velocity()));
  }
  CHECK(max_speed < 1e-3);
  CHECK(length(world.tires().front().centroid() - start) < 1e-3);
  CHECK(world.tires().front().grounded());
}

TEST_CASE("a tire's rest sag does not depend on substeps", "[unit][motion][physics]") {
  // A soft tire (visible sag); the sag is measured once the solver has converged in time.
  TireSpec spec;
  spec.position = {0, 0.5};
  spec.compliance.pressure = 1e-3;
  spec.compliance.spoke = 1e-4;
  // Gauss–Seidel's unconverged error shrinks with h, so the sag converges: 16 substeps are within
  // 20 % of the converged sag, 32 within 8 %, 64 within 3 %.
  std::vector<double> sags;
  for (const int substeps : {16, 32, 64, 128}) {
    SolverConfig config;
    config.substeps = substeps;
    config.sleep = false;  // the solver's rest, not where a still tire is frozen
    World world = flat_world(spec, config);
    run(world, 240);
    double sum = 0.0;
    for (int i = 0; i < 60; ++i) world.step({}), sum += world.tires().front().centroid().y;
    sags.push_back(spec.outer_radius - sum / 60);
  }
  INFO("sag at 16, 32, 64, 128 substeps: " << sags[0] << ", " << sags[1] << ", " << sags[2] << ", "
                                           << sags[3]);
  CHECK(sags[3] > 0.005);  // the tire really is soft
  CHECK(sags[0] == Approx(sags[3]).epsilon(0.20));
  CHECK(sags[1] == Approx(sags[3]).epsilon(0.08));
  CHECK(sags[2] == Approx(sags[3]).epsilon(0.03));
}

namespace {
// Unwrapped rotation (rad, CCW) of particle 0 about the centroid since the previous call.
struct RotationTracker {
  double last = 0.0;
  double total = 0.0;
  explicit RotationTracker(const Tire& t) : last(angle(t)) {}
  static double angle(const Tire& t) {
    const Vec2 r = t.particles.x[0] - t.centroid();
    return std::atan2(r.y, r.x);
  }
  void update(const Tire& t) {
    double a = angle(t), d = a - last;
    if (d > std::numbers::pi) d -= 2 * std::numbers::pi;
    if (d < -std::numbers::pi) d += 2 * std::numbers::pi;
    total += d;
    last = a;
  }
};
}  // namespace

TEST_CASE("steering rolls the tire by traction: rotation matches distance", "[unit][motion][physics]") {
  for (const double steer : {1.0, -1.0}) {
    World world(default_level().solver, {0, -9.81});
    populate_world(default_level(), world);
    run(world, 60);
    const Tire& t = world.tires().front();
    const double x0 = t.centroid().x;
    RotationTracker rotation(t);
    for (int i = 0; i < 90; ++i) {
      world.step({steer, false});
      rotation.update(t);
    }
    const double travelled = t.centroid().x - x0;
    INFO("steer " << steer << ": travelled " << travelled << " m, rotated " << rotation.total << " rad");
    CHECK(travelled * steer > 2.0);  // it went the way it was steered
    // Rolling without slipping: distance = −rotation · rolling radius.
    CHECK(-rotation.total * t.spec.outer_radius == Approx(travelled).epsilon(0.10));
  }
}

TEST_CASE("without input a tire on flat ground stays where it is", "[unit][motion]") {
  World world(default_level().solver, {0, -9.81});
  populate_world(default_level(), world);
  run(world, 600);
  CHECK(std::abs(world.tires().front().centroid().x) < 0.01);
}

TEST_CASE("steering in the air spins the tire but does not move it sideways", "[unit][motion][physics]") {
  SolverConfig config;
  World world(config, {0, 0});
  TireSpec spec;
  spec.position = {0, 10};
  world.add_tire(spec);
  run(world, 60, {1.0, false});
  const Tire& t = world.tires().front();
  CHECK(std::abs(t.velocity().x) < 1e-9);
  CHECK(t.angular_velocity() < -1.0);  // clockwise: the direction that would roll it to +x
}

TEST_CASE("jump lifts a grounded tire and does nothing in the air", "[unit][motion]") {
  World world(default_level().solver, {0, -9.81});
  populate_world(default_level(), world);
  run(world, 60);
  REQUIRE(world.tires().front().grounded());
  world.step({0.0, true});
  const double jump_speed = world.tires().front().spec.jump_speed;
  CHECK(world.tires().front().velocity().y == Approx(jump_speed - 9.81 * world.config().dt).margin(0.3));
  run(world, 10);
  const Tire& t = world.tires().front();
  REQUIRE_FALSE(t.grounded());
  const double vy = t.velocity().y;
  world.step({0.0, true});  // in the air: ignored
  CHECK(t.velocity().y == Approx(vy - 9.81 * world.config().dt).epsilon(1e-9));
  // It comes back down, settles and can jump again.
  run(world, 300);
  CHECK(t.grounded());
}

TEST_CASE("the anti-tunneling clamp holds under huge impulses", "[unit][motion]") {
  SolverConfig config;
  World world(config, {0, -9.81});
  world.add_obstacle({{{5, -10}, {5.05, 10}}});  // a 5 cm wall
  TireSpec spec;
  spec.position = {0, 0};
  spec.velocity = {1e4, 0};  // 10 km/s towards the wall
  spec.max_speed = 1e3;
  world.add_tire(spec);
  const Tire& t = world.tires().front();
  const double v_max = config.tunnel_clamp * t.segment_length / (config.dt / config.substeps);
  for (int i = 0; i < 60; ++i) {
    world.step({});
    for (const Vec2& v : t.particles.v) REQUIRE(length(v) <= v_max * 1.5);
  }
  // It did not pass through the wall.
  for (const Vec2& x : t.particles.x) CHECK(x.x < 5.0);
}

TEST_CASE("the horizontal speed cap holds", "[unit][motion]") {
  TireSpec spec;
  spec.position = {0, 0.5};
  spec.velocity = {40, 0};
  spec.max_speed = 12;
  World world = flat_world(spec);
  world.step({});
  CHECK(std::abs(world.tires().front().velocity().x) <= 12.0 + 1e-9);
}

// Vehicles (issue 37, vehicle_joints.h): a chassis on soft tires, held at its axles by joints solved
// with the tires' systems. The tests of physical meaning, and the rows' gradients.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "tire/math/trig.h"
#include "tire/world/energy.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {

// A 1.6 m × 0.3 m chassis of 48 kg on two 8 kg tires of radius 0.35 m, axles `front` and `rear`
// metres from its centre, 0.3 m below it; the chassis' centre at `position`.
VehicleSpec car(Vec2 position, double rear = 0.6, double front = 0.6) {
  VehicleSpec v;
  v.chassis.shape = PropShape::box;
  v.chassis.size = {1.6, 0.3};
  v.chassis.density = 100;
  v.chassis.position = position;
  for (const double x : {-rear, front}) {
    WheelSpec w;
    w.tire.outer_radius = 0.35;
    w.tire.inner_radius = 0.22;
    w.tire.mass = 8;
    w.tire.segments = 24;
    w.axle.point = {x, -0.3};
    v.wheels.push_back(w);
  }
  return v;
}

World flat_ground(const SolverConfig& config, Vec2 gravity = {0, -9.81}) {
  World world(config, gravity);
  world.add_obstacle({{{-300, -10}, {300, 0}}});
  return world;
}

SolverConfig awake(int substeps = 2) {
  SolverConfig c;
  c.sleep = false;
  c.substeps = substeps;
  return c;
}

const Tire& wheel(const World& world, std::uint32_t v, std::size_t w) {
  return world.tires()[world.vehicles().wheel_tire(v, w)];
}

// How far wheel w's hub (the mean of its rim) is from its axle point on the chassis.
double hub_offset(const World& world, std::uint32_t v, std::size_t w, const VehicleSpec& spec) {
  const Tire& t = wheel(world, v, w);
  const PropState chassis = world.rigid().prop_state(world.vehicles().chassis(v));
  return length(vehicle_rows::rim_hub(t.particles, t.n, false) -
                chassis.pose.to_world(spec.wheels[w].axle.point));
}

// Along wheel w's suspension axis, how far its hub is from its axle point (m; + is up the axis).
double hub_along(const World& world, std::uint32_t v, std::size_t w, const VehicleSpec& spec) {
  const Tire& t = wheel(world, v, w);
  return vehicle_rows::stroke(t.particles, t.n, world.rigid().prop_state(world.vehicles().chassis(v)).pose,
                              spec.wheels[w].axle);
}

// The ground's force on a wheel (N): its contacts' normal multipliers, λ_n m / h².
double ground_force(const World& world, const Tire& t) {
  double lambda = 0.0;
  for (std::uint32_t i = 0; i < 2 * t.n; ++i)
    if (t.contacts[i].active) lambda += t.contacts[i].lambda_n;
  const double h = world.config().dt / world.tick_substeps();
  return t.particle_mass() * lambda / (h * h);
}

// The vehicle's angular momentum about the origin (kg m²/s): its wheels' particles and its chassis.
double angular_momentum(const World& world, std::uint32_t v) {
  double l = 0.0;
  for (std::size_t w = 0; w < world.vehicles().wheel_count(v); ++w) {
    const Tire& t = wheel(world, v, w);
    for (std::size_t i = 0; i < t.particles.size(); ++i)
      l += t.particle_mass() * cross(t.particles.x[i], t.particles.v[i]);
  }
  const PropState c = world.rigid().prop_state(world.vehicles().chassis(v));
  return l + c.inertia * c.angular_velocity + c.mass * cross(c.center, c.velocity);
}

}  // namespace

TEST_CASE("vehicles: the joints' gradients are their values' derivatives", "[unit][vehicles]") {
  World world = flat_ground(awake());
  const TireId id = world.add_tire(tire_at({0.3, 2.0}));
  run(world, 3);  // a substep's start (x_prev) apart from x
  Tire& t = *world.find_tire(id);
  const std::uint32_t n = t.n;
  std::vector<double> g(GlobalSolver::dof(2 * n - 1, n) + 2, 0.0);
  const double eps = 1e-6;
  const auto dx = [&](std::uint32_t i, int c) -> double& {
    return c == 0 ? t.particles.x[i].x : t.particles.x[i].y;
  };
  SECTION("the axle's rows, d·hub") {
    const Vec2 d{0.6, -0.8};  // unit
    vehicle_rows::hub_gradient(n, d, g.data());
    for (std::uint32_t i = 0; i < 2 * n; ++i)
      for (int c = 0; c < 2; ++c) {
        const double before = dot(d, vehicle_rows::rim_hub(t.particles, n, false));
        dx(i, c) += eps;
        const double after = dot(d, vehicle_rows::rim_hub(t.particles, n, false));
        dx(i, c) -= eps;
        CHECK(g[GlobalSolver::dof(i, n) + static_cast<std::size_t>(c)] ==
              Approx((after - before) / eps).margin(1e-7));
      }
  }
  SECTION("the motor's row, the wheel's turn") {
    const vehicle_rows::TurnFrame f = vehicle_rows::turn_frame(t.particles);
    vehicle_rows::turn_gradient(t.particles, f, n, g.data());
    for (std::uint32_t i = 0; i < 2 * n; ++i)
      for (int c = 0; c < 2; ++c) {
        const double before = vehicle_rows::wheel_turn(t.particles, f);
        dx(i, c) += eps;
        const double after = vehicle_rows::wheel_turn(t.particles, f);
        dx(i, c) -= eps;
        CHECK(g[GlobalSolver::dof(i, n) + static_cast<std::size_t>(c)] ==
              Approx((after - before) / eps).margin(1e-6));
      }
    // Its force is a pure torque: the gradient sums to no force, and a rigid turn by δ reads δ.
    Vec2 sum;
    for (std::uint32_t i = 0; i < 2 * n; ++i)
      sum += Vec2{g[GlobalSolver::dof(i, n)], g[GlobalSolver::dof(i, n) + 1]};
    CHECK(length(sum) < 1e-9);
    const double delta = 0.3;
    const CosSin cs = cos_sin(delta);
    for (std::uint32_t i = 0; i < 2 * n; ++i) {
      const Vec2 r = t.particles.x_prev[i] - f.centroid;
      t.particles.x[i] =
          f.centroid + Vec2{0.1, -0.2} + Vec2{cs.cos * r.x - cs.sin * r.y, cs.sin * r.x + cs.cos * r.y};
    }
    CHECK(vehicle_rows::wheel_turn(t.particles, f) == Approx(delta).epsilon(1e-12));
  }
}

TEST_CASE("vehicles: a car at rest loads each tire with its share of the weight", "[unit][vehicles]") {
  const int substeps = GENERATE(2, 8);
  World world = flat_ground(awake(substeps));
  // The chassis' centre of mass 0.6 m behind the front axle and 0.9 m ahead of the rear one.
  const VehicleSpec spec = car({0.0, 0.7}, 0.9, 0.6);
  const std::uint32_t v = *world.add_vehicle(spec);
  run(world, 180);
  const double g = 9.81, chassis = 1.6 * 0.3 * 100, tire = 8;
  const double rear = chassis * g * 0.6 / 1.5 + tire * g, front = chassis * g * 0.9 / 1.5 + tire * g;
  const double measured_rear = ground_force(world, wheel(world, v, 0));
  const double measured_front = ground_force(world, wheel(world, v, 1));
  INFO(substeps << " substeps: rear " << measured_rear << " N (statics " << rear << "), front "
                << measured_front << " N (" << front << ")");
  CHECK(measured_rear == Approx(rear).epsilon(0.02));
  CHECK(measured_front == Approx(front).epsilon(0.02));
  for (std::size_t w = 0; w < 2; ++w) CHECK(hub_offset(world, v, w, spec) < 1e-3);
}

TEST_CASE("vehicles: a sprung axle sags by its load over its stiffness", "[unit][vehicles]") {
  // Hooke's law along the suspension's axis: at rest the chassis sinks on each axle by F/k, its hub
  // F/k above the axle point, F the chassis' share of the weight on that axle (the axle presses the
  // hub down with it), k the spring; damping changes nothing at rest.
  const int substeps = GENERATE(2, 8);
  World world = flat_ground(awake(substeps));
  VehicleSpec spec = car({0.0, 0.7}, 0.9, 0.6);
  for (WheelSpec& w : spec.wheels) {
    w.axle.stiffness = 6000;
    w.axle.damping = 300;
  }
  const std::uint32_t v = *world.add_vehicle(spec);
  run(world, 240);
  const double g = 9.81, mass = 1.6 * 0.3 * 100;
  const double shares[2] = {mass * g * 0.6 / 1.5, mass * g * 0.9 / 1.5};  // rear, front
  for (std::size_t w = 0; w < 2; ++w) {
    const double along = hub_along(world, v, w, spec);
    INFO(substeps << " substeps, wheel " << w << ": hub " << along * 1e3 << " mm along the axis, Hooke "
                  << shares[w] / 6000 * 1e3 << " mm; axle force " << world.vehicles().axle_force(v, w).y
                  << " N");
    CHECK(along == Approx(shares[w] / 6000).epsilon(0.02));
    CHECK(world.vehicles().axle_force(v, w).y == Approx(-shares[w]).epsilon(0.02));
  }
}

TEST_CASE("vehicles: a sprung car dropped stays within its suspension's travel", "[unit][vehicles]") {
  // Soft springs (a 48 kg chassis sags 59 mm on them at rest) and a drop of 1.5 m: unlimited, the
  // hubs go 300 mm along their axes as it lands. With a travel of 80 mm they stop there, within the
  // rigid rows' give, and come back off the stop: the limit only pushes (at rest, 59 mm is inside
  // it, and the spring carries the whole load); the landing makes no energy. The axis written up
  // the chassis meets the top of the travel; written down it, the same load meets the bottom.
  const int substeps = GENERATE(1, 2, 8);
  const double up = GENERATE(1.0, -1.0);
  const double travel = 0.08;
  struct Drop {
    double farthest = 0.0;  // the most either hub went along its axis (m)
    double rest[2] = {};    // each hub along its axis at the end
    double gain = 0.0;      // the most energy made (J)
  };
  const auto drop = [&](double limit) {
    World world = flat_ground(awake(substeps));
    VehicleSpec spec = car({0.0, 2.2});
    for (WheelSpec& w : spec.wheels) {
      w.axle.axis = {0.0, up};
      w.axle.stiffness = 4000;
      w.axle.damping = 150;
      w.axle.travel = limit;
    }
    const std::uint32_t v = *world.add_vehicle(spec);
    const double start = world_energy(world).total() - world.energy_in();
    Drop d;
    for (int tick = 0; tick < 240; ++tick) {
      world.step({});
      for (std::size_t w = 0; w < 2; ++w)
        d.farthest = std::max(d.farthest, std::abs(hub_along(world, v, w, spec)));
      d.gain = std::max(d.gain, world_energy(world).total() - world.energy_in() - start);
    }
    for (std::size_t w = 0; w < 2; ++w) d.rest[w] = hub_along(world, v, w, spec);
    return d;
  };
  const Drop free = drop(0.0), limited = drop(travel);
  const double sag = 1.6 * 0.3 * 100 * 9.81 / 2 / 4000;  // each axle's share over its stiffness
  INFO(substeps << " substeps, axis " << up << ": unlimited, the hubs went " << free.farthest * 1e3
                << " mm along their axes; with " << travel * 1e3 << " mm of travel, "
                << limited.farthest * 1e3 << " mm; at rest " << limited.rest[0] * 1e3 << " and "
                << limited.rest[1] * 1e3 << " mm (Hooke " << sag * 1e3 << " mm, unlimited "
                << free.rest[0] * 1e3 << "); energy made " << limited.gain << " J");
  CHECK(free.farthest > 2.0 * travel);  // the case: the drop goes well past the travel
  CHECK(limited.farthest < travel + 1e-3);
  for (std::size_t w = 0; w < 2; ++w) {
    CHECK(limited.rest[w] == Approx(free.rest[w]).epsilon(0.01));
    CHECK(limited.rest[w] * up == Approx(sag).epsilon(0.03));
  }
  CHECK(limited.gain < 1.0);
}

TEST_CASE("vehicles: parked on a 15 degree slope with the brake on, a car stays put", "[unit][vehicles]") {
  const double slope = 15.0 * std::numbers::pi / 180.0;
  World world = flat_ground(awake(), {-9.81 * std::sin(slope), -9.81 * std::cos(slope)});  // downhill is −x
  const std::uint32_t v = *world.add_vehicle(car({0.0, 0.66}));
  VehicleControl brake;
  brake.brake = true;
  world.set_vehicle_control(v, brake);
  run(world, 60);
  const Vec2 before = world.rigid().prop_state(world.vehicles().chassis(v)).center;
  run(world, 600);
  const Vec2 after = world.rigid().prop_state(world.vehicles().chassis(v)).center;
  INFO("moved " << length(after - before) * 1e3 << " mm in 10 s");
  CHECK(length(after - before) < 0.01);
  // Without the brake it rolls away.
  world.set_vehicle_control(v, {});
  run(world, 120);
  CHECK(world.rigid().prop_state(world.vehicles().chassis(v)).center.x < after.x - 1.0);
}

TEST_CASE("vehicles: the motor's torque and its reaction keep the vehicle's angular momentum",
          "[unit][vehicles]") {
  // In the air without gravity, full throttle for half a second: the motors give the wheels 60 kg
  // m²/s of spin and the chassis as much the other way; nothing outside the vehicle torques it. At
  // one substep the refinement (World::update_refinement) steps the tick finer as the wheels spin
  // up: unrefined, a wheel at 35 rad/s answered the motor's linear row less than its gradient
  // says, its spokes' tension resisting the turn, and the vehicle gained 5 % of what the motor gave.
  const int substeps = GENERATE(1, 2, 4, 8);
  World world(awake(substeps), {0.0, 0.0});
  const std::uint32_t v = *world.add_vehicle(car({1.0, 3.0}));
  const double before = angular_momentum(world, v);
  VehicleControl full;
  full.throttle = 1.0;
  world.set_vehicle_control(v, full);
  double worst = 0.0;
  for (int tick = 0; tick < 30; ++tick) {
    world.step({});
    worst = std::max(worst, std::abs(angular_momentum(world, v) - before));
  }
  const double spun = 2 * world.vehicles().drivetrain(v).motor_torque * 0.5;  // two wheels' τ t
  const double spin = wheel(world, v, 0).rigid_motion().omega;
  const PropState chassis = world.rigid().prop_state(world.vehicles().chassis(v));
  INFO(substeps << " substeps: wheel spin " << spin << " rad/s, chassis " << chassis.angular_velocity
                << " rad/s, angular momentum off by at most " << worst << " kg m²/s of " << spun);
  CHECK(spin < -20.0);                    // the motor turned the wheels forward (clockwise)
  CHECK(chassis.angular_velocity > 2.0);  // and the chassis the other way
  CHECK(worst < 1e-3 * spun);
}

TEST_CASE("vehicles: a car dropped and flipped gains no energy", "[unit][vehicles]") {
  const int substeps = GENERATE(1, 2, 4, 8);
  World world = flat_ground(awake(substeps));
  VehicleSpec spec = car({0.0, 2.5});
  spec.chassis.angle = 2.4;
  spec.chassis.angular_velocity = 3.0;
  spec.chassis.velocity = {2.0, 0.0};
  world.add_vehicle(spec);
  const double start = world_energy(world).total() - world.energy_in();
  double gain = 0.0;
  for (int tick = 0; tick < 300; ++tick) {
    world.step({});
    gain = std::max(gain, world_energy(world).total() - world.energy_in() - start);
  }
  INFO(substeps << " substeps: most energy made " << gain << " J");
  CHECK(gain < 1.0);
}

TEST_CASE("vehicles: a car dropped with its motor flat out makes no energy", "[unit][vehicles]") {
  // Its wheels spin up to 40 rad/s in the air under the motor, and it lands on them still driven
  // (and flips over backwards, as a car landing on wheels that fast does). At one substep that
  // turn, 0.67 rad a substep, is more than the motor's linear row holds: the refinement keeps it
  // within refine_turn (World::update_refinement); without that rule the wheels held 4.2 kJ for a
  // tick as the car flew.
  const int substeps = GENERATE(1, 2);
  World world = flat_ground(awake(substeps));
  world.set_player_vehicle(*world.add_vehicle(car({0.0, 3.0})));
  const double start = world_energy(world).total() - world.energy_in();
  double gain = 0.0, spin = 0.0;
  TickInput throttle;
  throttle.steer = 1.0;
  for (int tick = 0; tick < 150; ++tick) {
    world.step(throttle);
    gain = std::max(gain, world_energy(world).total() - world.energy_in() - start);
    spin = std::max(spin, std::abs(wheel(world, 0, 0).angular_velocity()));
  }
  INFO(substeps << " substeps: most energy made " << gain << " J of " << world.energy_in()
                << " J brought in");
  CHECK(spin > 30.0);  // the case: the motor spun the wheels up in the air
  CHECK(gain < 0.01 * world.energy_in());
}

TEST_CASE("vehicles: driven flat out over bumps, a hub stays on its axle", "[unit][vehicles]") {
  World world = flat_ground(awake());
  for (int k = 0; k < 12; ++k) world.add_obstacle({{{4.0 + 3.0 * k, 0.0}, {4.4 + 3.0 * k, 0.08}}});
  // A 96 kg chassis: the 48 kg one, flat out, lifts its nose over the bumps and flips onto its roof,
  // as a strong motor under a light car does.
  VehicleSpec spec = car({0.0, 0.7});
  spec.chassis.density = 200;
  const std::uint32_t v = *world.add_vehicle(spec);
  VehicleControl full;
  full.throttle = 1.0;
  world.set_vehicle_control(v, full);
  double worst = 0.0, tilt = 0.0;
  for (int tick = 0; tick < 360; ++tick) {
    world.step({});
    for (std::size_t w = 0; w < 2; ++w) worst = std::max(worst, hub_offset(world, v, w, spec));
    tilt = std::max(tilt, std::abs(world.rigid().prop_state(world.vehicles().chassis(v)).pose.angle));
  }
  const PropState chassis = world.rigid().prop_state(world.vehicles().chassis(v));
  INFO("at x = " << chassis.center.x << " m, " << chassis.velocity.x << " m/s, tilted at most " << tilt
                 << " rad; hub off its axle by at most " << worst * 1e3 << " mm");
  CHECK(chassis.center.x > 15.0);  // over five bumps
  CHECK(tilt < 1.0);
  CHECK(worst < 0.01);
}

TEST_CASE("vehicles: a parked car sleeps as it rests awake, and wakes to its controls", "[unit][vehicles]") {
  // A vehicle sleeps as one island, its chassis with its wheels (world/sleep_islands.h), once all
  // are still; asleep it keeps the pose it would rest in awake (docs/vehicles.md).
  SolverConfig sleeping;  // the default: sleep on
  World world = flat_ground(sleeping);
  World reference = flat_ground(awake());
  const std::uint32_t v = *world.add_vehicle(car({0.0, 0.7}));
  reference.add_vehicle(car({0.0, 0.7}));
  run(world, 600);
  run(reference, 600);
  const std::uint32_t c = world.vehicles().chassis(v);
  CHECK(world.asleep_count() == 2);
  CHECK(!world.rigid().prop_state(c).awake);
  const PropState rest = world.rigid().prop_state(c), settled = reference.rigid().prop_state(c);
  INFO("chassis asleep " << rest.center.y << " m, awake " << settled.center.y << " m");
  CHECK(length(rest.center - settled.center) < 1e-5);
  CHECK(std::abs(rest.pose.angle - settled.pose.angle) < 1e-6);
  for (std::size_t w = 0; w < 2; ++w)
    CHECK(length(wheel(world, v, w).centroid() - wheel(reference, v, w).centroid()) < 1e-5);

  // The brake alone lets it sleep; throttle wakes it and drives it.
  VehicleControl brake;
  brake.brake = true;
  world.set_vehicle_control(v, brake);
  run(world, 120);
  CHECK(world.asleep_count() == 2);
  VehicleControl throttle;
  throttle.throttle = 1.0;
  world.set_vehicle_control(v, throttle);
  run(world, 60);
  CHECK(world.asleep_count() == 0);
  CHECK(world.rigid().prop_state(c).center.x > 1.0);
}

TEST_CASE("vehicles: parked asleep on a slope, a car rolls away when its brake is let go",
          "[unit][vehicles]") {
  const double slope = 15.0 * std::numbers::pi / 180.0;
  World world = flat_ground(SolverConfig{}, {-9.81 * std::sin(slope), -9.81 * std::cos(slope)});
  const std::uint32_t v = *world.add_vehicle(car({0.0, 0.66}));
  VehicleControl brake;
  brake.brake = true;
  world.set_vehicle_control(v, brake);
  run(world, 300);
  REQUIRE(world.asleep_count() == 2);
  const double parked = world.rigid().prop_state(world.vehicles().chassis(v)).center.x;
  world.set_vehicle_control(v, {});  // nothing drives it: the change alone wakes it
  run(world, 120);
  CHECK(world.rigid().prop_state(world.vehicles().chassis(v)).center.x < parked - 1.0);
}

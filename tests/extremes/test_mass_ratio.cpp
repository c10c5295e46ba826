// Tire-to-prop mass ratios from 1:1000 to 1000:1, both ways round: a dynamic box falling on a
// resting tire, and a tire falling on a resting box.
//
// The heavier body is always 10 kg (the default tire's mass) and the lighter one 10 kg divided by
// the ratio, down to 10 g. That keeps every load within what the default tire carries (at most
// 98 N on it), so the grid tests the solver's conditioning (a 0.18 g particle against a 10 kg
// box, a 0.18 kg particle against a 10 g box) rather than the crushing of the tire, which the
// crush case covers with 1000 kg.
//
// Besides the whole-system energy, each case bounds the box's own speed (see LaunchWatch): a light
// body can be given energy the whole-system sum does not show, when the heavy one has just lost
// more than that in an inelastic landing.
#include "extremes.h"

using namespace tire;
using namespace tire::extremes;

namespace {

struct Ratio {
  const char* label;
  double tire;  // kg
  double prop;  // kg
};

constexpr Ratio kRatios[] = {{"1:1000", 0.01, 10.0}, {"1:100", 0.1, 10.0}, {"1:10", 1.0, 10.0},
                             {"1:1", 10.0, 10.0},    {"10:1", 10.0, 1.0},  {"100:1", 10.0, 0.1},
                             {"1000:1", 10.0, 0.01}};

double top_of(const Tire& t) {
  double top = -kInf;
  for (const Vec2& x : t.particles.x) top = std::max(top, x.y);
  return top;
}

// Deepest any tire particle sits inside box prop `i` of full size `size` (0 when none is inside).
double depth_in_box(const World& world, std::uint32_t i, Vec2 size) {
  const Pose pose = world.rigid().current_pose(i);
  double deepest = 0.0;
  for (const Tire& t : world.tires())
    for (const Vec2& x : t.particles.x) {
      const Vec2 l = pose.to_local(x);
      deepest = std::max(deepest, std::min(0.5 * size.x - std::abs(l.x), 0.5 * size.y - std::abs(l.y)));
    }
  return deepest;
}

double fastest_particle(const Tire& t) {
  double v = 0.0;
  for (const Vec2& u : t.particles.v) v = std::max(v, length(u));
  return v;
}

// The rigid box has no energy of its own to give: its speed comes from gravity and from being
// struck by the tire. Struck at a point moving at u (relative), a body's centre of mass gains at
// most 2u (a perfectly elastic hit by an infinitely heavy striker; the point's own speed change
// J(1/M + (r×n)²/I) bounds the centre's J/M). So at every tick
//   |v_box|² ≤ (2·u_max + 0.1 m/s)² + 2 g (y_highest − y),
// u_max the fastest tire particle so far, y_highest the box's highest centre so far. A box faster
// than that got energy from the solver: the light-body form of "no energy gain", which the whole-
// system sum can hide when the heavy body has just lost more than that in an inelastic landing.
struct LaunchWatch {
  double u_max = 0.0;
  double y_highest = -kInf;
  double worst_excess = -kInf;  // max over ticks of |v_box| − bound (m/s)
  double speed_at_worst = 0.0, bound_at_worst = 0.0;
  double time_at_worst = 0.0;
  std::uint64_t tick_at_worst = 0;
  double box_peak_speed = 0.0;
  double deepest = 0.0;  // deepest tire particle inside the box at a tick's end (m)

  void observe(const World& world, Vec2 size) {
    const Tire& t = world.tires().front();
    u_max = std::max(u_max, fastest_particle(t));
    const double y = world.rigid().current_pose(0).position.y;
    y_highest = std::max(y_highest, y);
    const double speed = length(world.rigid().current_velocity(0));
    box_peak_speed = std::max(box_peak_speed, speed);
    const double g = -world.gravity().y;
    const double bound = std::sqrt(std::pow(2.0 * u_max + 0.1, 2) + 2.0 * g * std::max(0.0, y_highest - y));
    if (speed - bound > worst_excess)
      worst_excess = speed - bound, speed_at_worst = speed, bound_at_worst = bound,
      time_at_worst = world.time(), tick_at_worst = world.tick();
    deepest = std::max(deepest, depth_in_box(world, 0, size));
  }
  std::string text() const {
    return "box peak speed " + fmt("%.3g", box_peak_speed) +
           " m/s; worst vs launch bound: " + fmt("%.3g", speed_at_worst) + " m/s against " +
           fmt("%.3g", bound_at_worst) + " m/s at t=" + fmt("%.3f", time_at_worst) +
           " s; deepest tire particle inside the box " + fmt("%.3f", deepest) + " m";
  }
};

}  // namespace

TEST_CASE("a box from 1000 times heavier to 1000 times lighter than the tire falls on it without instability",
          "[extremes][mass]") {
  // The tire rests on the ground for 1 s; then a 0.8 m × 0.4 m box is dropped from 0.3 m above its
  // top, 0.1 m off centre (so that it rolls off onto the ground), and both are watched for 4 s.
  // Energy scale: E(0) when the box appears (tire + box, ground-referenced; the settled tire's
  // residual strain is not counted as stored energy, see Probe).
  // Area bounds [0.2, 3] from 1 s after the drop: at most 98 N of box on a default tire.
  for (const Ratio& r : kRatios) {
    TireSpec spec = tire_spec({0, 0.5});
    spec.mass = r.tire;
    World world = ground_world();
    world.add_tire(spec);
    test::run(world, 60);
    const double top = top_of(world.tires().front());
    world.add_prop(box_prop("box", {0.1, top + 0.3 + 0.2}, {0.8, 0.4}, r.prop));
    Probe probe(std::string("tire:prop ") + r.label + " (tire " + fmt("%g", r.tire) + " kg, box " +
                    fmt("%g", r.prop) + " kg), box falls on a resting tire",
                world, AreaBounds{0.2, 3.0, world.time() + 1.0});
    LaunchWatch watch;
    watch.observe(world, {0.8, 0.4});
    double tire_peak_speed = 0.0;
    for (int i = 0; i < ticks_for(4.0, world.config()); ++i) {
      probe.step(1);
      watch.observe(world, {0.8, 0.4});
      tire_peak_speed = std::max(tire_peak_speed, length(world.tires().front().velocity()));
    }
    probe.note("box final y " + fmt("%.3f", world.rigid().current_pose(0).position.y) +
               " m, tire hub peak speed " + fmt("%.3g", tire_peak_speed) + " m/s, " + watch.text());
    probe.mark(watch.tick_at_worst);
    const bool printed = !probe.judge();
    INFO(probe.line());
    CHECK(watch.worst_excess <= 0.0);  // the box never outran what gravity and the tire could give it
    if (watch.worst_excess > 0.0 && !printed) probe.print_timeline();
  }
}

TEST_CASE(
    "a tire from 1000 times lighter to 1000 times heavier than a resting box falls on it without instability",
    "[extremes][mass]") {
  // A 2 m × 0.5 m box settles on the ground for 1 s (Box2D alone); then a tire is dropped with its
  // bottom 0.5 m above the box's top, and both are watched for 4 s.
  // Energy scale: E(0) when the tire appears (tire + box, ground-referenced).
  // Area bounds [0.2, 3] from 1 s after the drop: the tire only carries its own weight.
  for (const Ratio& r : kRatios) {
    World world = ground_world();
    world.add_prop(box_prop("box", {0, 0.25 + 0.015}, {2.0, 0.5}, r.prop));
    test::run(world, 60);
    const double top = world.rigid().current_pose(0).position.y + 0.25;
    TireSpec spec = tire_spec({0, top + 0.5 + 0.5});
    spec.mass = r.tire;
    world.add_tire(spec);
    Probe probe(std::string("tire:prop ") + r.label + " (tire " + fmt("%g", r.tire) + " kg, box " +
                    fmt("%g", r.prop) + " kg), tire falls on a resting box",
                world, AreaBounds{0.2, 3.0, world.time() + 1.0});
    LaunchWatch watch;
    watch.observe(world, {2.0, 0.5});
    for (int i = 0; i < ticks_for(4.0, world.config()); ++i) {
      probe.step(1);
      watch.observe(world, {2.0, 0.5});
    }
    const Tire& t = world.tires().front();
    probe.note("tire final hub y " + fmt("%.3f", t.centroid().y) + " m (box top " + fmt("%.3f", top) +
               "), tire final speed " + fmt("%.2g", length(t.velocity())) + " m/s, " + watch.text());
    probe.mark(watch.tick_at_worst);
    const bool printed = !probe.judge();
    INFO(probe.line());
    CHECK(watch.worst_excess <= 0.0);  // the box never outran what gravity and the tire could give it
    if (watch.worst_excess > 0.0 && !printed) probe.print_timeline();
  }
}

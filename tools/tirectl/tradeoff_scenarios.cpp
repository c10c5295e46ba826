#include "tradeoff_scenarios.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace tirectl {

namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kGravity = 9.81;
constexpr double kSlopeDegrees = 20.0;
constexpr double kSlopeLength = 12.0;  // m of slope surface below the tire's start
constexpr double kCrushMass = 300.0;   // kg
constexpr tire::Vec2 kCrushBoxSize{1.0, 0.4};
constexpr double kCrushClearance = 0.02;  // m between the box and each wall of its slot
constexpr double kCrushDrop = 0.02;       // m between the box and the tire at the start
constexpr double kSoftFactor = 100.0;     // rest-soft: compliances times this

// The default tire (TireSpec{}), R = 0.5 m.
double radius() { return tire::TireSpec{}.outer_radius; }

// Hub height of an undeformed tire resting on a flat segment: R·cos(π/N).
double rest_height(int segments) { return radius() * std::cos(std::numbers::pi / segments); }

tire::Obstacle box(tire::Vec2 min, tire::Vec2 max) { return {{min, max}}; }

tire::TireSpec placed(const tire::TireSpec& base, tire::Vec2 position) {
  tire::TireSpec s = base;
  s.position = position;
  return s;
}

void add_ground(tire::Simulation& world) { world.add_obstacle(box({-50.0, -1.0}, {50.0, 0.0})); }

// Mean of the last half second is taken by the caller; this reads one tick.
double rest_deflection(const tire::Simulation& world) {
  const tire::TireView t = *world.tire_at(0);
  return rest_height(static_cast<int>(t.segments)) - t.centroid.y;
}

// Height of the undeformed tire standing on its flat bottom segment: a flat top segment too for
// even N, a vertex on top for odd N.
double built_height(int segments) {
  return rest_height(segments) + (segments % 2 == 0 ? rest_height(segments) : radius());
}

// The tire's height as built less the height of the box's bottom face above the ground.
double crush_deflection(const tire::Simulation& world) {
  const tire::TireView t = *world.tire_at(0);
  const tire::Pose pose = world.prop(0)->state.pose;  // the box's centre
  return built_height(static_cast<int>(t.segments)) - (pose.position.y - 0.5 * kCrushBoxSize.y);
}

TradeoffScenario scenario(std::string name, std::string what, int ticks,
                          std::function<void(tire::Simulation&, const tire::TireSpec&)> populate) {
  TradeoffScenario s;
  s.name = std::move(name);
  s.what = std::move(what);
  s.ticks = ticks;
  s.populate = std::move(populate);
  return s;
}

std::vector<TradeoffScenario> make_scenarios() {
  std::vector<TradeoffScenario> list;
  const double weight = tire::TireSpec{}.mass * kGravity;

  {
    TradeoffScenario s = scenario("rest", "tire set down on flat ground, settles under its own weight (3 s)",
                                  180, [](tire::Simulation& world, const tire::TireSpec& base) {
                                    add_ground(world);
                                    world.add_tire(placed(base, {0.0, rest_height(base.segments)}));
                                  });
    s.deflection = rest_deflection;
    s.load = weight;
    s.ref_substeps = 1024;
    s.ref_iterations = 4;
    list.push_back(s);
  }
  {
    TradeoffScenario s = scenario(
        "rest-soft", "as rest, with every compliance 100 times the default (a 100 times softer tire) (3 s)",
        180, [](tire::Simulation& world, const tire::TireSpec& base) {
          add_ground(world);
          tire::TireSpec t = placed(base, {0.0, rest_height(base.segments)});
          t.compliance.outer *= kSoftFactor;
          t.compliance.inner *= kSoftFactor;
          t.compliance.spoke *= kSoftFactor;
          t.compliance.pressure *= kSoftFactor;
          world.add_tire(t);
        });
    s.deflection = rest_deflection;
    s.load = weight;
    s.ref_substeps = 1024;
    s.ref_iterations = 4;
    list.push_back(s);
  }
  {
    TradeoffScenario s = scenario("drop", "tread released 1.5 m above flat ground, falls and bounces (3 s)",
                                  180, [](tire::Simulation& world, const tire::TireSpec& base) {
                                    add_ground(world);
                                    world.add_tire(placed(base, {0.0, 1.5 + rest_height(base.segments)}));
                                  });
    s.decides = false;
    list.push_back(s);
  }
  {
    const double slope = kSlopeDegrees * std::numbers::pi / 180.0;
    TradeoffScenario s = scenario(
        "slope", "tire released at rest on a 20 degree slope (a rotated static Box2D box), rolls down (2 s)",
        120, [slope](tire::Simulation& world, const tire::TireSpec& base) {
          const tire::Vec2 down{std::cos(slope), -std::sin(slope)};
          const tire::Vec2 normal{std::sin(slope), std::cos(slope)};
          tire::PropSpec p;
          p.name = "slope";
          p.shape = tire::PropShape::box;
          p.type = tire::PropType::static_body;
          p.size = {kSlopeLength + 2.0, 1.0};
          p.angle = -slope;
          p.position = down * (0.5 * kSlopeLength - 1.0) - normal * 0.5;  // top face through (0, 0)
          world.add_prop(p);
          tire::TireSpec t = placed(base, normal * rest_height(base.segments));
          t.angle = -slope;  // a tread segment flat on the slope
          world.add_tire(t);
        });
    s.datum_y = -kSlopeLength * std::sin(slope);
    list.push_back(s);
  }
  {
    TradeoffScenario s = scenario(
        "crush", "a 300 kg Box2D box dropped 2 cm onto a resting tire, in a slot that keeps it level (3 s)",
        180, [](tire::Simulation& world, const tire::TireSpec& base) {
          add_ground(world);
          // A slot a little wider than the box keeps it from tipping off the round tire.
          const double gap = 0.5 * kCrushBoxSize.x + kCrushClearance;
          world.add_obstacle(box({-gap - 0.5, 0.0}, {-gap, 3.0}));
          world.add_obstacle(box({gap, 0.0}, {gap + 0.5, 3.0}));
          world.add_tire(placed(base, {0.0, rest_height(base.segments)}));
          tire::PropSpec p;
          p.name = "weight";
          p.shape = tire::PropShape::box;
          p.type = tire::PropType::dynamic_body;
          p.size = kCrushBoxSize;
          p.density = kCrushMass / (kCrushBoxSize.x * kCrushBoxSize.y);
          p.position = {0.0, built_height(base.segments) + kCrushDrop + 0.5 * kCrushBoxSize.y};
          world.add_prop(p);
        });
    s.deflection = crush_deflection;
    s.load = kCrushMass * kGravity;
    s.dynamic_props = true;
    // The tire–prop coupling turns unstable from about 1024 substeps (docs/accuracy.md), so the reference
    // stays below that and makes up with iterations.
    s.ref_substeps = 256;
    s.ref_iterations = 8;
    list.push_back(s);
  }
  {
    TradeoffScenario s =
        scenario("impact", "tire thrown at 20 m/s into a box wall 5.5 m away, bounces back and lands (1.5 s)",
                 90, [](tire::Simulation& world, const tire::TireSpec& base) {
                   add_ground(world);
                   world.add_obstacle(box({6.0, 0.0}, {7.0, 4.0}));
                   tire::TireSpec t = placed(base, {0.0, 1.2});
                   t.velocity = {20.0, 0.0};
                   t.max_speed = 30.0;  // the default caps the hub at 15 m/s
                   world.add_tire(t);
                 });
    s.decides = false;
    list.push_back(s);
  }
  return list;
}

}  // namespace

const std::vector<TradeoffScenario>& tradeoff_scenarios() {
  static const std::vector<TradeoffScenario> list = make_scenarios();
  return list;
}

tire::Simulation build_world(const TradeoffScenario& scenario, const SolverSettings& settings) {
  tire::SolverConfig config;
  config.dt = kDt;
  config.substeps = settings.substeps;
  config.iterations = settings.iterations;
  config.tunnel_clamp = settings.tunnel_clamp;
  config.method = settings.method;
  tire::Simulation world(config, {0.0, -kGravity});
  tire::TireSpec base;
  base.segments = settings.segments;
  base.material_damping = settings.material_damping;
  scenario.populate(world, base);
  return world;
}

double mechanical_energy(const tire::Simulation& world, double datum_y) {
  // The energy watch's kinetic and gravitational energy (zero at the origin), its potential moved
  // to the datum: less the weight of everything it counts times the datum's height.
  const tire::EnergyView e = world.energy();
  const double g = -world.gravity().y;
  double mass = 0.0;
  for (std::size_t i = 0; const std::optional<tire::TireView> t = world.tire_at(i); ++i) mass += t->mass;
  for (tire::PropId id = 0; id < world.prop_count(); ++id) {
    const tire::PropView p = *world.prop(id);
    if (p.alive && p.type == tire::PropType::dynamic_body) mass += p.state.mass;
  }
  return e.kinetic + e.gravitational - mass * g * datum_y;
}

RunMeasure measure_run(const TradeoffScenario& scenario, const SolverSettings& settings) {
  tire::Simulation world = build_world(scenario, settings);
  const tire::TireId tire = world.tires().front();
  RunMeasure m;
  m.centroid.reserve(static_cast<std::size_t>(scenario.ticks) + 1);
  m.centroid.push_back(world.tire(tire)->centroid);
  m.energy_start = mechanical_energy(world, scenario.datum_y);
  const int tail = std::min(scenario.ticks, 30);  // the last half second
  double deflection_sum = 0.0;
  std::chrono::duration<double, std::micro> stepping{0.0};
  const tire::TickInput input{};
  for (int tick = 0; tick < scenario.ticks; ++tick) {
    const auto start = std::chrono::steady_clock::now();
    world.step(input);
    stepping += std::chrono::steady_clock::now() - start;
    m.resets += static_cast<int>(world.take_warnings().size());
    const tire::TireView t = *world.tire(tire);
    m.centroid.push_back(t.centroid);
    m.peak_strain = std::max(m.peak_strain, *world.tire_strain(tire));
    m.area_error = std::max(m.area_error, std::abs(t.area_ratio - t.pressure));
    if (scenario.deflection && tick >= scenario.ticks - tail) deflection_sum += scenario.deflection(world);
  }
  m.energy_end = mechanical_energy(world, scenario.datum_y);
  m.us_per_step = stepping.count() / scenario.ticks;
  m.deflection = scenario.deflection ? deflection_sum / tail : std::numeric_limits<double>::quiet_NaN();
  return m;
}

namespace {

// What one steady_clock::now() costs (µs), measured once: the median of many back-to-back pairs.
double clock_cost_us() {
  static const double cost = [] {
    std::vector<double> d;
    for (int i = 0; i < 2001; ++i) {
      const auto a = std::chrono::steady_clock::now();
      const auto b = std::chrono::steady_clock::now();
      d.push_back(std::chrono::duration<double, std::micro>(b - a).count());
    }
    std::nth_element(d.begin(), d.begin() + 1000, d.end());
    return d[1000];
  }();
  return cost;
}

}  // namespace

std::vector<double> time_run(const TradeoffScenario& scenario, const SolverSettings& settings) {
  const double overhead = clock_cost_us();
  tire::Simulation world = build_world(scenario, settings);
  const tire::TickInput input{};
  std::vector<double> us(static_cast<std::size_t>(scenario.ticks));
  for (double& u : us) {
    const auto start = std::chrono::steady_clock::now();
    world.step(input);
    const auto end = std::chrono::steady_clock::now();
    u = std::max(0.0, std::chrono::duration<double, std::micro>(end - start).count() - overhead);
  }
  return us;
}

}  // namespace tirectl

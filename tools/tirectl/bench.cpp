// Performance scenes, timed with a monotonic clock outside the simulation. CSV on stdout.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "commands.h"
#include "process_memory.h"
#include "tire/engine.h"
#include "tire/io/file_io.h"

namespace tirectl {

namespace {

// Something that advances one fixed tick.
class Steppable {
 public:
  virtual ~Steppable() = default;
  virtual void step(const tire::TickInput& input) = 0;
  virtual std::size_t tire_count() const = 0;
  // The first tire's particles and segments.
  virtual std::size_t first_tire_particles() const = 0;
  virtual std::uint32_t first_tire_segments() const = 0;
  virtual const tire::SolverConfig& config() const = 0;
  virtual void set_threads(unsigned threads) = 0;
  virtual unsigned threads() const = 0;
  virtual void set_schedule(tire::StepSchedule schedule) = 0;
  // Particles in contact after the last step (with a surface or another tire), and candidate
  // tire pairs from the broad phase.
  virtual std::size_t contacts() const = 0;
  virtual std::size_t tire_pairs() const = 0;
  // Tires asleep now (SolverConfig::sleep).
  virtual std::size_t asleep() const = 0;
  // What the scene does to its world between two ticks (the crowd's re-drop), outside the timing.
  virtual void between_ticks() {}
};

// A scene built on a Simulation, as any program of the engine builds one (tire/engine.h).
class SimulationScene final : public Steppable {
 public:
  // `between`: what the scene does between ticks, if anything.
  explicit SimulationScene(tire::Simulation simulation,
                           std::function<void(tire::Simulation&)> between = nullptr)
      : simulation_(std::move(simulation)), between_(std::move(between)) {}
  void step(const tire::TickInput& input) override { simulation_.step(input); }
  std::size_t tire_count() const override { return simulation_.tire_count(); }
  std::size_t first_tire_particles() const override { return simulation_.tire_at(0)->positions.size(); }
  std::uint32_t first_tire_segments() const override { return simulation_.tire_at(0)->segments; }
  const tire::SolverConfig& config() const override { return simulation_.config(); }
  void set_threads(unsigned threads) override { simulation_.set_threads(threads); }
  void set_schedule(tire::StepSchedule schedule) override { simulation_.set_schedule(schedule); }
  unsigned threads() const override { return simulation_.threads(); }
  std::size_t contacts() const override { return simulation_.solver_report().touching_particles; }
  std::size_t tire_pairs() const override { return simulation_.solver_report().tire_pairs; }
  std::size_t asleep() const override { return simulation_.asleep_count(); }
  void between_ticks() override {
    if (between_) between_(simulation_);
  }

 private:
  tire::Simulation simulation_;
  std::function<void(tire::Simulation&)> between_;
};

// One tire and its ground, stepped by the tire solver alone: no world around it (no level, no
// divergence guard, no Box2D stepping, no refinement, nothing else; tire::BareTire), at the
// default settings, as "flat-level" is. Its floor.
class BareTireScene final : public Steppable {
 public:
  BareTireScene() : tire_(tire::SolverConfig{}, {0.0, -9.81}, spec(), {{{-50.0, -1.0}, {50.0, 0.0}}}) {}
  void step(const tire::TickInput& input) override { tire_.step(input); }
  std::size_t tire_count() const override { return 1; }
  std::size_t first_tire_particles() const override { return tire_.particle_count(); }
  std::uint32_t first_tire_segments() const override { return tire_.segments(); }
  const tire::SolverConfig& config() const override { return tire_.config(); }
  void set_threads(unsigned) override {}
  void set_schedule(tire::StepSchedule) override {}  // no world: the plain substep() loop already
  unsigned threads() const override { return 1; }
  std::size_t contacts() const override { return tire_.touching_particles(); }
  std::size_t tire_pairs() const override { return 0; }
  std::size_t asleep() const override { return tire_.asleep() ? 1 : 0; }

 private:
  static tire::TireSpec spec() {
    tire::TireSpec s;
    s.position = {0.0, 0.5};
    return s;
  }
  tire::BareTire tire_;
};

// The same tire and ground as a level file read by the loader, stepped by a Simulation: everything
// a level brings along (its bounds checked every tick), on the scene that needs none of it.
// Sleeping off: the solver's cost, as a resting tire would fall asleep.
constexpr const char* kFlatLevel = R"json({
  "name": "Flat (bench)",
  "solver": { "sleep": false },
  "tires": [ { "position": [0, 0.5] } ],
  "obstacles": [ { "min": [-50, -1], "max": [50, 0] } ]
})json";

// A scene's level text, read as a level file is; a scene the reader refuses is this program's fault.
std::unique_ptr<Steppable> level_scene(const char* text, const char* name) {
  tire::LevelOpen open = tire::open_level_text(text, name);
  if (!open.level) {
    for (const std::string& error : open.errors) std::fprintf(stderr, "%s\n", error.c_str());
    throw std::logic_error(std::string("tirectl bench: the scene ") + name + " does not load");
  }
  return std::make_unique<SimulationScene>(tire::Simulation(std::move(open.level)));
}

std::unique_ptr<Steppable> flat_level() { return level_scene(kFlatLevel, "flat-level"); }

// A walled pile: `count` default tires (28 segments, 8 substeps × 1 iteration unless said) stacked in rows in
// a box as wide as about sqrt(count) tires, already touching, with soft–soft contacts on; optionally with
// `crates` dynamic Box2D boxes mixed in. Sleeping off unless said: the scene times the solver.
enum class Sleep : bool { off, on };
std::unique_ptr<Steppable> pile(int count, int crates = 0,
                                tire::SolverMethod method = tire::SolverMethod::gauss_seidel,
                                int substeps = 8, Sleep sleep = Sleep::off,
                                int island_tires = tire::SolverConfig{}.island_tires) {
  // Gauss–Seidel as its old default had it (clamp 1); the global method as the default has it. The
  // method set either way, so that a scene's name holds whatever the default is.
  tire::SolverConfig config = method == tire::SolverMethod::gauss_seidel
                                  ? tire::SolverConfig::gauss_seidel_8x1()
                                  : tire::SolverConfig{};
  config.method = method;
  config.substeps = substeps;
  config.sleep = sleep == Sleep::on;
  config.island_tires = island_tires;
  tire::Simulation world(config, tire::Vec2{0.0, -9.81});
  const int per_row = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count)) * 1.5)));
  const double width = per_row * 1.05;
  world.add_obstacle({{{-1.0, -1.0}, {width + 1.0, 0.0}}});
  world.add_obstacle({{{-1.0, 0.0}, {0.0, 1000.0}}});
  world.add_obstacle({{{width, 0.0}, {width + 1.0, 1000.0}}});
  for (int i = 0; i < count; ++i) {
    tire::TireSpec spec;
    const int row = i / per_row, column = i % per_row;
    spec.position = {0.55 + 1.05 * column + 0.25 * (row % 2), 0.5 + 1.0 * row};
    world.add_tire(spec);
  }
  for (int i = 0; i < crates; ++i) {
    tire::PropSpec crate;
    crate.type = tire::PropType::dynamic_body;
    crate.size = {0.6, 0.6};
    crate.density = 20;
    crate.position = {0.5 + std::fmod(i * 2.3, width - 1.0), 1.0 + count / per_row + 0.8 * i / 4};
    world.add_prop(crate);
  }
  return std::make_unique<SimulationScene>(std::move(world));
}

// The crowd: `resting` default tires at rest on shelves beside a pit into which 100 tires are dropped
// again and again (the issue's "9 900 resting beside 100 falling"; the 100 alone with resting = 0).
//
// The shelves: 11 static boxes 0.2 m thick (the lowest is the ground), their tops 1.5 m apart
// (y = 0, 1.5, ..., 15), each holding up to 900 tires side by side 1.05 m apart (5 cm between
// treads, so no two touch) from x = 0.55 to 944.5: 9 900 tires fill them. Each tire starts exactly
// at rest on its shelf, a tread segment flat on it (hub r·cos(π/segments) above the shelf's top);
// the shelf above clears its top by 0.3 m. Fewer resting tires fill the same shelves from the bottom.
//
// The pit, right of the shelves behind a 1 m wall: 11 m wide (x from 946.5 to 957.5), its floor at
// y = -12, its walls up to y = 16. The 100 tires start above it in a block of 10 rows of 10 (1.05 m
// apart, odd rows shifted 0.25 m as in the pile; rows 1.1 m apart, the lowest at y = 2). The lowest
// lands 1.6 s later at 16 m/s, and the pile's impact throws more than a quarter of them back up
// above the ground (to y ≈ 7); 70 still move faster than 1 m/s at 4 s. Every 240 ticks (4 s) all
// 100 are put back where they started (Simulation::reset_tire: still, in their spawn shape) and fall
// again, so however many ticks the timing takes, its steps see falling, landing and bouncing in the
// same proportions. The re-drop is counted in ticks (Simulation::tick), never in time, and runs between
// ticks (Steppable::between_ticks), outside the timing.
constexpr int kCrowdShelves = 11;
constexpr int kCrowdPerShelf = 900;
constexpr double kCrowdShelfPitch = 1.5;
constexpr double kCrowdSpacing = 1.05;
constexpr double kCrowdPitLeft = kCrowdPerShelf * kCrowdSpacing + 1.5;  // 946.5
constexpr double kCrowdPitWidth = 11.0;
constexpr double kCrowdPitFloor = -12.0;
constexpr int kCrowdFalling = 100;
constexpr std::uint64_t kCrowdDropTicks = 240;

std::unique_ptr<Steppable> crowd(int resting, const tire::SolverConfig& config) {
  tire::Simulation world(config, tire::Vec2{0.0, -9.81});
  const double shelves_right = kCrowdPitLeft - 1.0;
  // The ground under the shelves is the lowest shelf; the pit's floor and walls.
  world.add_obstacle({{{-1.0, -1.0}, {shelves_right, 0.0}}});
  for (int k = 1; k < kCrowdShelves; ++k)
    world.add_obstacle({{{-1.0, k * kCrowdShelfPitch - 0.2}, {shelves_right, k * kCrowdShelfPitch}}});
  world.add_obstacle({{{-2.0, 0.0}, {-1.0, kCrowdShelves * kCrowdShelfPitch}}});  // the rack's left end
  const double pit_right = kCrowdPitLeft + kCrowdPitWidth;
  world.add_obstacle({{{kCrowdPitLeft - 1.0, kCrowdPitFloor - 1.0}, {pit_right + 1.0, kCrowdPitFloor}}});
  world.add_obstacle({{{kCrowdPitLeft - 1.0, kCrowdPitFloor}, {kCrowdPitLeft, 16.0}}});
  world.add_obstacle({{{pit_right, kCrowdPitFloor}, {pit_right + 1.0, 16.0}}});

  std::vector<tire::TireId> falling;
  for (int i = 0; i < kCrowdFalling; ++i) {
    tire::TireSpec spec;
    const int row = i / 10, column = i % 10;
    spec.position = {kCrowdPitLeft + 0.55 + kCrowdSpacing * column + 0.25 * (row % 2), 2.0 + 1.1 * row};
    falling.push_back(world.add_tire(spec));
  }
  for (int i = 0; i < resting; ++i) {
    tire::TireSpec spec;
    const int shelf = i / kCrowdPerShelf, column = i % kCrowdPerShelf;
    const double rest = spec.outer_radius * std::cos(std::numbers::pi / spec.segments);
    spec.position = {0.55 + kCrowdSpacing * column, shelf * kCrowdShelfPitch + rest};
    world.add_tire(spec);
  }
  return std::make_unique<SimulationScene>(std::move(world), [falling](tire::Simulation& w) {
    if (w.tick() == 0 || w.tick() % kCrowdDropTicks != 0) return;
    for (const tire::TireId id : falling) w.reset_tire(id);
  });
}

// A chain of `points` points 0.2 m apart along x from `first_x`, on a gentle wave (2 cm high, 10 m
// long, of x alone, so that every chain has the same ground under the same x), solid below: one
// default tire driven flat out along it from x = -90, by the default method. A chain of 1000 points
// reaches from -100 to 100 m, one of 100 000 (the most a level may give) from -10 000 to 10 000 m.
// Every 600 ticks (10 s, at most 150 m at the tire's top speed) the tire is put back where it
// started, at rest (Simulation::reset_tire, between ticks and outside the timing): on both chains it
// drives over the same ground, and only the edges far from it differ.
constexpr std::uint64_t kChainDriveTicks = 600;
std::unique_ptr<Steppable> chain_world(int points) {
  tire::Simulation world(tire::SolverConfig{}, tire::Vec2{0.0, -9.81});
  tire::PropSpec chain;
  chain.shape = tire::PropShape::chain;
  const double first_x = -0.1 * points;
  for (int k = 0; k < points; ++k) {
    const double x = first_x + 0.2 * k;
    chain.points.push_back({x, 0.02 * std::sin(2.0 * std::numbers::pi * x / 10.0)});
  }
  world.add_prop(chain);
  tire::TireSpec spec;
  spec.position = {-90.0, 0.6};
  spec.player = true;
  const tire::TireId id = world.add_tire(spec);
  return std::make_unique<SimulationScene>(std::move(world), [id](tire::Simulation& w) {
    if (w.tick() > 0 && w.tick() % kChainDriveTicks == 0) w.reset_tire(id);
  });
}

// Tires of 256 segments, 1953 of them (1953 x 512 = 999 936 particles, just under the default
// particle budget), by the default method with sleeping off, over a ground whose top is y = 0:
// - on a grid 1.2 m apart (45 to a row, the lowest row resting on the ground, the rest in the air,
//   none touching another): what the tires cost;
// - all on one spot, resting on the ground (what a level may place, or a spawn flood make): every
//   tire inside every other, each exactly on the others, so that no tread particle is inside
//   another tread by more than rounding;
// - heaped within 5 cm of one spot (tire i at 5 cm · sqrt(i/1953) from it, turned by the golden
//   angle from the one before), just above the ground: every tire inside every other, by up to
//   10 cm, and pushed by them.
// Before every tick (outside the timing) every tire is put back where it started, at rest
// (Simulation::reset_tire), so each timed tick is the first tick of the scene: the pile never gets to
// spread, nor the grid to fall.
constexpr int kSpotTires = 1953;
constexpr int kSpotSegments = 256;
enum class Placement { grid, one_spot, heap };
std::unique_ptr<Steppable> spot_world(Placement placement) {
  tire::SolverConfig config;
  config.sleep = false;
  tire::Simulation world(config, tire::Vec2{0.0, -9.81});
  world.add_obstacle({{{-10.0, -1.0}, {60.0, 0.0}}});
  std::vector<tire::TireId> ids;
  for (int i = 0; i < kSpotTires; ++i) {
    tire::TireSpec spec;
    spec.segments = kSpotSegments;
    switch (placement) {
      case Placement::grid: spec.position = {1.2 * (i % 45), 0.5 + 1.2 * (i / 45)}; break;
      case Placement::one_spot: spec.position = {0.0, 0.5}; break;
      case Placement::heap: {
        const double r = 0.05 * std::sqrt(static_cast<double>(i) / kSpotTires);
        const double angle = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
        spec.position = {r * std::cos(angle), 0.55 + r * std::sin(angle)};
        break;
      }
    }
    ids.push_back(world.add_tire(spec));
  }
  return std::make_unique<SimulationScene>(std::move(world), [ids](tire::Simulation& w) {
    if (w.tick() == 0) return;
    for (const tire::TireId id : ids) w.reset_tire(id);
  });
}

struct Scene {
  const char* name;
  const char* what;
  std::function<std::unique_ptr<Steppable>()> build;
  tire::TickInput input;
  // Settled first: stepped, before the warm-up, until as many tires have been asleep for 60 ticks
  // running (at least one) or --settle ticks have passed (bench() below).
  bool settled = false;
};

// The prototype's scene: the earlier XPBD tire prototype this engine set out to beat, which took 88 µs
// per frame here (docs/performance.md): one tire of 28 segments with radial spokes, one step of 22
// iterations per 60 Hz frame, on a ground line next to a box.
std::unique_ptr<Steppable> prototype_world(tire::SpokePattern spokes, int substeps, int iterations,
                                           tire::SolverMethod method = tire::SolverMethod::gauss_seidel) {
  tire::SolverConfig config;
  config.dt = 1.0 / 60.0;
  config.substeps = substeps;
  config.iterations = iterations;
  config.method = method;
  config.tunnel_clamp = 1.0;  // the prototype's scene as measured before the default changed
  config.sleep = false;       // the solver's cost: a resting tire would fall asleep
  tire::Simulation world(config, tire::Vec2{0.0, -9.81});
  world.add_obstacle({{{-50.0, -1.0}, {50.0, 0.0}}});
  world.add_obstacle({{{3.0, 0.0}, {4.0, 0.6}}});
  tire::TireSpec spec;
  spec.position = {0.0, 0.52};
  spec.spokes = spokes;
  world.add_tire(spec);
  return std::make_unique<SimulationScene>(std::move(world));
}

// One default tire driven flat out along flat ground with nothing in its way (issue 13's cost
// figure: a tire rolling on flat ground), by either method.
std::unique_ptr<Steppable> rolling_world(tire::SolverMethod method, int substeps) {
  tire::SolverConfig config;
  config.method = method;
  config.substeps = substeps;
  config.tunnel_clamp = 4.0;  // the speed limit of Gauss–Seidel 8 × 1 at any substep count
  tire::Simulation world(config, tire::Vec2{0.0, -9.81});
  world.add_obstacle({{{-1.0e6, -1.0}, {1.0e6, 0.0}}});
  tire::TireSpec spec;
  spec.position = {0.0, 0.52};
  spec.player = true;
  world.add_tire(spec);
  return std::make_unique<SimulationScene>(std::move(world));
}

// A car (levels/README.md, "Vehicles"): a 48 kg box chassis on two default tires, each on a rigid
// axle, both driven, flat out along flat ground with nothing in its way; the default method. Its
// cost against "rolling-global-2x1" (one default tire rolling) is issue 37's figure.
constexpr const char* kCarLevel = R"json({
  "name": "Car (bench)",
  "solver": { "sleep": false },
  "obstacles": [ { "min": [-10000, -1], "max": [10000, 0] } ],
  "vehicles": [ { "player": true,
    "chassis": { "shape": "box", "position": [0, 1.05], "size": [1.6, 0.3], "density": 100 },
    "wheels": [ { "axle": [-0.7, -0.4] }, { "axle": [0.7, -0.4] } ] } ]
})json";

std::unique_ptr<Steppable> car_level() { return level_scene(kCarLevel, "car"); }

const Scene kScenes[] = {
    {"prototype",
     "1 tire, 28 segments, radial spokes, 1 substep x 22 iterations, resting",
     [] { return prototype_world(tire::SpokePattern::radial, 1, 22); },
     {}},
    {"prototype-rolling",
     "as prototype, steering +1 (friction and drive active)",
     [] { return prototype_world(tire::SpokePattern::radial, 1, 22); },
     {1.0, false}},
    {"default-tire",
     "1 tire, 28 segments, cross spokes, Gauss-Seidel 8 substeps x 1 iteration (the default until issue 13)",
     [] { return prototype_world(tire::SpokePattern::cross, 8, 1); },
     {1.0, false}},
    {"global-tire",
     "as default-tire, solved by the global method at 4 substeps x 1 iteration",
     [] { return prototype_world(tire::SpokePattern::cross, 4, 1, tire::SolverMethod::global); },
     {1.0, false}},
    {"global-tire-2x1",
     "as global-tire, at 2 substeps x 1 iteration",
     [] { return prototype_world(tire::SpokePattern::cross, 2, 1, tire::SolverMethod::global); },
     {1.0, false}},
    {"rolling-gauss-seidel-8x1",
     "1 default tire driven flat out on flat ground with nothing in its way, Gauss-Seidel 8 x 1",
     [] { return rolling_world(tire::SolverMethod::gauss_seidel, 8); },
     {1.0, false}},
    {"rolling-global-2x1",
     "as rolling-gauss-seidel-8x1, solved by the global method at 2 substeps x 1 iteration",
     [] { return rolling_world(tire::SolverMethod::global, 2); },
     {1.0, false}},
    {"car-global-2x1",
     "a car: a 48 kg box on two default tires, both driven, flat out on flat ground, default method "
     "(global 2 x 1); against rolling-global-2x1",
     [] { return car_level(); },
     {1.0, false}},
    {"global-tire-resting",
     "as global-tire, resting (no steering)",
     [] { return prototype_world(tire::SpokePattern::cross, 4, 1, tire::SolverMethod::global); },
     {}},
    {"bare-tire",
     "1 default tire on a ground box, stepped by the tire solver alone (no world, no level)",
     [] { return std::make_unique<BareTireScene>(); },
     {}},
    {"flat-level",
     "the same tire and ground loaded as a level and stepped by a Simulation",
     [] { return flat_level(); },
     {}},
    {"pile-1", "1 tire in a walled box", [] { return pile(1); }, {}},
    {"pile-10", "10 tires piled in a walled box, soft-soft contacts on", [] { return pile(10); }, {}},
    {"pile-100", "100 tires piled in a walled box", [] { return pile(100); }, {}},
    {"pile-1000", "1000 tires piled in a walled box", [] { return pile(1000); }, {}},
    {"pile-200-settled",
     "200 tires piled in a walled box, sleeping on, stepped until its count of sleeping tires holds for 60 "
     "ticks (at most --settle ticks) before the warm-up",
     [] { return pile(200, 0, tire::SolverMethod::gauss_seidel, 8, Sleep::on); },
     {},
     true},
    {"pile-200-settled-awake",
     "as pile-200-settled with sleeping off (\"solver\": {\"sleep\": false}): --settle ticks",
     [] { return pile(200); },
     {},
     true},
    {"pile-1000-settled",
     "as pile-1000 with sleeping on, settled as pile-200-settled",
     [] { return pile(1000, 0, tire::SolverMethod::gauss_seidel, 8, Sleep::on); },
     {},
     true},
    {"mixed-200", "200 tires and 40 dynamic Box2D crates in a walled box", [] { return pile(200, 40); }, {}},
    {"global-pile-10",
     "as pile-10, solved by the global method at 2 substeps x 1 iteration",
     [] { return pile(10, 0, tire::SolverMethod::global, 2); },
     {}},
    {"global-pile-100",
     "as pile-100, solved by the global method at 2 substeps x 1 iteration",
     [] { return pile(100, 0, tire::SolverMethod::global, 2); },
     {}},
    {"global-pile-1000",
     "as pile-1000, solved by the global method at 2 substeps x 1 iteration",
     [] { return pile(1000, 0, tire::SolverMethod::global, 2); },
     {}},
    {"global-pile-60-settled-awake",
     "60 tires piled in a walled box, global 2 x 1, sleeping off, stepped --settle ticks before the warm-up: "
     "a pile at rest, its contacts between tires by block Gauss-Seidel (\"island_tires\": 0)",
     [] { return pile(60, 0, tire::SolverMethod::global, 2, Sleep::off, 0); },
     {},
     true},
    {"island-pile-60-settled-awake",
     "as global-pile-60-settled-awake with \"solver\": {\"island_tires\": 64} (the default): the pile's "
     "contacts between tires solved as one problem (docs/at-rest.md)",
     [] { return pile(60, 0, tire::SolverMethod::global, 2, Sleep::off, 64); },
     {},
     true},
    {"crowd-100",
     "100 tires dropped into a pit again every 4 s, beside empty shelves, Gauss-Seidel 8 x 1",
     [] { return crowd(0, tire::SolverConfig::gauss_seidel_8x1()); },
     {}},
    {"crowd-10000",
     "as crowd-100, beside 9900 tires resting on the shelves",
     [] { return crowd(kCrowdShelves * kCrowdPerShelf, tire::SolverConfig::gauss_seidel_8x1()); },
     {}},
    {"global-crowd-100",
     "as crowd-100, solved by the default method (global 2 x 1)",
     [] { return crowd(0, {}); },
     {}},
    {"global-crowd-10000",
     "as crowd-10000, solved by the default method (global 2 x 1)",
     [] { return crowd(kCrowdShelves * kCrowdPerShelf, {}); },
     {}},
    {"chain-1000",
     "1 default tire driven flat out along a chain of 1000 points 0.2 m apart, default method (global 2 x 1)",
     [] { return chain_world(1000); },
     {1.0, false}},
    {"chain-100000",
     "as chain-1000 on a chain of 100000 points (the most a level may give): the same ground near the tire",
     [] { return chain_world(100000); },
     {1.0, false}},
    {"spot-grid-1953",
     "1953 tires of 256 segments on a grid 1.2 m apart, none touching another, put back before every tick; "
     "default method, sleeping off",
     [] { return spot_world(Placement::grid); },
     {}},
    {"spot-pile-1953",
     "the same 1953 tires all on one spot (each inside every other), put back before every tick",
     [] { return spot_world(Placement::one_spot); },
     {}},
    {"spot-heap-1953",
     "the same 1953 tires heaped within 5 cm of one spot (each pushed by every other), put back before "
     "every tick",
     [] { return spot_world(Placement::heap); },
     {}},
};

// The prototype's figure for its own scene, per 60 Hz frame (docs/performance.md, "The scenes").
constexpr double kPrototypeUsPerFrame = 88.0;
// The vector instructions this build was compiled for (TIRE_AVX2, docs/performance.md): the same
// bits either way, not the same times, so a figure says which it was.
#if defined(__AVX2__)
constexpr const char* kSimd = "avx2";
#elif defined(__SSE2__)
constexpr const char* kSimd = "sse2";
#else
constexpr const char* kSimd = "scalar";
#endif

// The q-quantile of `v` (nearest rank), q in [0, 1].
double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const auto i = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
  return v[std::min(v.size() - 1, i == 0 ? 0 : i - 1)];
}

// A settled scene: stepped until its count of sleeping tires has held for 60 ticks running while
// at least one tire sleeps (a pile whose tires have not yet slept is still settling), or all sleep,
// or `max_ticks` ticks have passed. Bounded by ticks, never by time: with sleeping off (or nothing
// falling asleep) it takes all `max_ticks`. Says how it went on stderr.
void settle(Steppable& world, const Scene& scene, int max_ticks) {
  constexpr int kHeld = 60;
  std::size_t asleep = world.asleep();
  int held = 0, ticks = 0;
  while (ticks < max_ticks && held < kHeld && asleep < world.tire_count()) {
    world.between_ticks();
    world.step(scene.input);
    ++ticks;
    const std::size_t now = world.asleep();
    held = now == asleep && now > 0 ? held + 1 : 0;
    asleep = now;
  }
  std::fprintf(stderr, "%s: settled for %d ticks, %zu of %zu tires asleep\n", scene.name, ticks, asleep,
               world.tire_count());
}

}  // namespace

using tire_tools::heap_mib;
using tire_tools::peak_rss_mib;
using tire_tools::rss_mib;

int bench(const BenchOptions& options) {
  for (const std::string& name : options.scenes) {
    if (std::none_of(std::begin(kScenes), std::end(kScenes),
                     [&](const Scene& s) { return name == s.name; })) {
      std::cerr << "tirectl bench: unknown scene \"" << tire::printable(name) << "\"; scenes:";
      for (const Scene& s : kScenes) std::cerr << " " << s.name;
      std::cerr << "\n";
      return 2;
    }
  }
  std::cout
      << "scene,tires,particles,contacts,tire_pairs,threads,segments,substeps,iterations,steps,median_ms,"
         "p99_ms,mean_ms,us_per_tire,peak_rss_mib,speedup_vs_prototype,asleep,simd\n";
  using Clock = std::chrono::steady_clock;
  std::vector<double> step_ms;
  for (const Scene& scene : kScenes) {
    if (!options.scenes.empty() &&
        std::find(options.scenes.begin(), options.scenes.end(), scene.name) == options.scenes.end())
      continue;
    auto world = scene.build();
    if (options.threads > 0) world->set_threads(static_cast<unsigned>(options.threads));
    world->set_schedule(options.schedule == "plain" ? tire::StepSchedule::plain : tire::StepSchedule::fused);
    if (scene.settled) settle(*world, scene, options.settle);
    for (int i = 0; i < options.warmup; ++i) {  // settle and warm the caches
      world->between_ticks();
      world->step(scene.input);
    }
    // Each step timed on its own: the median is the typical step, the p99 the hitches a player sees.
    // Either exactly --steps steps, or at least 30 and until --seconds have passed.
    step_ms.clear();
    // Reserved up front: a long run must not grow the heap it reports on.
    step_ms.reserve(options.steps > 0 ? static_cast<std::size_t>(options.steps) : std::size_t{1} << 20);
    const auto scene_start = Clock::now();
    for (int s = 0;; ++s) {
      if (options.steps > 0 ? s >= options.steps
                            : s >= 30 && std::chrono::duration<double>(Clock::now() - scene_start).count() >=
                                             options.seconds)
        break;
      world->between_ticks();
      const auto start = Clock::now();
      world->step(scene.input);
      step_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
      // A long run's progress on stderr: is the step time steady, is memory flat?
      if (options.report_every > 0 && (s + 1) % options.report_every == 0) {
        const std::vector<double> window(step_ms.end() - options.report_every, step_ms.end());
        std::fprintf(stderr,
                     "%s: step %d, %.0f s: median %.3f ms, p99 %.3f ms over the last %d; RSS %.1f MiB, heap "
                     "%.1f MiB\n",
                     scene.name, s + 1, std::chrono::duration<double>(Clock::now() - scene_start).count(),
                     quantile(window, 0.5), quantile(window, 0.99), options.report_every, rss_mib(),
                     heap_mib());
      }
    }
    const std::size_t tires = world->tire_count();
    const double median = quantile(step_ms, 0.5);
    double mean = 0.0;
    for (const double ms : step_ms) mean += ms / static_cast<double>(step_ms.size());
    std::cout << scene.name << "," << tires << "," << tires * world->first_tire_particles() << ","
              << world->contacts() << "," << world->tire_pairs() << "," << world->threads() << ","
              << world->first_tire_segments() << "," << world->config().substeps << ","
              << world->config().iterations << "," << step_ms.size() << "," << median << ","
              << quantile(step_ms, 0.99) << "," << mean << "," << median * 1000.0 / static_cast<double>(tires)
              << "," << peak_rss_mib() << ",";
    // The prototype's figure is for its own scene only.
    if (std::string_view(scene.name).starts_with("prototype"))
      std::cout << kPrototypeUsPerFrame / (median * 1000.0);
    // A row at a time: long runs show progress.
    std::cout << "," << world->asleep() << "," << kSimd << std::endl;
  }
  return 0;
}

}  // namespace tirectl

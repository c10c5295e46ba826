// Performance scenes, timed with a monotonic clock outside the simulation. CSV on stdout.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <string_view>

#include "commands.h"
#include "level.h"
#include "tire_solver.h"
#include "world.h"

namespace tirectl {

namespace {

// Something that advances one fixed tick.
class Steppable {
 public:
  virtual ~Steppable() = default;
  virtual void step(const tire::TickInput& input) = 0;
  virtual const tire::Tire& first_tire() const = 0;
  virtual std::size_t tire_count() const = 0;
  virtual const tire::SolverConfig& config() const = 0;
};

class WorldScene final : public Steppable {
 public:
  explicit WorldScene(std::unique_ptr<tire::World> world) : world_(std::move(world)) {}
  void step(const tire::TickInput& input) override { world_->step(input); }
  const tire::Tire& first_tire() const override { return world_->tires().front(); }
  std::size_t tire_count() const override { return world_->tires().size(); }
  const tire::SolverConfig& config() const override { return world_->config(); }

 private:
  std::unique_ptr<tire::World> world_;
};

// One tire and its ground, stepped by the tire solver alone: no World around it (no level, no
// divergence guard, no Box2D stepping, nothing else). The floor for "flat-level".
class BareTireScene final : public Steppable {
 public:
  BareTireScene() : rigid_({0.0, -9.81}), tire_(0, spec()) { rigid_.add_obstacle({{{-50.0, -1.0}, {50.0, 0.0}}}); }
  void step(const tire::TickInput& input) override {
    tire_.control = {input.steer, input.jump};
    tire::begin_tick(tire_, config_, rigid_);
    const double h = config_.dt / config_.substeps;
    tire::SubstepContext ctx{h, 0.0, {0.0, -9.81}, &config_, &rigid_};
    for (int s = 0; s < config_.substeps; ++s) {
      ctx.time = s * h;
      tire::substep(tire_, ctx, rigid_);
    }
  }
  const tire::Tire& first_tire() const override { return tire_; }
  std::size_t tire_count() const override { return 1; }
  const tire::SolverConfig& config() const override { return config_; }

 private:
  static tire::TireSpec spec() {
    tire::TireSpec s;
    s.position = {0.0, 0.5};
    return s;
  }
  tire::SolverConfig config_;
  tire::RigidWorld rigid_;
  tire::Tire tire_;
};

// The same tire and ground as a level file read by the loader, stepped by the World: everything a
// level brings along, on the scene that needs none of it.
constexpr const char* kFlatLevel = R"json({
  "name": "Flat (bench)",
  "tires": [ { "position": [0, 0.5] } ],
  "obstacles": [ { "min": [-50, -1], "max": [50, 0] } ]
})json";

std::unique_ptr<Steppable> flat_level() {
  const tire::LevelLoad load = tire::load_level_text(kFlatLevel, "flat-level");
  auto world = std::make_unique<tire::World>(load.level->solver, load.level->gravity);
  tire::populate_world(*load.level, *world);
  return std::make_unique<WorldScene>(std::move(world));
}

// A walled pile: `count` default tires (28 segments, 8 substeps × 1 iteration) stacked in rows in a
// box as wide as about sqrt(count) tires, already touching, with soft–soft contacts on; optionally
// with `crates` dynamic Box2D boxes mixed in.
std::unique_ptr<Steppable> pile(int count, int crates = 0) {
  tire::SolverConfig config;
  auto world = std::make_unique<tire::World>(config, tire::Vec2{0.0, -9.81});
  const int per_row = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count)) * 1.5)));
  const double width = per_row * 1.05;
  world->add_obstacle({{{-1.0, -1.0}, {width + 1.0, 0.0}}});
  world->add_obstacle({{{-1.0, 0.0}, {0.0, 1000.0}}});
  world->add_obstacle({{{width, 0.0}, {width + 1.0, 1000.0}}});
  for (int i = 0; i < count; ++i) {
    tire::TireSpec spec;
    const int row = i / per_row, column = i % per_row;
    spec.position = {0.55 + 1.05 * column + 0.25 * (row % 2), 0.5 + 1.0 * row};
    world->add_tire(spec);
  }
  for (int i = 0; i < crates; ++i) {
    tire::PropSpec crate;
    crate.type = tire::PropType::dynamic_body;
    crate.size = {0.6, 0.6};
    crate.density = 20;
    crate.position = {0.5 + std::fmod(i * 2.3, width - 1.0), 1.0 + count / per_row + 0.8 * i / 4};
    world->add_prop(crate);
  }
  return std::make_unique<WorldScene>(std::move(world));
}

struct Scene {
  const char* name;
  const char* what;
  std::function<std::unique_ptr<Steppable>()> build;
  tire::TickInput input;
};

// The prototype's scene (../shared/REFERENCE.md): one tire of 28 segments with radial spokes,
// one step of 22 iterations per 60 Hz frame, on a ground line next to a box.
std::unique_ptr<Steppable> prototype_world(tire::SpokePattern spokes, int substeps, int iterations) {
  tire::SolverConfig config;
  config.dt = 1.0 / 60.0;
  config.substeps = substeps;
  config.iterations = iterations;
  auto world = std::make_unique<tire::World>(config, tire::Vec2{0.0, -9.81});
  world->add_obstacle({{{-50.0, -1.0}, {50.0, 0.0}}});
  world->add_obstacle({{{3.0, 0.0}, {4.0, 0.6}}});
  tire::TireSpec spec;
  spec.position = {0.0, 0.52};
  spec.spokes = spokes;
  world->add_tire(spec);
  return std::make_unique<WorldScene>(std::move(world));
}

const Scene kScenes[] = {
    {"prototype", "1 tire, 28 segments, radial spokes, 1 substep x 22 iterations, resting",
     [] { return prototype_world(tire::SpokePattern::radial, 1, 22); }, {}},
    {"prototype-rolling", "as prototype, steering +1 (friction and drive active)",
     [] { return prototype_world(tire::SpokePattern::radial, 1, 22); }, {1.0, false}},
    {"default-tire", "1 tire, 28 segments, cross spokes, 8 substeps x 1 iteration (the default level)",
     [] { return prototype_world(tire::SpokePattern::cross, 8, 1); }, {1.0, false}},
    {"bare-tire", "1 default tire on a ground box, stepped by the tire solver alone (no World, no level)",
     [] { return std::make_unique<BareTireScene>(); }, {}},
    {"flat-level", "the same tire and ground loaded as a level and stepped by the World",
     [] { return flat_level(); }, {}},
    {"pile-1", "1 tire in a walled box", [] { return pile(1); }, {}},
    {"pile-10", "10 tires piled in a walled box, soft-soft contacts on", [] { return pile(10); }, {}},
    {"pile-100", "100 tires piled in a walled box", [] { return pile(100); }, {}},
    {"pile-1000", "1000 tires piled in a walled box", [] { return pile(1000); }, {}},
    {"mixed-200", "200 tires and 40 dynamic Box2D crates in a walled box", [] { return pile(200, 40); }, {}},
};

// The prototype's figure for its own scene, per 60 Hz frame (REFERENCE.md).
constexpr double kPrototypeUsPerFrame = 88.0;

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const auto i = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5);
  return v[i];
}

}  // namespace

int bench(const BenchOptions& options) {
  for (const std::string& name : options.scenes) {
    if (std::none_of(std::begin(kScenes), std::end(kScenes), [&](const Scene& s) { return name == s.name; })) {
      std::cerr << "tirectl bench: unknown scene \"" << name << "\"; scenes:";
      for (const Scene& s : kScenes) std::cerr << " " << s.name;
      std::cerr << "\n";
      return 2;
    }
  }
  std::cout << "scene,tires,particles,segments,substeps,iterations,frames,repeats,median_us_per_frame,"
               "p99_us_per_frame,speedup_vs_prototype\n";
  for (const Scene& scene : kScenes) {
    if (!options.scenes.empty() &&
        std::find(options.scenes.begin(), options.scenes.end(), scene.name) == options.scenes.end())
      continue;
    auto world = scene.build();
    for (int i = 0; i < 120; ++i) world->step(scene.input);  // settle and warm the caches
    std::vector<double> per_frame_us;
    for (int r = 0; r < options.repeats; ++r) {
      const auto start = std::chrono::steady_clock::now();
      for (int f = 0; f < options.frames; ++f) world->step(scene.input);
      const std::chrono::duration<double, std::micro> elapsed = std::chrono::steady_clock::now() - start;
      per_frame_us.push_back(elapsed.count() / options.frames);
      if (scene.input.steer != 0.0) world = scene.build();  // keep the rolling tire on its ground
    }
    const tire::Tire& t = world->first_tire();
    const std::size_t particles = world->tire_count() * t.particle_count();
    const double median = percentile(per_frame_us, 0.5);
    std::cout << scene.name << "," << world->tire_count() << "," << particles << "," << t.segments() << ","
              << world->config().substeps << "," << world->config().iterations << "," << options.frames << ","
              << options.repeats << "," << median << "," << percentile(per_frame_us, 0.99) << ",";
    // The prototype's figure is for its own scene only.
    if (std::string_view(scene.name).starts_with("prototype")) std::cout << kPrototypeUsPerFrame / median;
    std::cout << "\n";
  }
  return 0;
}

}  // namespace tirectl

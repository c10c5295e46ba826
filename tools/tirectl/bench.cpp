// Performance scenes, timed with a monotonic clock outside the simulation. CSV on stdout.
#include <algorithm>
#include <chrono>
#include <functional>
#include <iostream>
#include <memory>

#include "commands.h"
#include "world.h"

namespace tirectl {

namespace {

struct Scene {
  const char* name;
  const char* what;
  std::function<std::unique_ptr<tire::World>()> build;
  tire::TickInput input;
};

// The prototype's scene (../shared/REFERENCE.md): one tire of 28 segments with radial spokes,
// one step of 22 iterations per 60 Hz frame, on a ground line next to a box.
std::unique_ptr<tire::World> prototype_world(tire::SpokePattern spokes, int substeps, int iterations) {
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
  return world;
}

const Scene kScenes[] = {
    {"prototype", "1 tire, 28 segments, radial spokes, 1 substep x 22 iterations, resting",
     [] { return prototype_world(tire::SpokePattern::radial, 1, 22); }, {}},
    {"prototype-rolling", "as prototype, steering +1 (friction and drive active)",
     [] { return prototype_world(tire::SpokePattern::radial, 1, 22); }, {1.0, false}},
    {"default-tire", "1 tire, 28 segments, cross spokes, 8 substeps x 1 iteration (the default level)",
     [] { return prototype_world(tire::SpokePattern::cross, 8, 1); }, {1.0, false}},
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
    std::size_t particles = 0;
    for (const tire::Tire& t : world->tires()) particles += t.particle_count();
    const tire::Tire& t = world->tires().front();
    const double median = percentile(per_frame_us, 0.5);
    std::cout << scene.name << "," << world->tires().size() << "," << particles << "," << t.segments() << ","
              << world->config().substeps << "," << world->config().iterations << "," << options.frames << ","
              << options.repeats << "," << median << "," << percentile(per_frame_us, 0.99) << ","
              << kPrototypeUsPerFrame / median << "\n";
  }
  return 0;
}

}  // namespace tirectl

// The fixed tick from 1/30 s to 1/1000 s, times 1 to 64 substeps; and the ring resolution from 6
// to 256 segments.
#include "extremes.h"

using namespace tire;
using namespace tire::extremes;

namespace {
// A default tire dropped 0.5 m (hub from y = 1.0) and watched for `seconds`.
// Energy scale: E(0) = M g y_hub = 98.1 J. Area bounds [0.2, 3] after 1 s: the default tire
// (α = 1e-6 / 1e-7 / 1e-6 / 1e-5) carries its 98 N weight with a few percent of sag.
void drop(const std::string& name, const SolverConfig& config, int segments, double seconds) {
  TireSpec spec = tire_spec({0, 1.0});
  spec.segments = segments;
  World world = ground_world(config);
  world.add_tire(spec);
  Probe probe(name, world);
  probe.step(ticks_for(seconds, config));
  probe.note("final area " + fmt("%.3f", world.tires().front().area_ratio()) + ", final hub y " +
             fmt("%.3f", world.tires().front().centroid().y) + " m, final speed " +
             fmt("%.2g", length(world.tires().front().velocity())) + " m/s");
  probe.judge();
}
}  // namespace

TEST_CASE("a dropped tire is stable for every tick length from 1/30 s to 1/1000 s and 1 to 64 substeps",
          "[extremes][timestep]") {
  for (const int hz : {30, 60, 240, 1000}) {
    for (const int substeps : {1, 2, 8, 64}) {
      SolverConfig config;
      config.dt = 1.0 / hz;
      config.substeps = substeps;
      drop("dt=1/" + std::to_string(hz) + " substeps=" + std::to_string(substeps), config, 28, 3.0);
    }
  }
}

TEST_CASE("a dropped tire is stable with 6 to 256 segments per ring", "[extremes][segments]") {
  for (const int segments : {6, 8, 28, 64, 256})
    drop("segments=" + std::to_string(segments), SolverConfig{}, segments, 3.0);
}

// Fifty tires dropped into a walled box: many soft–soft contacts at once.
#include "extremes.h"

using namespace tire;
using namespace tire::extremes;

TEST_CASE("a pile of 50 tires in a walled box settles without NaN, energy gain or crushed tires",
          "[extremes][pile]") {
  // Box: ground at y = 0, walls at x = ±3.5 (7 m inside, 40 m tall). 50 default tires in rows of
  // 6 at 1.1 m spacing, 1.15 m apart vertically (hubs from y = 0.6 to 9.8), each row shifted by
  // ±0.2 m so that the rows nest. Watched for 6 s.
  // Energy scale: E(0) = Σ M g y_hub ≈ 25 kJ (all at rest, ground-referenced).
  // Area bounds [0.2, 3] after 1 s: the bottom row carries at most ~8 tires (≈ 800 N), which the
  // default air (α = 1e-5 m⁴/J) resists with ΔA ≈ W·α/L ≈ 0.01–0.02 m².
  const SolverConfig config;
  World world = ground_world(config);
  world.add_obstacle({{{-4.5, 0}, {-3.5, 40}}});
  world.add_obstacle({{{3.5, 0}, {4.5, 40}}});
  for (int i = 0; i < 50; ++i) {
    const int row = i / 6, col = i % 6;
    const double shift = row % 2 == 0 ? -0.2 : 0.2;
    world.add_tire(tire_spec({-2.75 + 1.1 * col + shift, 0.6 + 1.15 * row}));
  }
  Probe probe("pile of 50 tires in a walled box", world);
  probe.step(ticks_for(6.0, config));
  double fastest = 0.0, kinetic = 0.0, top = -kInf;
  for (const Tire& t : world.tires()) {
    fastest = std::max(fastest, length(t.velocity()));
    kinetic += tire_energy(t, {0, 0});
    top = std::max(top, t.centroid().y);
  }
  probe.note("final fastest hub " + fmt("%.3g", fastest) + " m/s, final kinetic energy " +
             fmt("%.3g", kinetic) + " J, highest hub " + fmt("%.2f", top) + " m");
  probe.judge();
}

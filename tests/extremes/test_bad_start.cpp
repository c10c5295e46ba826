// Broken starting states: coincident particles, and a tire turned inside out.
#include "extremes.h"

using namespace tire;
using namespace tire::extremes;

TEST_CASE("a tire that starts with coincident particles separates them without NaN", "[extremes][start]") {
  // The default tire rests on the ground (hub y = 0.5). Before the first step, outer particles 0,
  // 1 and 2 and inner particle 0 (n) are all put at outer particle 1's position (near the bottom).
  // The constraints joining them then have no direction (zero gradient); their neighbours' do.
  // Energy scale: E(0) + U(0), U(0) = Σ ½C²/α of the strained constraints (the energy the start
  // state holds). Area bounds [0.2, 3] after 1 s. Watched 4 s.
  World world = ground_world();
  const TireId id = world.add_tire(tire_spec({0, 0.5}));
  Tire& t = *world.find_tire(id);
  const Vec2 p = t.particles.x[1];
  for (const std::uint32_t i : {0u, 1u, 2u, t.n}) t.particles.x[i] = t.particles.x_prev[i] = p;
  Probe probe("coincident particles (outer 0,1,2 and inner 0) at start", world, AreaBounds{}, true);
  probe.step(ticks_for(4.0, world.config()));
  const double gap = length(t.particles.x[1] - t.particles.x[0]);
  probe.note("final area " + fmt("%.3f", t.area_ratio()) + ", final |x1 − x0| " + fmt("%.4f", gap) +
             " m (rest " + fmt("%.4f", t.segment_length) + ")");
  probe.judge();
}

TEST_CASE("a tire that starts inside out (clockwise) does not produce NaN and recovers a sane area",
          "[extremes][start]") {
  // The default tire rests on the ground (hub y = 0.5). Before the first step every particle is
  // mirrored through the vertical line through the hub (x → 2·x_hub − x), so both rings run
  // clockwise: the signed area is −A0 while every distance constraint is at its rest length. (A
  // point reflection through the hub would be a rotation by 180° and keep the rings CCW.)
  // Energy scale: E(0) + U(0), with U(0) = ½(−A0 − A0)²/α_pressure ≈ 121 kJ held by the air.
  // Area bounds [0.2, 3] after 1 s; watched 4 s; the final area is reported.
  World world = ground_world();
  const TireId id = world.add_tire(tire_spec({0, 0.5}));
  Tire& t = *world.find_tire(id);
  const double hub_x = t.centroid().x;
  for (std::size_t i = 0; i < t.particles.size(); ++i) {
    t.particles.x[i].x = 2.0 * hub_x - t.particles.x[i].x;
    t.particles.x_prev[i] = t.particles.x[i];
  }
  const double start_area = t.area_ratio();
  Probe probe("inverted (clockwise) tire at start", world, AreaBounds{}, true);
  double first_positive = -1.0;
  for (int i = 0; i < ticks_for(4.0, world.config()); ++i) {
    probe.step(1);
    if (first_positive < 0.0 && t.area_ratio() > 0.0) first_positive = world.time();
  }
  probe.note("start area " + fmt("%.3f", start_area) +
             ", area first positive at t=" + fmt("%.3f", first_positive) + " s, final area " +
             fmt("%.3f", t.area_ratio()) + ", final hub y " + fmt("%.3f", t.centroid().y) + " m");
  probe.judge();
}

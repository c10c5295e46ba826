// A world built in code rather than read from a level: the ground, a crate, and two tires dropped
// one onto the other (the top one rolls off towards the crate). Steps three seconds and prints
// each body as the engine shows it (a view: read only), then pushes the top tire on into the crate.
//   world-in-code
#include <tire/engine.h>

#include <cstdio>

namespace {

void print(const tire::Simulation& sim) {
  // The energy watch: what the world holds against what came into it (the bodies, the push).
  const tire::EnergyView e = sim.energy();
  std::printf("t = %.2f s, %zu asleep, energy %.1f J of %.1f J brought in\n", sim.time(), sim.asleep_count(),
              e.total(), e.brought_in);
  for (const tire::TireId id : sim.tires()) {
    const tire::TireView t = *sim.tire(id);
    std::printf("  tire %u: hub (%.3f, %.3f) m, %.2f m/s, area %.1f %%, %s, ground %.1f N·s\n", t.id,
                t.centroid.x, t.centroid.y, t.velocity.x, 100.0 * t.area_ratio,
                t.grounded ? "on the ground" : "off the ground", t.contacts.ground);
  }
  for (tire::PropId id = 0; id < sim.prop_count(); ++id) {
    const tire::PropView p = *sim.prop(id);
    std::printf("  prop %u: at (%.3f, %.3f) m, turned %.3f rad\n", p.id, p.state.pose.position.x,
                p.state.pose.position.y, p.state.pose.angle);
  }
}

}  // namespace

int main() {
  tire::Simulation sim(tire::SolverConfig{}, {0.0, -9.81});  // the default solver; gravity in m/s²
  sim.add_obstacle({{{-10.0, -1.0}, {10.0, 0.0}}});          // the ground: a box from (-10, -1) to (10, 0)

  tire::PropSpec crate;  // a 60 cm box lying on the ground
  crate.type = tire::PropType::dynamic_body;
  crate.size = {0.6, 0.6};
  crate.position = {2.0, 0.3};
  sim.add_prop(crate);

  tire::TireSpec tire;  // a tire's defaults are the level format's (levels/README.md)
  tire.position = {0.0, 0.6};
  const tire::TireId bottom = sim.add_tire(tire);
  tire.position = {0.1, 2.0};
  const tire::TireId top = sim.add_tire(tire);

  for (int i = 0; i < 180; ++i) sim.step();  // 3 s at the default 60 ticks a second
  print(sim);

  // Commands go through the simulation, which wakes what they touch.
  sim.apply_impulse(top, {30.0, 0.0});  // N·s
  sim.set_parameter("tires.friction", 0.4);
  for (int i = 0; i < 120; ++i) sim.step();
  print(sim);
  std::printf("bottom tire %u, solver failures %llu\n", bottom,
              static_cast<unsigned long long>(sim.solver_failures()));
  return 0;
}

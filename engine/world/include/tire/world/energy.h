// The world's mechanical energy: what the energy watch (tirectl run, tests/test_energy.cpp) adds up
// to see that no contact makes energy. Between ticks.
#pragma once

#include "tire/math/geometry.h"

namespace tire {

class World;
struct Tire;

struct Energy {
  double kinetic = 0.0;        // ½ m v² of every particle and prop (props: + ½ I ω²) (J)
  double gravitational = 0.0;  // −m g·x, zero at the origin (J)
  double elastic = 0.0;        // ½ C²/α of every compliant constraint of every tire and suspension (J)
  double total() const { return kinetic + gravitational + elastic; }
  Energy& operator+=(const Energy& o) {
    kinetic += o.kinetic;
    gravitational += o.gravitational;
    elastic += o.elastic;
    return *this;
  }
};

// One tire's: its particles' kinetic and gravitational energy, and the energy its compliant
// constraints hold, U = ½ C²/α (the potential XPBD's compliance stands for: Macklin et al. 2016,
// eq. 2–4). A constraint of compliance 0 is rigid and holds none.
Energy tire_energy(const Tire& t, Vec2 gravity);

// Every tire's, every live dynamic prop's (Box2D's state between ticks) and every vehicle's suspension
// springs' (½ k C², C the hub's offset along its axis). Static and kinematic props have none to
// count: a kinematic prop's driven motion is work done on the world from outside.
Energy world_energy(const World& world);

}  // namespace tire

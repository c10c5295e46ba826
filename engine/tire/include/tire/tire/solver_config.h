// Every solver number a user can tune, in one place. The level's "solver" object fills the first
// block; the rest are engine defaults that a level may also override.
#pragma once

namespace tire {

struct SolverConfig {
  double dt = 1.0 / 60.0;  // fixed tick (s)
  int substeps = 8;        // n: the tick is split into substeps of h = dt/n (Macklin et al. 2019)
  int iterations = 1;      // constraint sweeps per substep
  double damping = 0.0;    // decay rate (1/s) of non-rigid particle motion (0 = none)

  // Anti-tunneling clamp: a particle's speed is limited so that it travels at most this many
  // rest outer-segment lengths in one substep.
  double tunnel_clamp = 1.0;
  // A contact counts as ground (for grounded flags and jumping) when its normal's y is at least
  // this: 0.5 accepts surfaces up to 60 degrees steep.
  double ground_normal_y = 0.5;
  // A tire with a coordinate beyond this (m) or any NaN/Inf is reset to its spawn state.
  double divergence_limit = 1.0e5;
};

}  // namespace tire

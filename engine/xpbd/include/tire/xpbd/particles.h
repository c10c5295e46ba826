// The particle store the solver streams through: structure-of-arrays, one entry per particle.
// Each array is touched by a different phase (x and w by every constraint, x_prev and v only by
// prediction and the velocity update), so keeping them apart keeps the constraint loop's cache
// lines full of what it reads.
#pragma once

#include <cstdint>
#include <vector>

#include "tire/math/vec2.h"

namespace tire {

struct Particles {
  std::vector<Vec2> x;       // position (m)
  std::vector<Vec2> x_prev;  // position at the start of the substep (m)
  std::vector<Vec2> v;       // velocity (m/s)
  std::vector<double> w;     // inverse mass (1/kg); 0 pins the particle

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n) {
    x.resize(n);
    x_prev.resize(n);
    v.resize(n);
    w.resize(n);
  }
};

// The two ends of an XPBD substep (Macklin et al. 2019, "Small Steps", Algorithm 1):
// x_prev ← x; x ← x + h·v (line 5, after v ← v + h·f/m at line 4, which the caller does), and
// after the constraints, v ← (x − x_prev)/h (line 10). Pinned particles (w = 0) stay put.
inline void predict_positions(Particles& p, double h) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.x_prev[i] = p.x[i];
    if (p.w[i] != 0.0) p.x[i] += p.v[i] * h;
  }
}

inline void derive_velocities(Particles& p, double h) {
  const double inv_h = 1.0 / h;
  for (std::size_t i = 0; i < p.size(); ++i) p.v[i] = (p.x[i] - p.x_prev[i]) * inv_h;
}

}  // namespace tire

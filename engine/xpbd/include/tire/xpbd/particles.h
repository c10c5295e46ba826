// The particle store the solver streams through: structure-of-arrays, one entry per particle.
// Each array is touched by a different phase (x and w by every constraint, x_prev and v only by
// prediction and the velocity update), so keeping them apart keeps the constraint loop's cache
// lines full of what it reads.
//
// The arrays are views into one block (tire/math/array_block.h): a tire places them in its own
// block, next to the rest of its per-particle state, with plan() and the constructor from a block;
// a store on its own (a test's) has a block of its own. Either way their size is fixed
// once built. Move-only: a move keeps the arrays where they are; copy_from() copies the values.
#pragma once

#include <cstddef>

#include "tire/math/array_block.h"
#include "tire/math/geometry.h"

namespace tire {

struct Particles {
  ArrayView<Vec2> x;       // position (m)
  ArrayView<Vec2> x_prev;  // position at the start of the substep (m)
  ArrayView<Vec2> v;       // velocity (m/s)
  ArrayView<double> w;     // inverse mass (1/kg); 0 pins the particle

  // Where the four arrays of `count` particles go in a block.
  struct Slots {
    BlockSlot<Vec2> x, x_prev, v;
    BlockSlot<double> w;
  };
  static Slots plan(BlockLayout& layout, std::size_t count) {
    return {layout.add<Vec2>(count), layout.add<Vec2>(count), layout.add<Vec2>(count),
            layout.add<double>(count)};
  }

  Particles() = default;
  // The arrays at `slots` in `block`, which their owner keeps (a tire: its one block). All zero.
  Particles(ArrayBlock& block, const Slots& slots) { bind(block, slots); }
  // `count` particles in a block of their own. All zero.
  explicit Particles(std::size_t count) {
    BlockLayout layout;
    const Slots slots = plan(layout, count);
    own_ = ArrayBlock(layout);
    bind(own_, slots);
  }

  std::size_t size() const { return x.size(); }
  // The values of `o`, which has as many particles.
  void copy_from(const Particles& o) {
    x.assign(o.x);
    x_prev.assign(o.x_prev);
    v.assign(o.v);
    w.assign(o.w);
  }

 private:
  void bind(ArrayBlock& block, const Slots& slots) {
    x = block.construct(slots.x);
    x_prev = block.construct(slots.x_prev);
    v = block.construct(slots.v);
    w = block.construct(slots.w);
  }

  ArrayBlock own_;  // the arrays' block when they have one of their own; empty in a tire's
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

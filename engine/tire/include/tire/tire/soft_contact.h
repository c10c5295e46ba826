// Contacts between tires. Every tread particle of one tire is kept outside the other tire's tread
// polygon: not against its particles (a particle could slip between two of them) but against its
// rim edges, so tires never pass through each other and leave no gap.
//
// The constraint for a particle p inside the other tread, against edge (b0, b1) at barycentric t:
//   C = n·(p − (1−t) b0 − t b1) ≥ 0,  ∇_p C = n, ∇_b0 C = −(1−t) n, ∇_b1 C = −t n,
// solved with zero compliance (XPBD eq. 18 with α = 0), so momentum is kept exactly, with
// position-level static friction on the relative tangential motion (Müller et al. 2020, §3.5).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tire/math/aabb.h"
#include "tire/tire/tire.h"

namespace tire {

struct TirePair {
  std::uint32_t a;  // indices into the world's tire list, a < b
  std::uint32_t b;
};

// Broad phase: sort-and-sweep of the tires' bounds along x, each expanded by how far its tread can
// travel this tick (its fastest particle's speed over dt, plus what gravity adds, plus a skin).
// Sub-quadratic for a spread-out scene, deterministic (ties broken by index), no allocation once
// warmed up.
class TirePairFinder {
 public:
  // The pairs among tires[which[k]] (indices ascending), into `out`.
  void find(const std::vector<Tire>& tires, std::span<const std::uint32_t> which, double dt, double gravity,
            std::vector<TirePair>& out);
  // Tire i's bounds in the last find (i one of `which`): its tread, widened by its travel in dt.
  const Aabb& bounds(std::uint32_t i) const { return bounds_[i]; }

 private:
  struct Entry {
    double min_x;
    std::uint32_t index;
  };
  std::vector<Entry> order_;
  std::vector<Aabb> bounds_;
};

// Room for what the constraints move a particle within a tick, beyond its velocity (m).
inline constexpr double kTirePairSkin = 0.05;

// The edge (x_k, x_k+1) of a tread of n particles whose wedge from `hub` holds the direction d: the
// edge a particle at hub + d would cross. A tread holds its shape, so it is star-shaped about its
// hub; the edge is guessed from the angle and confirmed by a short walk.
std::uint32_t tread_edge_towards(const Vec2* x, std::uint32_t n, Vec2 hub, Vec2 d);

// One iteration of contacts between two tires, both ways. Uses each tire's tread_hub and
// tread_reach from its own iteration. `ground_normal_y` marks particles that
// rest on the other tire as grounded (a tire can jump off a pile).
void solve_tire_contact(Tire& a, Tire& b, double ground_normal_y);

// The same constraint within one tire: its tread particles stay outside its own rim polygon. A
// tire crushed flat bottoms out on its rim, as a real one does, instead of folding through it
// (which would tangle the rings for good). Frictionless. Uses rim_hub and rim_reach.
void keep_tread_outside_rim(Tire& tire);

// Whether the tread–rim contact applies: the rim is stiff (a real rim, not a rubbery one) and
// holds at least a fifth of its area, so that its edges can be found by angle about its hub.
bool rim_can_hold_tread(const Tire& tire);

}  // namespace tire

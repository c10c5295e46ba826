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

#include "tire/math/geometry.h"
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
//
// Each tire keeps at most `max_neighbours` pairs (the level's solver.tire_neighbours,
// SolverConfig::tire_neighbours), so that what the contacts between tires cost a tick follows the
// contacts a tire can have, not how many tires are heaped on one spot (a level may place 1953
// tires of 256 segments on one point: every tire inside every other, 1.9 million pairs). Where a
// tire has more candidates than that, the pairs are chosen nearest first (by the distance between
// their bounds' centres relative to their sizes, then by the nearest index, then the lower), each
// kept while neither of its tires has max_neighbours yet, and a tire left with none then takes its
// nearest (soft_contact.cpp); the choice depends on the tires alone, not on which is asked first.
// Below the limit every candidate is a pair, in the sweep's order, as without it.
class TirePairFinder {
 public:
  // The pairs among tires[which[k]] (indices ascending), into `out`.
  void find(const std::vector<Tire>& tires, std::span<const std::uint32_t> which, double dt, double gravity,
            std::uint32_t max_neighbours, std::vector<TirePair>& out);
  // Tire i's bounds in the last find (i one of `which`): its tread, widened by its travel in dt.
  const Aabb& bounds(std::uint32_t i) const { return bounds_[i]; }
  // Whether the last find left out candidates of a tire past max_neighbours.
  bool capped() const { return capped_; }

 private:
  struct Entry {
    double min_x;
    std::uint32_t index;
  };
  // A candidate pair, a < b, by how near: the distance between the centres of their bounds over the
  // sum of the radii of the circles round them (below 1: overlapping; 0: on one spot), then
  // |a − b|, then the tires; the smaller is the nearer. Relative, so that a tire's nearest are
  // those about it whatever their sizes (by the gap between the circles, every tire's nearest on a
  // heap were the few with the widest bounds, and the rest kept none).
  struct Near {
    double apart;
    std::uint32_t spread;
    std::uint32_t a, b;
    std::uint32_t other(std::uint32_t self) const { return self == a ? b : a; }
    bool operator<(const Near& o) const {
      if (apart != o.apart) return apart < o.apart;
      if (spread != o.spread) return spread < o.spread;
      return a != o.a ? a < o.a : b < o.b;
    }
  };
  static constexpr std::uint32_t kNotCrowded = ~std::uint32_t{0};
  // fn(i, j) for each pair of overlapping bounds, in sweep order.
  template <typename F>
  void sweep(F&& fn) const;
  Near nearness(std::uint32_t i, std::uint32_t j) const;
  void keep_nearest_pairs(std::span<const std::uint32_t> which, std::uint32_t max_neighbours,
                          std::vector<TirePair>& out);
  void offer(std::uint32_t slot, const Near& near, std::size_t k);
  bool give_up_farthest(std::uint32_t j, std::size_t k);

  std::vector<Entry> order_;
  std::vector<Aabb> bounds_;
  std::vector<std::uint32_t> count_;  // per tire: its candidates in this find
  // Per tire: its slot among the crowded (more than max_neighbours candidates), or kNotCrowded.
  std::vector<std::uint32_t> slot_;
  // Per crowded tire, slot s at s · max_neighbours: its nearest crowded candidates (a max-heap
  // during the sweep) and the tires it keeps.
  std::vector<Near> nearest_;
  std::vector<std::uint32_t> nearest_size_;
  std::vector<std::uint32_t> kept_;
  std::vector<std::uint32_t> kept_size_;
  std::vector<Near> candidates_;       // the pairs the greedy choice is among
  std::vector<std::uint32_t> degree_;  // per tire: the pairs it keeps
  std::vector<Near> best_;             // per tire: its nearest candidate with a crowded tire in it
  bool capped_ = false;
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

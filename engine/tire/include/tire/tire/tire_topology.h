// What every tire of one shape has in common (Jolt's shared settings, as its SoftBodySharedSettings):
// which particles each distance constraint joins, which compliance each takes (tread ring, rim ring,
// spoke), the cut of the constraints into SIMD batches, and the particle ranges of the two area
// constraints. Immutable, held by std::shared_ptr<const TireTopology> by every tire of the shape.
//
// The shape is the segment count and the spoke pattern. The radii are not part of it: the rest
// lengths and rest areas are measured on each tire as built, at its own position, and the rounding
// of those sums depends on where the tire stands, so they are per tire (sharing them would change
// the bits of every replay).
#pragma once

#include <compare>
#include <cstdint>
#include <memory>
#include <vector>

#include "tire/tire/tire_spec.h"
#include "tire/xpbd/distance_constraint.h"

namespace tire {

struct TireShape {
  int segments = 28;
  SpokePattern spokes = SpokePattern::cross;
  auto operator<=>(const TireShape&) const = default;
  static TireShape of(const TireSpec& spec) { return {spec.segments, spec.spokes}; }
};

class TireTopology {
 public:
  // The compliance groups of `distance`: the index of each kind's α in the tire's set.
  enum Group : std::uint32_t { outer_ring = 0, inner_ring = 1, spoke = 2, group_count = 3 };

  explicit TireTopology(TireShape shape);

  TireShape shape() const { return shape_; }
  std::uint32_t segments() const { return n_; }
  std::uint32_t particle_count() const { return 2 * n_; }
  // Rings first (outer at [0, N), inner at [N, 2N)), then spokes from 2N.
  const std::shared_ptr<const DistanceLayout>& distance() const { return distance_; }

 private:
  TireShape shape_;
  std::uint32_t n_;
  std::shared_ptr<const DistanceLayout> distance_;
};

// The topologies of the shapes a world holds, one per shape: what World::add_tire hands its tires.
// Looked up by value (a short vector searched in order), never by address, so it is deterministic.
class TireTopologies {
 public:
  std::shared_ptr<const TireTopology> of(TireShape shape);
  std::size_t size() const { return topologies_.size(); }

 private:
  std::vector<std::shared_ptr<const TireTopology>> topologies_;
};

}  // namespace tire

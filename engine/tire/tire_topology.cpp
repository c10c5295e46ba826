#include "tire/tire/tire_topology.h"

#include "tire/math/check.h"

namespace tire {

namespace {

// Appends ring edges (i, i+1) of a ring starting at `first`: even edges, then odd ones, so that
// consecutive constraints share no particle and the CPU can overlap their square roots.
void add_ring(std::vector<DistanceLayout::Pair>& pairs, std::vector<std::uint32_t>& group,
              std::uint32_t first, std::uint32_t n, std::uint32_t g) {
  for (std::uint32_t parity = 0; parity < 2; ++parity)
    for (std::uint32_t i = parity; i < n; i += 2) {
      pairs.push_back({first + i, first + (i + 1) % n});
      group.push_back(g);
    }
}

}  // namespace

TireTopology::TireTopology(TireShape shape) : shape_(shape), n_(static_cast<std::uint32_t>(shape.segments)) {
  TIRE_ASSERT(shape.segments >= 3, "a tire ring of fewer than three segments");
  const std::uint32_t n = n_;
  const std::size_t count = (shape.spokes == SpokePattern::cross ? 5u : 3u) * n;
  std::vector<DistanceLayout::Pair> pairs;
  std::vector<std::uint32_t> group;
  pairs.reserve(count);
  group.reserve(count);
  add_ring(pairs, group, 0, n, outer_ring);
  add_ring(pairs, group, n, n, inner_ring);
  const auto add_spoke = [&](std::uint32_t a, std::uint32_t b) {
    pairs.push_back({a, b});
    group.push_back(spoke);
  };
  for (std::uint32_t i = 0; i < n; ++i) add_spoke(n + i, i);
  if (shape.spokes == SpokePattern::cross) {
    for (std::uint32_t i = 0; i < n; ++i) add_spoke(n + i, (i + 1) % n);
    for (std::uint32_t i = 0; i < n; ++i) add_spoke(n + i, (i + n - 1) % n);
  }
  TIRE_ASSERT(pairs.size() == count, "a ring or a spoke is missing");
  distance_ = std::make_shared<const DistanceLayout>(std::move(pairs), std::move(group));
}

std::shared_ptr<const TireTopology> TireTopologies::of(TireShape shape) {
  for (const std::shared_ptr<const TireTopology>& t : topologies_)
    if (t->shape() == shape) return t;
  topologies_.push_back(std::make_shared<const TireTopology>(shape));
  return topologies_.back();
}

}  // namespace tire

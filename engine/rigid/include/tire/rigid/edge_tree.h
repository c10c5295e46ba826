// A bounding-volume tree over the edges of a polyline (a chain prop's), built once when the prop is
// made: what a particle's contact asks is which edges lie near its path, and the answer costs the
// depth of the tree and the edges near it, not the chain's length (a chain may have 100 000 points).
//
// A polyline is its own spatial order: consecutive edges share a point, so a run of consecutive
// edges is a stretch of the line, and the box of a run is a tight bound. The tree is the complete
// binary tree over runs of kLeafEdges edges in index order (node k's children 2k and 2k + 1, the
// root 1), each node the box of its run, widened by a margin (a chain's thickness). No sorting, no
// hashing: a query visits the edges near it in ascending index order, as a loop over all edges
// would meet them, so a caller that stops at the first edge of some kind gets the same edge.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "tire/math/geometry.h"

namespace tire {

class EdgeTree {
 public:
  static constexpr std::size_t kLeafEdges = 4;

  // Edges i = (points[i], points[(i + 1) % size]) for i < edge_count, each box widened by `margin`
  // (≥ 0). Allocates.
  void build(std::span<const Vec2> points, std::size_t edge_count, double margin);

  std::size_t edge_count() const { return edges_; }

  // fn(i) for every edge i whose widened box may overlap `box` (every one that does, and some
  // beside it in a leaf), in ascending order, until fn returns false. Returns how many edges it
  // passed to fn. Does not allocate.
  template <typename F>
  std::size_t visit(const Aabb& box, F&& fn) const {
    if (edges_ == 0) return 0;
    std::size_t visited = 0;
    std::array<std::uint32_t, 64> stack;  // depth ≤ 33: the leaves number at most 2³²
    std::size_t top = 0;
    stack[top++] = 1;
    while (top > 0) {
      const std::uint32_t node = stack[--top];
      if (!nodes_[node].overlaps(box)) continue;
      if (node < leaves_) {
        stack[top++] = 2 * node + 1;  // the right child after the left: ascending edges
        stack[top++] = 2 * node;
        continue;
      }
      const std::size_t first = (node - leaves_) * kLeafEdges;
      const std::size_t last = std::min(first + kLeafEdges, edges_);
      for (std::size_t i = first; i < last; ++i) {
        ++visited;
        if (!fn(i)) return visited;
      }
    }
    return visited;
  }

 private:
  std::vector<Aabb> nodes_;   // 2 × leaves_: [1, leaves_) inner, [leaves_, 2 leaves_) the runs; [0] unused
  std::uint32_t leaves_ = 0;  // a power of two; runs past the last edge hold an empty box
  std::size_t edges_ = 0;
};

}  // namespace tire

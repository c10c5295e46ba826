#include "tire/rigid/edge_tree.h"

#include <bit>
#include <limits>

namespace tire {

void EdgeTree::build(std::span<const Vec2> points, std::size_t edge_count, double margin) {
  edges_ = edge_count;
  const std::size_t runs = (edge_count + kLeafEdges - 1) / kLeafEdges;
  leaves_ = static_cast<std::uint32_t>(std::bit_ceil(std::max<std::size_t>(runs, 1)));
  constexpr double inf = std::numeric_limits<double>::infinity();
  const Aabb empty{{inf, inf}, {-inf, -inf}};  // overlaps nothing, and a union leaves it out
  nodes_.assign(2 * std::size_t{leaves_}, empty);
  const auto unite = [](const Aabb& a, const Aabb& b) {
    return Aabb{{std::min(a.min.x, b.min.x), std::min(a.min.y, b.min.y)},
                {std::max(a.max.x, b.max.x), std::max(a.max.y, b.max.y)}};
  };
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < edge_count; ++i) {
    const Vec2 a = points[i], b = points[(i + 1) % n];
    const Aabb edge{{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}};
    Aabb& leaf = nodes_[leaves_ + i / kLeafEdges];
    leaf = unite(leaf, edge.expanded(margin));
  }
  for (std::size_t k = leaves_; k-- > 1;) nodes_[k] = unite(nodes_[2 * k], nodes_[2 * k + 1]);
}

}  // namespace tire

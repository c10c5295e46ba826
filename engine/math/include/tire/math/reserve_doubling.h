// Room for n items in a vector reserved again each time the scene grows by one (a tire added): the
// capacity at least doubles when it must grow, so n additions reallocate O(log n) times, not n.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace tire {

template <typename T>
void reserve_doubling(std::vector<T>& v, std::size_t n) {
  if (n > v.capacity()) v.reserve(std::max(n, 2 * v.capacity()));
}

}  // namespace tire

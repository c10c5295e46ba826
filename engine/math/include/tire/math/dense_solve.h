// Small dense linear systems, solved in place.
#pragma once

#include <cmath>
#include <cstddef>
#include <utility>

namespace tire {

// Gaussian elimination with partial pivoting on the m × m system in the first m rows of `a`, its
// right-hand side in column m, which ends holding the solution. False when the system is singular
// or not finite (then `a` is left part-way).
template <std::size_t Rows, std::size_t Columns>
bool solve_augmented(double (&a)[Rows][Columns], std::size_t m) {
  static_assert(Columns == Rows + 1, "an augmented system: one column more than rows");
  for (std::size_t c = 0; c < m; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < m; ++r)
      if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
    if (!(std::abs(a[pivot][c]) > 0.0) || !std::isfinite(a[pivot][c])) return false;
    if (pivot != c)
      for (std::size_t k = c; k <= m; ++k) std::swap(a[c][k], a[pivot][k]);
    for (std::size_t r = c + 1; r < m; ++r) {
      const double factor = a[r][c] / a[c][c];
      for (std::size_t k = c; k <= m; ++k) a[r][k] -= factor * a[c][k];
    }
  }
  for (std::size_t r = m; r-- > 0;) {
    double v = a[r][m];
    for (std::size_t k = r + 1; k < m; ++k) v -= a[r][k] * a[k][m];
    a[r][m] = v / a[r][r];
  }
  return true;
}

}  // namespace tire

#include "tire/xpbd/cyclic_block_cholesky.h"

#include <algorithm>
#include <cmath>

#include "tire/math/check.h"

namespace tire {

namespace {

constexpr std::size_t B = CyclicBlockCholesky::kBlock;

double& at(Block4& m, std::size_t r, std::size_t c) { return m[r * B + c]; }
double at(const Block4& m, std::size_t r, std::size_t c) { return m[r * B + c]; }

// m ← m − a bᵀ
void subtract_abt(Block4& m, const Block4& a, const Block4& b) {
  for (std::size_t r = 0; r < B; ++r)
    for (std::size_t c = 0; c < B; ++c) {
      double s = 0.0;
      for (std::size_t k = 0; k < B; ++k) s += at(a, r, k) * at(b, c, k);
      at(m, r, c) -= s;
    }
}

// m ← m − a aᵀ on the lower triangle only (what cholesky() reads of a symmetric block).
void subtract_aat_lower(Block4& m, const Block4& a) {
  for (std::size_t r = 0; r < B; ++r)
    for (std::size_t c = 0; c <= r; ++c) {
      double s = 0.0;
      for (std::size_t k = 0; k < B; ++k) s += at(a, r, k) * at(a, c, k);
      at(m, r, c) -= s;
    }
}

Block4 transpose(const Block4& m) {
  Block4 t{};
  for (std::size_t r = 0; r < B; ++r)
    for (std::size_t c = 0; c < B; ++c) at(t, r, c) = at(m, c, r);
  return t;
}

// m ← its lower Cholesky factor (the upper triangle is zeroed). False on a pivot that is not
// positive (or not finite).
bool cholesky(Block4& m) {
  for (std::size_t j = 0; j < B; ++j) {
    double d = at(m, j, j);
    for (std::size_t k = 0; k < j; ++k) d -= at(m, j, k) * at(m, j, k);
    if (!(d > 0.0) || !std::isfinite(d)) return false;
    const double l = std::sqrt(d);
    at(m, j, j) = l;
    for (std::size_t i = j + 1; i < B; ++i) {
      double s = at(m, i, j);
      for (std::size_t k = 0; k < j; ++k) s -= at(m, i, k) * at(m, j, k);
      at(m, i, j) = s / l;
    }
    for (std::size_t c = j + 1; c < B; ++c) at(m, j, c) = 0.0;
  }
  return true;
}

// v ← L⁻¹ v (forward substitution)
void lower_solve(const Block4& l, double* v) {
  for (std::size_t i = 0; i < B; ++i) {
    double s = v[i];
    for (std::size_t k = 0; k < i; ++k) s -= at(l, i, k) * v[k];
    v[i] = s / at(l, i, i);
  }
}

// v ← L⁻ᵀ v (back substitution with Lᵀ)
void upper_solve(const Block4& l, double* v) {
  for (std::size_t i = B; i-- > 0;) {
    double s = v[i];
    for (std::size_t k = i + 1; k < B; ++k) s -= at(l, k, i) * v[k];
    v[i] = s / at(l, i, i);
  }
}

// m ← m L⁻ᵀ: each row x of the result solves L xᵀ = (row of m)ᵀ.
void right_solve_transpose(Block4& m, const Block4& l) {
  for (std::size_t r = 0; r < B; ++r) lower_solve(l, m.data() + r * B);
}

// v ← v − a x
void subtract_product(double* v, const Block4& a, const double* x) {
  for (std::size_t r = 0; r < B; ++r) {
    double s = 0.0;
    for (std::size_t k = 0; k < B; ++k) s += at(a, r, k) * x[k];
    v[r] -= s;
  }
}

// v ← v − aᵀ x
void subtract_transpose_product(double* v, const Block4& a, const double* x) {
  for (std::size_t c = 0; c < B; ++c) {
    double s = 0.0;
    for (std::size_t k = 0; k < B; ++k) s += at(a, k, c) * x[k];
    v[c] -= s;
  }
}

}  // namespace

void CyclicBlockCholesky::reserve(std::size_t blocks) {
  diag_.resize(std::max(diag_.size(), blocks));
  couple_.resize(std::max(couple_.size(), blocks));
  border_.resize(std::max(border_.size(), blocks));
}

void CyclicBlockCholesky::reset(std::size_t blocks) {
  TIRE_ASSERT(blocks >= 3 && blocks <= diag_.size(), "a cyclic block matrix needs 3 blocks or more, within reserve()");
  blocks_ = blocks;
  for (std::size_t k = 0; k < blocks; ++k) {
    diag_[k].fill(0.0);
    couple_[k].fill(0.0);
  }
}

bool CyclicBlockCholesky::factor() {
  const std::size_t p = blocks_;
  // The chain 1 … P−1, then the border block 0 (see the header).
  for (std::size_t j = 1; j < p; ++j) {
    if (j > 1) subtract_aat_lower(diag_[j], couple_[j - 1]);  // K_jj − L_{j,j−1} L_{j,j−1}ᵀ
    if (!cholesky(diag_[j])) return false;
    // Block 0's row: K_{0,j} is K_{1,0}ᵀ at j = 1 and the wrap K_{0,P−1} at j = P−1, zero between.
    Block4& b = border_[j];
    if (j == 1) b = transpose(couple_[0]);
    else if (j == p - 1) b = couple_[p - 1];
    else b.fill(0.0);
    if (j > 1) subtract_abt(b, border_[j - 1], couple_[j - 1]);  // − L_{0,j−1} L_{j,j−1}ᵀ
    right_solve_transpose(b, diag_[j]);
    if (j + 1 < p) right_solve_transpose(couple_[j], diag_[j]);  // L_{j+1,j} = K_{j+1,j} L_jj⁻ᵀ
    subtract_aat_lower(diag_[0], b);                               // K_00 − Σ L_{0,j} L_{0,j}ᵀ
  }
  return cholesky(diag_[0]);
}

void CyclicBlockCholesky::forward(double* y) const {
  const std::size_t p = blocks_;
  double* y0 = y;
  for (std::size_t j = 1; j < p; ++j) {
    double* yj = y + B * j;
    if (j > 1) subtract_product(yj, couple_[j - 1], yj - B);
    lower_solve(diag_[j], yj);
    subtract_product(y0, border_[j], yj);
  }
  lower_solve(diag_[0], y0);
}

void CyclicBlockCholesky::backward(double* x) const {
  const std::size_t p = blocks_;
  const double* x0 = x;
  upper_solve(diag_[0], x);
  for (std::size_t j = p - 1; j >= 1; --j) {
    double* xj = x + B * j;
    if (j + 1 < p) subtract_transpose_product(xj, couple_[j], xj + B);
    subtract_transpose_product(xj, border_[j], x0);
    upper_solve(diag_[j], xj);
  }
}

}  // namespace tire

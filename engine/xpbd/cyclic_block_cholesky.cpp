#include "tire/xpbd/cyclic_block_cholesky.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "tire/math/check.h"

namespace tire {

namespace {

constexpr std::size_t B = CyclicBlockCholesky::kBlock;

// Four doubles as one value (GCC's vector extension): element-wise IEEE arithmetic, as the scalar
// code would do it lane by lane, compiled to whatever vector unit the target has. Same bits on any.
// (GCC warns that passing one by value has another ABI under AVX: these functions are internal to
// this file, so no other object ever calls them.)
#pragma GCC diagnostic ignored "-Wpsabi"
typedef double V4 __attribute__((vector_size(32)));

V4 row(const Block4& m, std::size_t r) {
  V4 v;
  std::memcpy(&v, m.data() + B * r, sizeof v);
  return v;
}
void set_row(Block4& m, std::size_t r, V4 v) { std::memcpy(m.data() + B * r, &v, sizeof v); }
V4 load(const double* p) {
  V4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
void store(double* p, V4 v) { std::memcpy(p, &v, sizeof v); }
V4 splat(double x) { return V4{x, x, x, x}; }

double& at(Block4& m, std::size_t r, std::size_t c) { return m[r * B + c]; }
double at(const Block4& m, std::size_t r, std::size_t c) { return m[r * B + c]; }

Block4 transpose(const Block4& m) {
  Block4 t{};
  for (std::size_t r = 0; r < B; ++r)
    for (std::size_t c = 0; c < B; ++c) at(t, r, c) = at(m, c, r);
  return t;
}

// The blocks below the diagonal are kept transposed (Aᵀ, row-major), so that what the factor and
// the forward solve need of them are rows: A x = Σ_k x_k (row k of Aᵀ).

// m ← m − (A Bᵀ) given Aᵀ and Bᵀ: row r of A Bᵀ is Σ_k A_rk (row k of Bᵀ) = Σ_k (Aᵀ)_kr (Bᵀ)_k.
void subtract_abt(Block4& m, const Block4& at_, const Block4& bt) {
  const V4 b0 = row(bt, 0), b1 = row(bt, 1), b2 = row(bt, 2), b3 = row(bt, 3);
  for (std::size_t r = 0; r < B; ++r) {
    V4 s = splat(at(at_, 0, r)) * b0;
    s += splat(at(at_, 1, r)) * b1;
    s += splat(at(at_, 2, r)) * b2;
    s += splat(at(at_, 3, r)) * b3;
    set_row(m, r, row(m, r) - s);
  }
}

// m ← L⁻¹ for m's lower Cholesky factor L (m = L Lᵀ), and m_t ← L⁻ᵀ: the solves then multiply by
// them, four lanes at a time, where substitution would go entry by entry. Found as m = U D Uᵀ (U unit
// lower triangular), so that the chain from pivot to pivot holds a division each and no square
// root: L = U D^½ and L⁻¹ = D^-½ U⁻¹, whose four square roots come last, side by side. False on a
// pivot that is not positive (or not finite).
bool cholesky_inverse(Block4& m, Block4& m_t) {
  // U and U D below the diagonal ((U D)_ij = U_ij d_j), written before they are read (zeroing them
  // took a quarter of the time).
  double u[B][B], ud[B][B], d[B];
  for (std::size_t j = 0; j < B; ++j) {
    double dj = at(m, j, j);
    for (std::size_t k = 0; k < j; ++k) dj -= u[j][k] * ud[j][k];
    if (!(dj > 0.0) || !std::isfinite(dj)) return false;
    d[j] = dj;
    const double inv = 1.0 / dj;
    for (std::size_t i = j + 1; i < B; ++i) {
      double s = at(m, i, j);
      for (std::size_t k = 0; k < j; ++k) s -= u[i][k] * ud[j][k];
      ud[i][j] = s;
      u[i][j] = s * inv;
    }
  }
  // U⁻¹ column by column: 1 on the diagonal, (U⁻¹)_ij = −Σ_{k=j}^{i−1} U_ik (U⁻¹)_kj below it; then
  // row i times d_i^-½. Built in a local array and written once: written into m as it was built, the
  // stores and loads through memory cost more than the arithmetic (on AVX2 most of all).
  double inv[B][B];
  for (std::size_t j = 0; j < B; ++j) {
    inv[j][j] = 1.0;
    for (std::size_t i = j + 1; i < B; ++i) {
      double s = 0.0;
      for (std::size_t k = j; k < i; ++k) s -= u[i][k] * inv[k][j];
      inv[i][j] = s;
    }
  }
  for (std::size_t i = 0; i < B; ++i) {
    const double scale = 1.0 / std::sqrt(d[i]);
    for (std::size_t j = 0; j < B; ++j) {
      const double v = j <= i ? inv[i][j] * scale : 0.0;
      at(m, i, j) = v;
      at(m_t, j, i) = v;
    }
  }
  return true;
}

// X ← A X given A = L⁻¹ (row-major, lower triangular), the four columns of X at once: row r of
// A X is Σ_{k ≤ r} A_rk (row k of X).
void lower_multiply_rows(const Block4& a, Block4& x) {
  const V4 x0 = row(x, 0), x1 = row(x, 1), x2 = row(x, 2), x3 = row(x, 3);
  set_row(x, 0, splat(at(a, 0, 0)) * x0);
  set_row(x, 1, splat(at(a, 1, 0)) * x0 + splat(at(a, 1, 1)) * x1);
  set_row(x, 2, splat(at(a, 2, 0)) * x0 + splat(at(a, 2, 1)) * x1 + splat(at(a, 2, 2)) * x2);
  set_row(
      x, 3,
      splat(at(a, 3, 0)) * x0 + splat(at(a, 3, 1)) * x1 + splat(at(a, 3, 2)) * x2 + splat(at(a, 3, 3)) * x3);
}

// A x, given Aᵀ: Σ_k x_k (row k of Aᵀ).
V4 product(const Block4& a_t, const double* x) {
  V4 s = splat(x[0]) * row(a_t, 0);
  s += splat(x[1]) * row(a_t, 1);
  s += splat(x[2]) * row(a_t, 2);
  s += splat(x[3]) * row(a_t, 3);
  return s;
}

// v ← v − A x, given Aᵀ.
void subtract_product(double* v, const Block4& a_t, const double* x) { store(v, load(v) - product(a_t, x)); }

// v ← A v, given Aᵀ.
void multiply(double* v, const Block4& a_t) { store(v, product(a_t, v)); }

// v ← v − Aᵀ x, given Aᵀ: (Aᵀ x)_r = (row r of Aᵀ)·x.
void subtract_transpose_product(double* v, const Block4& a_t, const double* x) {
  for (std::size_t r = 0; r < B; ++r) {
    double s = 0.0;
    for (std::size_t k = 0; k < B; ++k) s += at(a_t, r, k) * x[k];
    v[r] -= s;
  }
}

}  // namespace

void CyclicBlockCholesky::reserve(std::size_t blocks) {
  diag_.resize(std::max(diag_.size(), blocks));
  diag_t_.resize(std::max(diag_t_.size(), blocks));
  couple_.resize(std::max(couple_.size(), blocks));
  border_.resize(std::max(border_.size(), blocks));
}

void CyclicBlockCholesky::reset(std::size_t blocks) {
  TIRE_ASSERT(blocks >= 3 && blocks <= diag_.size(),
              "a cyclic block matrix needs 3 blocks or more, within reserve()");
  blocks_ = blocks;
  for (std::size_t k = 0; k < blocks; ++k) {
    diag_[k].fill(0.0);
    couple_[k].fill(0.0);
  }
}

bool CyclicBlockCholesky::factor() {
  const std::size_t p = blocks_;
  for (std::size_t k = 0; k < p; ++k) couple_[k] = transpose(couple_[k]);  // kept transposed from here on
  // The chain 1 … P−1, then the border block 0 (see the header). couple_[j] holds L_{j+1,j}ᵀ and
  // border_[j] holds L_{0,j}ᵀ.
  for (std::size_t j = 1; j < p; ++j) {
    if (j > 1) subtract_abt(diag_[j], couple_[j - 1], couple_[j - 1]);  // K_jj − L_{j,j−1} L_{j,j−1}ᵀ
    if (!cholesky_inverse(diag_[j], diag_t_[j])) return false;
    // Block 0's row: K_{0,j} is K_{1,0}ᵀ at j = 1 and the wrap K_{0,P−1} at j = P−1, zero between;
    // here transposed: K_{1,0} and K_{0,P−1}ᵀ.
    Block4& b = border_[j];
    if (j == 1)
      b = transpose(couple_[0]);
    else if (j == p - 1)
      b = couple_[p - 1];
    else
      b.fill(0.0);
    if (j > 1)
      subtract_abt(b, couple_[j - 1], border_[j - 1]);  // (L_{0,j−1} L_{j,j−1}ᵀ)ᵀ = L_{j,j−1} L_{0,j−1}ᵀ
    lower_multiply_rows(diag_[j], b);                   // L_{0,j}ᵀ = L_jj⁻¹ (K_{0,j} − …)ᵀ
    if (j + 1 < p) lower_multiply_rows(diag_[j], couple_[j]);  // L_{j+1,j}ᵀ = L_jj⁻¹ K_{j+1,j}ᵀ
    subtract_abt(diag_[0], b, b);                              // K_00 − Σ L_{0,j} L_{0,j}ᵀ
  }
  return cholesky_inverse(diag_[0], diag_t_[0]);
}

void CyclicBlockCholesky::forward(double* const* ys, std::size_t count, std::size_t first) const {
  TIRE_ASSERT(count <= kMaxRightHandSides, "too many right-hand sides for one forward solve");
  const std::size_t p = blocks_;
  TIRE_ASSERT(first >= 1 && first <= p, "a forward solve's first block outside the chain");
  // Block by block, every vector at once: their chains are independent, so the CPU overlaps them.
  // Block 0 of each, which every block's border term updates, stays in a register meanwhile.
  V4 head[kMaxRightHandSides];
  for (std::size_t v = 0; v < count; ++v) head[v] = load(ys[v]);
  for (std::size_t j = first; j < p; ++j)
    for (std::size_t v = 0; v < count; ++v) {
      double* yj = ys[v] + B * j;
      if (j > first) subtract_product(yj, couple_[j - 1], yj - B);
      multiply(yj, diag_t_[j]);  // L_jj⁻¹ y_j
      head[v] -= product(border_[j], yj);
    }
  for (std::size_t v = 0; v < count; ++v) {
    store(ys[v], head[v]);
    multiply(ys[v], diag_t_[0]);
  }
}

void CyclicBlockCholesky::backward(double* const* xs, std::size_t count) const {
  TIRE_ASSERT(count <= kMaxRightHandSides, "too many right-hand sides for one backward solve");
  // Block by block, every vector at once, each with the arithmetic of backward(x) alone.
  const std::size_t p = blocks_;
  for (std::size_t v = 0; v < count; ++v) multiply(xs[v], diag_[0]);  // L_00⁻ᵀ x_0
  for (std::size_t j = p - 1; j >= 1; --j)
    for (std::size_t v = 0; v < count; ++v) {
      double* xj = xs[v] + B * j;
      if (j + 1 < p) subtract_transpose_product(xj, couple_[j], xj + B);
      subtract_transpose_product(xj, border_[j], xs[v]);
      multiply(xj, diag_[j]);
    }
}

}  // namespace tire

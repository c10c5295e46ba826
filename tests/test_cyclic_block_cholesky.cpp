// The global method's factorisation: K = L Lᵀ for a cyclic block-tridiagonal K, checked against a
// dense elimination of the same matrix (written here for the test, never used by the engine).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "tire/xpbd/cyclic_block_cholesky.h"

using namespace tire;

namespace {

constexpr std::size_t B = CyclicBlockCholesky::kBlock;

// A random symmetric positive definite matrix of that shape: random couplings, and diagonal blocks
// made dominant. Returned dense (row-major), and written into `k`.
std::vector<double> random_cyclic(CyclicBlockCholesky& k, std::size_t blocks, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::size_t n = B * blocks;
  std::vector<double> dense(n * n, 0.0);
  k.reserve(blocks);
  k.reset(blocks);
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t next = (b + 1) % blocks;
    for (std::size_t r = 0; r < B; ++r)
      for (std::size_t c = 0; c < B; ++c) {
        const double v = u(rng);
        k.coupling(b)[r * B + c] = v;  // K_{next, b}
        dense[(B * next + r) * n + B * b + c] = v;
        dense[(B * b + c) * n + B * next + r] = v;
      }
  }
  for (std::size_t b = 0; b < blocks; ++b)
    for (std::size_t r = 0; r < B; ++r)
      for (std::size_t c = 0; c <= r; ++c) {
        const double v = r == c ? 4.0 * B + 1.0 + u(rng) : 0.5 * u(rng);
        k.diagonal(b)[r * B + c] = k.diagonal(b)[c * B + r] = v;
        dense[(B * b + r) * n + B * b + c] = dense[(B * b + c) * n + B * b + r] = v;
      }
  return dense;
}

// x ← A⁻¹ x by Gaussian elimination with partial pivoting.
void dense_solve(std::vector<double> a, std::vector<double>& x) {
  const std::size_t n = x.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(a[r * n + c]) > std::abs(a[pivot * n + c])) pivot = r;
    for (std::size_t k = 0; k < n; ++k) std::swap(a[c * n + k], a[pivot * n + k]);
    std::swap(x[c], x[pivot]);
    for (std::size_t r = c + 1; r < n; ++r) {
      const double f = a[r * n + c] / a[c * n + c];
      for (std::size_t k = c; k < n; ++k) a[r * n + k] -= f * a[c * n + k];
      x[r] -= f * x[c];
    }
  }
  for (std::size_t r = n; r-- > 0;) {
    double s = x[r];
    for (std::size_t k = r + 1; k < n; ++k) s -= a[r * n + k] * x[k];
    x[r] = s / a[r * n + r];
  }
}

}  // namespace

TEST_CASE("the cyclic block Cholesky solves what a dense elimination solves", "[unit][global]") {
  const std::size_t blocks = GENERATE(3, 4, 7, 28);
  std::mt19937 rng(static_cast<unsigned>(blocks));
  CyclicBlockCholesky k;
  const std::vector<double> dense = random_cyclic(k, blocks, rng);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> rhs(B * blocks);
  for (double& v : rhs) v = u(rng);
  std::vector<double> expected = rhs, got = rhs;
  dense_solve(dense, expected);
  REQUIRE(k.factor());
  k.solve(got.data());
  for (std::size_t i = 0; i < rhs.size(); ++i) CHECK(got[i] == Approx(expected[i]).margin(1e-12));
  // forward then backward is the solve, and forward alone gives y with |y|² = rhsᵀ K⁻¹ rhs.
  std::vector<double> y = rhs;
  k.forward(y.data());
  double yy = 0.0, rk = 0.0;
  for (std::size_t i = 0; i < rhs.size(); ++i) {
    yy += y[i] * y[i];
    rk += rhs[i] * expected[i];
  }
  CHECK(yy == Approx(rk).epsilon(1e-12));
}

TEST_CASE("the cyclic block Cholesky refuses a matrix that is not positive definite", "[unit][global]") {
  std::mt19937 rng(7);
  CyclicBlockCholesky k;
  random_cyclic(k, 5, rng);
  k.diagonal(3)[2 * B + 2] = -1.0;
  CHECK_FALSE(k.factor());
}

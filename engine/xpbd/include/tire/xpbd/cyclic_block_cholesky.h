// Cholesky factorisation K = L Lᵀ of a symmetric positive definite matrix that is block
// tridiagonal with a cyclic wrap: P blocks of 4×4 in a ring, block k coupled only to blocks k ± 1
// (mod P). A tire's system matrix has this shape when its unknowns are ordered segment by segment
// (tread particle i and rim particle i form block i): every constraint joins a segment to itself or
// to a neighbour.
//
// The wrap is handled by eliminating block 0 last (a one-block border): blocks 1 … P−1 form a
// plain block-tridiagonal chain, and block 0's row of L fills in along the whole chain. Cost: about
// 15 4×4 products a block, O(P) in all; storage 3P blocks. No allocation after reserve().
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace tire {

// A 4×4 block, row-major.
using Block4 = std::array<double, 16>;

class CyclicBlockCholesky {
 public:
  static constexpr std::size_t kBlock = 4;

  // Room for up to `blocks` blocks (allocates; call outside the step).
  void reserve(std::size_t blocks);
  // Starts a new matrix of `blocks` blocks (3 ≤ blocks ≤ the reserved count), all zero.
  void reset(std::size_t blocks);
  std::size_t blocks() const { return blocks_; }
  std::size_t size() const { return kBlock * blocks_; }

  // The matrix, filled by the caller between reset() and factor(): the diagonal block K_kk and the
  // coupling K_{k+1,k} (block row k+1 mod P, block column k). K_{k,k+1} is its transpose.
  Block4& diagonal(std::size_t k) { return diag_[k]; }
  Block4& coupling(std::size_t k) { return couple_[k]; }

  // Factors in place. False when a pivot is not positive (K not positive definite); the factor is
  // then unusable.
  bool factor();
  // y ← L⁻¹ y and x ← L⁻ᵀ x, on vectors of size() entries in block order (block k at 4k).
  void forward(double* y) const { forward(&y, 1); }
  void backward(double* x) const { backward(&x, 1); }
  // y ← L⁻¹ y for `count` vectors at once (at most kMaxRightHandSides), faster than one by one.
  // `first`: every vector is zero in blocks 1 … first − 1 (blocks() when only block 0 is not), so
  // that L⁻¹ y is too, and the sweep starts at block `first`.
  static constexpr std::size_t kMaxRightHandSides = 4;
  void forward(double* const* ys, std::size_t count, std::size_t first = 1) const;
  // x ← L⁻ᵀ x for `count` vectors at once (at most kMaxRightHandSides), each as backward(x) does it.
  void backward(double* const* xs, std::size_t count) const;
  // x ← K⁻¹ x: forward then backward.
  void solve(double* x) const {
    forward(x);
    backward(x);
  }

 private:
  std::size_t blocks_ = 0;
  // Before factor(): K's blocks. After: L's, with diag_[k] = L_kk⁻¹ (lower triangular) and
  // diag_t_[k] = L_kk⁻ᵀ, so that the solves multiply by them; couple_[k] = L_{k+1,k}ᵀ for the chain
  // k = 1 … P−2, and border_[k] = L_{0,k}ᵀ (block 0's row) for k = 1 … P−1: the blocks below the
  // diagonal are kept transposed, so what the factor and the forward solve read of them are rows,
  // four doubles side by side.
  std::vector<Block4> diag_;
  std::vector<Block4> diag_t_;
  std::vector<Block4> couple_;
  std::vector<Block4> border_;
};

}  // namespace tire

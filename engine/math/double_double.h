// Error-free transformations (private to the math layer): a sum or a product of two doubles as
// an unevaluated pair hi + lo that holds it exactly. They use only +, −, × in round-to-nearest,
// which IEEE 754 makes exact everywhere, and they rely on no multiply–add being fused (the project
// compiles with -ffp-contract=off). References: Knuth, TAOCP vol. 2, 4.2.2 (two_sum); Dekker,
// "A floating-point technique for extending the available precision", Numer. Math. 18 (1971)
// (fast_two_sum, split, two_product); Muller et al., "Handbook of Floating-Point Arithmetic",
// ch. 4.
#pragma once

#include <bit>
#include <cstdint>

namespace tire::detail {

// std::bit_cast, which the browser build's libc++ (emscripten 3.1.6) does not have yet: the same
// compiler builtin it is made of (GCC 11 and clang).
template <typename To, typename From>
constexpr To bit_cast(const From& from) noexcept {
  static_assert(sizeof(To) == sizeof(From));
  return __builtin_bit_cast(To, from);
}

// A value as hi + lo with |lo| <= ulp(hi) / 2.
struct DoubleDouble {
  double hi;
  double lo;
};

// a + b exactly, for any a and b (Knuth's TwoSum: 6 operations).
inline DoubleDouble two_sum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  const double e = (a - (s - bb)) + (b - bb);
  return {s, e};
}

// a + b exactly, when |a| >= |b| or a == 0 (Dekker's Fast2Sum: 3 operations).
inline DoubleDouble fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

// a·b exactly (Dekker's TwoProduct with Veltkamp's splitting into two 26-bit halves), for
// |a|, |b| well inside the range where a·(2^27 + 1) neither overflows nor underflows.
inline DoubleDouble two_product(double a, double b) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  const double ca = kSplitter * a;
  const double a_hi = ca - (ca - a);
  const double a_lo = a - a_hi;
  const double cb = kSplitter * b;
  const double b_hi = cb - (cb - b);
  const double b_lo = b - b_hi;
  const double p = a * b;
  return {p, ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo};
}

// 2^n exactly, for a normal power of two (−1022 <= n <= 1023).
inline double pow2(int n) { return bit_cast<double>(static_cast<std::uint64_t>(n + 1023) << 52); }

}  // namespace tire::detail

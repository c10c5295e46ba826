// exp in +, −, ×, / alone (trig.h says why), by fdlibm's method (e_exp.c):
//  1. x = k·ln2 + r with k the nearest integer to x/ln2, |r| <= ln2/2; ln2 split into a 32-bit
//     part, whose product with k (|k| <= 1075) is exact, and the rest: r = hi − lo.
//  2. e^r by a rational form that keeps the leading terms exact:
//       R(r) = r·(e^r + 1)/(e^r − 1) ≈ 2 + P1·r² + … + P5·r¹⁰   (a minimax (Remez) polynomial in
//       r² on [0, 0.34658], error below 2^-59), c = r − (P1·r² + … + P5·r¹⁰),
//       e^r = 1 + r + r·c/(2 − c).
//  3. e^x = 2^k·e^r, the power of two put into the exponent bits (exact).
// fdlibm's error analysis bounds the result's error below 1 ulp; tests/test_trig.cpp measures it.
//
// The coefficients (exact hexadecimal forms of fdlibm's) come from FDLIBM 5.3:
//   Copyright (C) 2004 by Sun Microsystems, Inc. All rights reserved.
//   Permission to use, copy, modify, and distribute this software is freely granted, provided
//   that this notice is preserved.
// ln2 and 1/ln2 were computed to 2000 bits with mpmath and rounded (cut, for the 32-bit part).
#include "tire/math/exp.h"

#include <cstdint>
#include <limits>

#include "double_double.h"

namespace tire {

namespace {

constexpr double kInvLn2 = 0x1.71547652b82fep+0;
constexpr double kLn2Hi = 0x1.62e42feep-1;  // 32 significant bits
constexpr double kLn2Lo = 0x1.a39ef35793c76p-33;
constexpr double kP1 = 0x1.555555555553ep-3;
constexpr double kP2 = -0x1.6c16c16bebd93p-9;
constexpr double kP3 = 0x1.1566aaf25de2cp-14;
constexpr double kP4 = -0x1.bbd41c5d26bf1p-20;
constexpr double kP5 = 0x1.6376972bea4d0p-25;
constexpr double kOverflow = 0x1.62e42fefa39efp+9;    // 709.78…: the largest x with a finite e^x
constexpr double kUnderflow = -0x1.74910d52d3051p+9;  // −745.13…: below, e^x rounds to 0

}  // namespace

double exp(double x) {
  if (x != x) return x + x;  // NaN
  if (x > kOverflow) return std::numeric_limits<double>::infinity();
  if (x < kUnderflow) return 0.0;
  const double ax = x < 0.0 ? -x : x;
  if (ax < 0x1p-28) return 1.0 + x;  // e^x = 1 + x once rounded
  // 1. Argument reduction (k = 0 when |x| <= ln2/2: r = x).
  int k = 0;
  double hi = x, lo = 0.0;
  if (ax > 0x1.62e42fefa39efp-2) {  // ln2/2
    k = static_cast<int>(x * kInvLn2 + (x < 0.0 ? -0.5 : 0.5));
    const auto kd = static_cast<double>(k);
    hi = x - kd * kLn2Hi;  // exact: k·kLn2Hi is exact, and x is within a factor 2 of it
    lo = kd * kLn2Lo;
  }
  const double r = hi - lo;
  // 2. e^r.
  const double z = r * r;
  const double c = r - z * (kP1 + z * (kP2 + z * (kP3 + z * (kP4 + z * kP5))));
  const double y = 1.0 + (((r * c) / (2.0 - c) - lo) + hi);
  // 3. Times 2^k: in one step while 2^k is a normal double, else in two (the second rounds once
  // into the subnormals, or is exact near overflow).
  if (k >= -1022 && k <= 1023) return y * detail::pow2(k);
  if (k > 1023) return y * 2.0 * detail::pow2(k - 1);
  return y * detail::pow2(k + 1000) * detail::pow2(-1000);
}

}  // namespace tire

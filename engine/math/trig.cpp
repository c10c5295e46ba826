// cos_sin and atan2 in +, −, ×, / alone (trig.h says why).
//
// cos_sin: the classical scheme of Cody and Waite ("Software Manual for the Elementary Functions",
// 1980) as fdlibm implements it: reduce x to r = x − k·π/2 with |r| <= π/4, then evaluate the
// polynomials for sin r and cos r and pick them by the quadrant k mod 4.
//  - |x| < 2^20: r by Cody–Waite, π/2 split into three 33-bit parts (k·part is exact for
//    k < 2^20) and a fourth rounded one: π/2 to 152 bits, so r keeps its full precision even
//    where x is within 2^-60 of a multiple of π/2.
//  - |x| >= 2^20: the exact reduction of Payne and Hanek ("Radian reduction for trigonometric
//    functions", SIGNUM Newsletter 18, 1983): x = m·2^e is multiplied, in integers, by the 224
//    bits of 2/π that matter for that e (those above are whole multiples of 8 quarter turns, those
//    below are far below rounding), and the fraction of a quarter turn is read from the product.
// The reduced argument is carried as hi + lo. The polynomials are fdlibm's minimax (Remez)
// polynomials on [−π/4, π/4] (k_sin.c, k_cos.c), with an error below 2^-58 relative:
//   sin r ≈ r + S1·r³ + … + S6·r¹³,   cos r ≈ 1 − r²/2 + C1·r⁴ + … + C6·r¹⁴.
//
// atan2: the angle of (|x|, |y|) folded into [0, π/4] as atan(t) with t = min/max <= 1, t carried
// as hi + lo (the division's rounding error recovered exactly); t is moved near 0 by
// atan t = atan c + atan((t − c)/(1 + t·c)) with c = 0, 1/2 or 1 (fdlibm's s_atan.c breakpoints
// 7/16, 11/16), where |u| <= 7/16 and fdlibm's minimax polynomial
//   atan u ≈ u − u·(A0·u² + A1·u⁴ + … + A10·u²²)
// has an error below 2^-58 relative. The octant is then undone in double-double arithmetic
// (π/2 − a, π − a), so that only the last addition rounds.
//
// The coefficients (exact hexadecimal forms of fdlibm's) come from FDLIBM 5.3:
//   Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved.
//   Developed at SunSoft, a Sun Microsystems, Inc. business.
//   Permission to use, copy, modify, and distribute this software is freely granted, provided
//   that this notice is preserved.
// The other constants (the parts of π/2, π/4, atan(1/2), π and the bits of 2/π) were computed to
// 2000 bits with mpmath and rounded (or cut, for the 33-bit parts) to the doubles shown.
#include "tire/math/trig.h"

#include <bit>
#include <cstdint>
#include <limits>

#include "double_double.h"

namespace tire {

namespace {

using detail::DoubleDouble;
using detail::fast_two_sum;
using detail::pow2;
using detail::two_product;
using detail::two_sum;

constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
// π/2 = kPio2Part1 + kPio2Part2 + kPio2Part3 + kPio2Part4 (the first three have 33 significant bits).
constexpr double kPio2Part1 = 0x1.921fb544p+0;
constexpr double kPio2Part2 = 0x1.0b4611a6p-34;
constexpr double kPio2Part3 = 0x1.3198a2ep-69;
constexpr double kPio2Part4 = 0x1.b839a252049c1p-104;
// π/2, π/4, π and atan(1/2) as hi + lo (hi the nearest double, lo the rest rounded).
constexpr DoubleDouble kPio2{0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54};
constexpr DoubleDouble kPio4{0x1.921fb54442d18p-1, 0x1.1a62633145c07p-55};
constexpr DoubleDouble kPi{0x1.921fb54442d18p+1, 0x1.1a62633145c07p-53};
constexpr DoubleDouble kAtanHalf{0x1.dac670561bb4fp-2, 0x1.a2b7f222f65e2p-56};

// The binary digits of 2/π, 32 a word, most significant first: 2/π = 0.A2F9836E 4E441529 …
// (hexadecimal). 40 words are enough for the largest double (exponent 971 + 224 bits).
constexpr std::uint32_t kTwoOverPiBits[40] = {
    0xA2F9836E, 0x4E441529, 0xFC2757D1, 0xF534DDC0, 0xDB629599, 0x3C439041, 0xFE5163AB, 0xDEBBC561,
    0xB7246E3A, 0x424DD2E0, 0x06492EEA, 0x09D1921C, 0xFE1DEB1C, 0xB129A73E, 0xE88235F5, 0x2EBB4484,
    0xE99C7026, 0xB45F7E41, 0x3991D639, 0x835339F4, 0x9C845F8B, 0xBDF9283B, 0x1FF897FF, 0xDE05980F,
    0xEF2F118B, 0x5A0A6D1F, 0x6D367ECF, 0x27CB09B7, 0x4F463F66, 0x9E5FEA2D, 0x7527BAC7, 0xEBE5F17B,
    0x3D0739F7, 0x8A5292EA, 0x6BFB5FB1, 0x1F8D5D08, 0x56033046, 0xFC7B6BAB, 0xF0CFBC20, 0x9AF4361D};

// sin on [−π/4, π/4]: fdlibm k_sin.c.
constexpr double kS1 = -0x1.5555555555549p-3;
constexpr double kS2 = 0x1.111111110f8a6p-7;
constexpr double kS3 = -0x1.a01a019c161d5p-13;
constexpr double kS4 = 0x1.71de357b1fe7dp-19;
constexpr double kS5 = -0x1.ae5e68a2b9cebp-26;
constexpr double kS6 = 0x1.5d93a5acfd57cp-33;
// cos on [−π/4, π/4]: fdlibm k_cos.c.
constexpr double kC1 = 0x1.555555555554cp-5;
constexpr double kC2 = -0x1.6c16c16c15177p-10;
constexpr double kC3 = 0x1.a01a019cb1590p-16;
constexpr double kC4 = -0x1.27e4f809c52adp-22;
constexpr double kC5 = 0x1.1ee9ebdb4b1c4p-29;
constexpr double kC6 = -0x1.8fae9be8838d4p-37;
// atan on [−7/16, 7/16]: fdlibm s_atan.c.
constexpr double kA[11] = {0x1.555555555550dp-2,  -0x1.999999998ebc4p-3, 0x1.24924920083ffp-3,
                           -0x1.c71c6fe231671p-4, 0x1.745cdc54c206ep-4,  -0x1.3b0f2af749a6dp-4,
                           0x1.10d66a0d03d51p-4,  -0x1.dde2d52defd9ap-5, 0x1.97b4b24760debp-5,
                           -0x1.2b4442c6a6c2fp-5, 0x1.0ad3ae322da11p-6};

// x − k·π/2 as hi + lo, |hi| <= π/4 (a hair more where k·2/π rounded the other way), and k mod 4.
struct Reduced {
  DoubleDouble r;
  unsigned quadrant;
};

// π/4 < x < 2^20: Cody–Waite. k·Part1..3 are exact (k < 2^20, 33-bit parts), x − k·Part1 is
// exact (Sterbenz: x and k·Part1 are within a factor 2), and the rest is summed error-free.
Reduced reduce_medium(double x) {
  const auto k = static_cast<std::int32_t>(x * kTwoOverPi + 0.5);
  const auto kd = static_cast<double>(k);
  const double a = x - kd * kPio2Part1;
  const DoubleDouble s1 = two_sum(a, -(kd * kPio2Part2));
  const DoubleDouble s2 = two_sum(s1.hi, -(kd * kPio2Part3));
  const double tail = (s1.lo + s2.lo) - kd * kPio2Part4;
  return {fast_two_sum(s2.hi, tail), static_cast<unsigned>(k) & 3u};
}

// Bits pos … pos+63 of the little-endian 288-bit integer p (bits below 0 read as 0).
std::uint64_t bits_at(const std::uint32_t (&p)[9], int pos) {
  if (pos < 0) return pos <= -64 ? 0 : bits_at(p, 0) << -pos;
  const auto limb = [&p](int i) -> std::uint64_t { return i < 9 ? p[i] : 0; };
  const int i = pos / 32, shift = pos % 32;
  const std::uint64_t low = limb(i) | limb(i + 1) << 32;
  return shift == 0 ? low : low >> shift | limb(i + 2) << (64 - shift);
}

// x >= 2^20, finite: Payne–Hanek.
Reduced reduce_large(double x) {
  const auto bits = detail::bit_cast<std::uint64_t>(x);
  const std::uint64_t m = (bits & ((std::uint64_t{1} << 52) - 1)) | std::uint64_t{1} << 52;
  const int e = static_cast<int>(bits >> 52) - 1075;  // x = m·2^e, m < 2^53, e >= −32
  // x·2/π = m·Σ_j word_j·2^(e − 32(j+1)). The words before j0 add multiples of 8 (mod 4 they are
  // 0); the 7 words from j0 leave 190 to 256 bits of fraction; the words after add under 2^-137.
  const int j0 = e > 3 ? (e - 3) / 32 : 0;
  std::uint32_t p[9] = {};  // m × words j0 … j0+6, least significant limb first
  const std::uint64_t m_limbs[2] = {m & 0xFFFFFFFFu, m >> 32};
  for (int i = 0; i < 2; ++i) {
    std::uint64_t carry = 0;
    for (int j = 0; j < 7; ++j) {
      const std::uint64_t t = m_limbs[i] * kTwoOverPiBits[j0 + 6 - j] + p[i + j] + carry;
      p[i + j] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
    p[i + 7] = static_cast<std::uint32_t>(carry);
  }
  const int s = 32 * (j0 + 7) - e;  // x·2/π ≡ p·2^-s (mod 8)
  auto quadrant = static_cast<unsigned>(bits_at(p, s)) & 3u;
  // The first 192 bits of the fraction f of a quarter turn.
  std::uint64_t f0 = bits_at(p, s - 64), f1 = bits_at(p, s - 128), f2 = bits_at(p, s - 192);
  const bool negative = f0 >> 63 != 0;
  if (negative) {  // f >= 1/2: the next quarter turn is nearer, r = (f − 1)·π/2
    ++quadrant;
    f2 = ~f2 + 1;
    f1 = ~f1 + (f2 == 0 ? 1 : 0);
    f0 = ~f0 + (f2 == 0 && f1 == 0 ? 1 : 0);
  }
  int shift = 0;  // normalise: the leading 1 of |f| to bit 63 of f0
  while (f0 == 0 && shift < 128) {
    f0 = f1;
    f1 = f2;
    f2 = 0;
    shift += 64;
  }
  if (f0 == 0) return {{0.0, 0.0}, quadrant & 3u};
  const int lz = std::countl_zero(f0);
  if (lz > 0) {
    f0 = f0 << lz | f1 >> (64 - lz);
    f1 = f1 << lz | f2 >> (64 - lz);
  }
  shift += lz;
  // |f| = hi + lo to 106 bits (each an integer of 53 bits times a power of two: exact).
  const double hi = static_cast<double>(f0 >> 11) * pow2(-53 - shift);
  const double lo = static_cast<double>((f0 & 0x7FFu) << 42 | f1 >> 22) * pow2(-106 - shift);
  // Quarter turns to radians: (hi + lo)·(π/2)_hi exactly, plus the small cross terms.
  const DoubleDouble prod = two_product(hi, kPio2.hi);
  const DoubleDouble r = fast_two_sum(prod.hi, prod.lo + (hi * kPio2.lo + lo * kPio2.hi));
  return {negative ? DoubleDouble{-r.hi, -r.lo} : r, quadrant & 3u};
}

// sin(hi + lo), |hi + lo| <= π/4 (and a hair): sin hi + lo·cos hi with cos hi ≈ 1 − hi²/2, the
// small terms summed first and hi added last.
double sin_kernel(DoubleDouble x) {
  const double z = x.hi * x.hi;
  const double v = z * x.hi;
  const double p = kS2 + z * (kS3 + z * (kS4 + z * (kS5 + z * kS6)));
  return x.hi + (v * kS1 + (z * (v * p - 0.5 * x.lo) + x.lo));
}

// cos(hi + lo), |hi + lo| <= π/4 (and a hair): cos hi − lo·sin hi with sin hi ≈ hi. w = 1 − hi²/2
// rounds; its rounding error (1 − w) − hi²/2 is exact (Fast2Sum) and added back with the rest.
double cos_kernel(DoubleDouble x) {
  const double z = x.hi * x.hi;
  const double p = z * z * (kC1 + z * (kC2 + z * (kC3 + z * (kC4 + z * (kC5 + z * kC6)))));
  const double hz = 0.5 * z;
  const double w = 1.0 - hz;
  return w + (((1.0 - w) - hz) + (p - x.hi * x.lo));
}

// atan(u + u_lo) − u for |u| <= 7/16, |u_lo| <= ulp(u): the polynomial's tail plus u_lo/(1 + u²).
double atan_tail(double u, double u_lo) {
  const double z = u * u;
  double q = kA[10];
  for (int i = 9; i >= 0; --i) q = kA[i] + z * q;
  return u_lo * (1.0 - z) - u * (z * q);
}

// atan(t + t_lo) as hi + lo, for 0 <= t <= 1 and |t_lo| <= ulp(t).
DoubleDouble atan_unit(double t, double t_lo) {
  if (t < 0x1.cp-2) return fast_two_sum(t, atan_tail(t, t_lo));  // t < 7/16
  // u = (t − c)/(1 + t·c): the numerator is exact (Sterbenz), the denominator an exact sum, and
  // the quotient hi + lo by one Newton correction of the rounded quotient.
  const bool half = t < 0x1.6p-1;  // t < 11/16: c = 1/2, u = (2t − 1)/(2 + t)
  const double num = half ? 2.0 * t - 1.0 : t - 1.0;
  const double num_lo = half ? 2.0 * t_lo : t_lo;
  const DoubleDouble den = two_sum(half ? 2.0 : 1.0, t);
  const double den_lo = den.lo + t_lo;
  const double u = num / den.hi;
  const DoubleDouble ud = two_product(u, den.hi);
  const double u_lo = (((num - ud.hi) - ud.lo) + (num_lo - u * den_lo)) / den.hi;
  const DoubleDouble base = half ? kAtanHalf : kPio4;
  const DoubleDouble s = two_sum(base.hi, u);
  return fast_two_sum(s.hi, s.lo + (base.lo + atan_tail(u, u_lo)));
}

// c − a as hi + lo, for a double-double constant c > a >= 0.
DoubleDouble minus(DoubleDouble c, DoubleDouble a) {
  const DoubleDouble s = two_sum(c.hi, -a.hi);
  return fast_two_sum(s.hi, s.lo + (c.lo - a.lo));
}

}  // namespace

CosSin cos_sin(double angle) {
  const double x = angle < 0.0 ? -angle : angle;
  if (!(x < std::numeric_limits<double>::infinity())) {
    const double nan = angle - angle;  // NaN for ±inf and NaN
    return {nan, nan};
  }
  // |x| < 2^-27: sin x = x and cos x = 1 once rounded (the next terms are below half an ulp).
  if (x < 0x1p-27) return {1.0, angle};
  Reduced red;
  if (x <= 0x1.921fb54442d18p-1)  // <= π/4
    red = {{x, 0.0}, 0};
  else if (x < 0x1p20)
    red = reduce_medium(x);
  else
    red = reduce_large(x);
  const double s = sin_kernel(red.r), c = cos_kernel(red.r);
  CosSin out{};
  switch (red.quadrant) {
    case 0: out = {c, s}; break;
    case 1: out = {-s, c}; break;
    case 2: out = {-c, -s}; break;
    default: out = {s, -c}; break;
  }
  if (angle < 0.0) out.sin = -out.sin;
  return out;
}

double atan2(double y, double x) {
  if (x != x || y != y) return x + y;  // NaN
  const double ax = x < 0.0 ? -x : x, ay = y < 0.0 ? -y : y;
  const bool x_negative = detail::bit_cast<std::uint64_t>(x) >> 63 != 0;  // −0 too
  const bool y_negative = detail::bit_cast<std::uint64_t>(y) >> 63 != 0;
  constexpr double inf = std::numeric_limits<double>::infinity();
  double angle;  // in [0, π], the sign of y applied last
  if (ay == 0.0) {
    angle = x_negative ? kPi.hi : 0.0;
  } else if (ax == 0.0) {
    angle = kPio2.hi;
  } else if (ax == inf || ay == inf) {
    if (ax == inf && ay == inf)
      angle = x_negative ? 0x1.2d97c7f3321d2p+1 : kPio4.hi;  // 3π/4 or π/4
    else if (ax == inf)
      angle = x_negative ? kPi.hi : 0.0;
    else
      angle = kPio2.hi;
  } else {
    const bool swapped = ay > ax;  // fold into the first octant: t = small / big <= 1
    double small = swapped ? ax : ay, big = swapped ? ay : ax;
    DoubleDouble a;
    if (small < big * 0x1p-27) {
      a = {small / big, 0.0};  // atan t = t once rounded; its correction is below 2^-54 of t
    } else {
      // Scale both by a power of two (exact) so that big is in [1, 2): the exact products below
      // neither overflow nor underflow.
      const int big_exponent = static_cast<int>(detail::bit_cast<std::uint64_t>(big) >> 52) - 1023;
      if (big_exponent > -1022 && big_exponent < 1023) {
        small *= pow2(-big_exponent);
        big *= pow2(-big_exponent);
      } else {  // subnormal or near overflow: in two steps
        const double k = big_exponent > 0 ? 0x1p-600 : 0x1p600;
        small *= k;
        big *= k;
        const int e2 = static_cast<int>(detail::bit_cast<std::uint64_t>(big) >> 52) - 1023;
        small *= pow2(-e2);
        big *= pow2(-e2);
      }
      const double t = small / big;
      const DoubleDouble tb = two_product(t, big);
      const double t_lo = ((small - tb.hi) - tb.lo) / big;  // small − t·big is exact
      a = atan_unit(t, t_lo);
    }
    if (swapped) a = minus(kPio2, a);
    if (x_negative) a = minus(kPi, a);
    angle = a.hi + a.lo;
  }
  return y_negative ? -angle : angle;
}

}  // namespace tire

// The engine's own cos_sin, atan2 and exp (tire/math/trig.h, exp.h): how far from the exact values
// they are over many arguments, the special values, and that they give the same bits everywhere.
//
// The error is measured against long double (64-bit significand on x86-64: its error is ~2^-11
// of a double's ulp); how far std:: (glibc's) is from them is printed too, and bounded only where
// long double is no more precise than double. (glibc's own cos misses the hardest argument to
// reduce, 0x1.6ac5b262ca1ffp+849, by 8 ulp; GCC folds std::cos of a constant with MPFR, exactly.)
// Each accuracy test prints its maximum error in ulps. Two random draws are never arguments of one
// call: C++ leaves their order to the compiler, and the inputs must be the same everywhere.
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <vector>

#include "tire/math/exp.h"
#include "tire/math/trig.h"

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.141592653589793;  // the double nearest π
// Is long double precise enough to be the reference (x86-64's 80-bit format, or binary128)?
constexpr bool kPreciseReference = std::numeric_limits<long double>::digits >= 64;

// splitmix64 (Steele, Lea, Flood 2014): a fixed sequence on every platform.
struct Random {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  // ±m·2^e with e uniform in [lo, hi]: every scale equally often.
  double log_uniform(int lo, int hi) {
    const int e = lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
    return std::ldexp(next() % 2 ? 1.0 + unit() : -1.0 - unit(), e);
  }
};

// One ulp at `exact` (of the double nearest to it; 2^-1074 among the subnormals).
long double ulp_at(long double exact) {
  const double r = static_cast<double>(exact);
  if (r == 0.0 || !std::isfinite(r)) return std::ldexp(1.0L, -1074);
  int e = 0;
  std::frexp(r, &e);
  return std::ldexp(1.0L, std::max(e - 53, -1074));
}

// How many doubles apart a and b are (0: the same double).
std::uint64_t ulps_apart(double a, double b) {
  const auto key = [](double v) {
    const auto bits = std::bit_cast<std::int64_t>(v);
    return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
  };
  const std::int64_t ka = key(a), kb = key(b);
  return ka > kb ? static_cast<std::uint64_t>(ka) - static_cast<std::uint64_t>(kb)
                 : static_cast<std::uint64_t>(kb) - static_cast<std::uint64_t>(ka);
}

// The largest error of one function over its arguments.
struct Error {
  const char* name;
  double max_ulp = 0.0;  // against the long double reference
  double worst_arg = 0.0;
  std::uint64_t max_apart = 0;  // against std::
  std::size_t differ = 0;       // arguments where the bits differ from std::'s
  std::size_t count = 0;

  void add(double arg, double got, long double exact, double std_value) {
    ++count;
    if (kPreciseReference) {
      const auto e = static_cast<double>(std::fabs(static_cast<long double>(got) - exact) / ulp_at(exact));
      if (e > max_ulp) max_ulp = e, worst_arg = arg;
    }
    const std::uint64_t apart = ulps_apart(got, std_value);
    if (apart > max_apart) max_apart = apart;
    if (apart != 0) ++differ;
  }
  void report() const {
    std::printf("%-6s %zu arguments: max error %.3f ulp (at %a), %zu differ from std:: by at most %llu ulp\n",
                name, count, max_ulp, worst_arg, differ, static_cast<unsigned long long>(max_apart));
  }
};

constexpr int kSamples = 1000000;

}  // namespace

TEST_CASE("cos_sin is within 1 ulp of the exact cos and sin", "[unit][trig]") {
  Error sin_error{"sin"}, cos_error{"cos"};
  const auto check = [&](double x) {
    const tire::CosSin cs = tire::cos_sin(x);
    sin_error.add(x, cs.sin, std::sin(static_cast<long double>(x)), std::sin(x));
    cos_error.add(x, cs.cos, std::cos(static_cast<long double>(x)), std::cos(x));
  };
  Random random{1};
  for (int i = 0; i < kSamples; ++i) {
    switch (i % 4) {
      case 0: check(random.uniform(-4.0, 4.0)); break;      // the first turns, near 0 and π/4
      case 1: check(random.uniform(-1e4, 1e4)); break;      // what the engine sees
      case 2: check(random.log_uniform(-40, 30)); break;    // every scale up to ~1e9
      default: check(random.log_uniform(20, 1023)); break;  // huge: the exact reduction
    }
  }
  // Near and at multiples of π/2 and π, where the reduction cancels: the doubles nearest k·π/2
  // and their neighbours.
  for (int k = 1; k <= 6400; ++k) {
    const double x = k * (kPi / 2.0);
    for (const double v : {x, std::nextafter(x, 0.0), std::nextafter(x, kInf)}) check(v), check(-v);
  }
  // The double nearest a multiple of π/2 of all (Kahan, McDonald), and other large ones.
  for (const double x : {0x1.6ac5b262ca1ffp+849, 1e22, 0x1p1023, std::numeric_limits<double>::max(), 0x1p20,
                         std::nextafter(0x1p20, 0.0), 0x1.921fb54442d18p-1, 0x1.921fb54442d19p-1})
    check(x), check(-x);
  sin_error.report();
  cos_error.report();
  if (kPreciseReference) {
    CHECK(sin_error.max_ulp < 1.0);
    CHECK(cos_error.max_ulp < 1.0);
  } else {
    CHECK(sin_error.max_apart <= 2);
    CHECK(cos_error.max_apart <= 2);
  }
}

TEST_CASE("cos_sin of special values", "[unit][trig]") {
  const tire::CosSin zero = tire::cos_sin(0.0), minus_zero = tire::cos_sin(-0.0);
  CHECK(zero.cos == 1.0);
  CHECK(zero.sin == 0.0);
  CHECK_FALSE(std::signbit(zero.sin));
  CHECK(minus_zero.cos == 1.0);
  CHECK(minus_zero.sin == 0.0);
  CHECK(std::signbit(minus_zero.sin));
  // Tiny: sin x = x, cos x = 1 exactly once rounded.
  for (const double x : {1e-300, 5e-324, -5e-324, 0x1p-27, -0x1p-28, 1e-9}) {
    CHECK(tire::cos_sin(x).sin == x - (x * x * x) / 6.0);
    CHECK(tire::cos_sin(x).cos == (std::fabs(x) < 0x1p-27 ? 1.0 : std::cos(x)));
  }
  // Multiples of π: the double nearest k·π is off by up to half an ulp, and sin is that offset.
  CHECK(tire::cos_sin(kPi).sin == 0x1.1a62633145c07p-53);  // π − (double)π
  CHECK(tire::cos_sin(kPi).cos == -1.0);
  CHECK(tire::cos_sin(kPi / 2.0).cos == 0x1.1a62633145c07p-54);
  CHECK(tire::cos_sin(kPi / 2.0).sin == 1.0);
  CHECK(tire::cos_sin(2.0 * kPi).cos == 1.0);
  // Huge: sin(1e22) (a classic check of the reduction) and the largest double.
  CHECK(tire::cos_sin(1e22).sin == -0x1.b453ab76bf397p-1);
  CHECK(tire::cos_sin(1e22).cos == 0x1.0be2cef01c8f4p-1);
  CHECK(tire::cos_sin(std::numeric_limits<double>::max()).sin ==
        std::sin(std::numeric_limits<double>::max()));
  // Not numbers.
  for (const double x : {kInf, -kInf, std::numeric_limits<double>::quiet_NaN()}) {
    CHECK(std::isnan(tire::cos_sin(x).cos));
    CHECK(std::isnan(tire::cos_sin(x).sin));
  }
}

TEST_CASE("atan2 is within 1 ulp of the exact angle", "[unit][trig]") {
  Error error{"atan2"};
  const auto check = [&](double y, double x) {
    error.add(y, tire::atan2(y, x), std::atan2(static_cast<long double>(y), static_cast<long double>(x)),
              std::atan2(y, x));
  };
  Random random{2};
  for (int i = 0; i < kSamples; ++i) {
    switch (i % 3) {
      case 0: {
        const double y = random.uniform(-1.0, 1.0);
        check(y, random.uniform(-1.0, 1.0));
        break;
      }
      case 1: {
        const double y = random.log_uniform(-30, 30);
        check(y, random.log_uniform(-30, 30));
        break;
      }
      default: {
        const double y = random.log_uniform(-1074, 1023);
        check(y, random.log_uniform(-1074, 1023));
        break;
      }
    }
  }
  // On and next to the octant boundaries (|y| = |x|, and t = 7/16, 11/16 inside).
  for (const double t : {1.0, 7.0 / 16.0, 11.0 / 16.0})
    for (const double x : {1.0, 3.7, 1e-300, 1e300}) {
      const double y = t * x;
      for (const double v : {y, std::nextafter(y, 0.0), std::nextafter(y, kInf)})
        check(v, x), check(-v, x), check(v, -x), check(x, v), check(-x, -v);
    }
  error.report();
  if (kPreciseReference)
    CHECK(error.max_ulp < 1.0);
  else
    CHECK(error.max_apart <= 2);
}

TEST_CASE("atan2 of special values as C's (Annex F.10.1.4)", "[unit][trig]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> values = {0.0, -0.0, 1.0, -1.0, 1e-310, -2.5, 1e300, kInf, -kInf, nan};
  for (const double y : values)
    for (const double x : values) {
      const double got = tire::atan2(y, x), want = std::atan2(y, x);
      INFO("atan2(" << y << ", " << x << ") = " << got << ", std:: " << want);
      if (std::isnan(want)) {
        CHECK(std::isnan(got));
      } else {
        CHECK(ulps_apart(got, want) <= 1);
        CHECK(std::signbit(got) == std::signbit(want));
      }
    }
  CHECK(tire::atan2(0.0, -0.0) == kPi);
  CHECK(tire::atan2(-0.0, -1.0) == -kPi);
  CHECK(tire::atan2(1.0, 0.0) == kPi / 2.0);
  CHECK(tire::atan2(1.0, 1.0) == kPi / 4.0);
  CHECK(tire::atan2(-kInf, -kInf) == -3.0 * kPi / 4.0);
}

TEST_CASE("exp is within 1 ulp of the exact value", "[unit][trig]") {
  Error error{"exp"};
  const auto check = [&](double x) {
    error.add(x, tire::exp(x), std::exp(static_cast<long double>(x)), std::exp(x));
  };
  Random random{3};
  for (int i = 0; i < kSamples; ++i) {
    switch (i % 3) {
      case 0: check(random.uniform(-700.0, 0.0)); break;  // the engine's: exp(−damping·h)
      case 1: check(random.uniform(-708.3, 709.7)); break;
      default: check(random.log_uniform(-60, 8)); break;  // |x| < 512
    }
  }
  for (int k = -1020; k <= 1023; ++k) {  // at and next to k·ln 2, where the reduction switches k
    const double x = k * 0.6931471805599453;
    check(x), check(std::nextafter(x, -kInf)), check(std::nextafter(x, kInf));
    check(x + 0.5 * 0.6931471805599453);
  }
  error.report();
  if (kPreciseReference)
    CHECK(error.max_ulp < 1.0);
  else
    CHECK(error.max_apart <= 2);
}

TEST_CASE("exp of special values", "[unit][trig]") {
  CHECK(tire::exp(0.0) == 1.0);
  CHECK(tire::exp(-0.0) == 1.0);
  CHECK(ulps_apart(tire::exp(1.0), 0x1.5bf0a8b145769p+1) <= 1);  // e (fdlibm's method rounds it up)
  CHECK(tire::exp(-1.0) == 0x1.78b56362cef38p-2);                // 1/e
  CHECK(tire::exp(1e-20) == 1.0);
  CHECK(tire::exp(709.78) < kInf);
  CHECK(tire::exp(709.79) == kInf);
  CHECK(tire::exp(-745.2) == 0.0);
  CHECK(tire::exp(-708.0) > 0x1p-1022);
  CHECK(tire::exp(-740.0) > 0.0);  // subnormal
  CHECK(tire::exp(kInf) == kInf);
  CHECK(tire::exp(-kInf) == 0.0);
  CHECK(std::isnan(tire::exp(std::numeric_limits<double>::quiet_NaN())));
}

// The same bits on every platform: a checksum of many results, pinned. A platform, compiler or
// flag that rounds one of them differently (a fused multiply–add, x87 excess precision, a changed
// constant) fails here before it moves a replay's hash.
TEST_CASE("cos_sin, atan2 and exp give these bits", "[unit][trig]") {
  std::uint64_t h = 0xCBF29CE484222325u;  // FNV-1a over the results' bits
  const auto mix = [&h](double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    for (int i = 0; i < 64; i += 8) h = (h ^ ((bits >> i) & 0xFFu)) * 0x100000001B3u;
  };
  Random random{4};
  for (int i = 0; i < 100000; ++i) {
    const tire::CosSin cs = tire::cos_sin(i % 2 ? random.uniform(-1e4, 1e4) : random.log_uniform(-30, 1023));
    mix(cs.cos);
    mix(cs.sin);
    const double y = random.log_uniform(-40, 40);
    mix(tire::atan2(y, random.log_uniform(-40, 40)));
    mix(tire::exp(random.uniform(-745.0, 709.0)));
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  CHECK(std::string(text) == "81ed7a468a912ee6");
}

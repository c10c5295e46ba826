// The engine's own cosine, sine and arctangent: the same bits on every platform.
//
// The simulation's results must not depend on the C library it is linked with (glibc natively,
// musl in the WebAssembly build): a replay is checked bit for bit by its state hash on both. The
// C standard leaves the accuracy of sin, cos and atan2 to each library, and glibc's and musl's
// differ in the last bit for some arguments. These are written out in +, −, ×, / alone, which
// IEEE 754 rounds exactly the same everywhere, in a fixed order (the project compiles with
// -ffp-contract=off, so no compiler fuses a multiply and an add). How they work and how accurate
// they are: trig.cpp, and tests/test_trig.cpp, which measures them.
//
// Engine code on the simulation path or in level set-up calls these, never std::sin, std::cos,
// std::atan2 (std::sqrt is fine: IEEE rounds it exactly). See also exp.h.
#pragma once

namespace tire {

struct CosSin {
  double cos;
  double sin;
};

// cos and sin of `angle` (radians), within 1 ulp of the exact values for every finite double
// (an exact range reduction), cos_sin(±0) = {1, ±0}; NaN for ±inf and NaN.
CosSin cos_sin(double angle);

// The angle of the point (x, y) from the +x axis, in [−π, π], within 1 ulp; the special cases
// (zeros, infinities, NaN) as C's atan2 (C17 Annex F.10.1.4).
double atan2(double y, double x);

}  // namespace tire

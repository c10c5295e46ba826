// The engine's own exponential: the same bits on every platform (why: trig.h). How it works:
// exp.cpp; how accurate it is: tests/test_trig.cpp.
#pragma once

namespace tire {

// e^x within 1 ulp of the exact value for every x whose result is a normal double
// (−708.39 <= x <= 709.78); +inf above, 0 below −745.14, subnormal in between; exp(NaN) is NaN,
// exp(−inf) = 0, exp(+inf) = +inf.
double exp(double x);

}  // namespace tire

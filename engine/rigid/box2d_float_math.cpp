// The float functions Box2D takes from the C library, defined here as the engine's own, so that
// Box2D's rotations are the same bits on every platform (docs/determinism.md).
//
// Box2D 2.4 turns an angle into a rotation with sinf and cosf (b2Rot::Set, inline in b2_math.h and
// compiled into libbox2d as sincosf), in its solver and wherever a body is placed; it also imports
// atan2f and expf. glibc's and musl's (the browser build's) sinf and cosf differ in the last bit
// for about 0.1 % of floats (tools/libm-diff), enough for a prop level's replay to diverge within
// half a second. Defining them in the program puts these definitions in front of the C library's
// for every caller: a shared library's references bind to the executable's definition at load
// time (ELF symbol interposition, the mechanism malloc replacements use), and a static link takes
// the first definition it meets. Each is the engine's double-precision function, within 1 ulp
// (trig.h, exp.h), rounded once to float: correctly rounded except where that double lies within
// 1 ulp of a float rounding boundary, and the same bits everywhere. tests/test_box2d_float_math.cpp
// checks that Box2D's rotations, inline and compiled, are these.
//
// These are C-library names, so no layer of the engine holds them: an engine installed as a library
// leaves its user's C library alone. They are an object library of their own, tire::float_math
// (engine/rigid/CMakeLists.txt), that a program opts into; every program of this project does
// (cmake/float_math.cmake), and a program that embeds the engine links it to get the same bits as
// tirectl, the game and the browser build (docs/engine.md).
//
// No header of the C library is included here: its declarations of these names (noexcept in
// glibc's, not in musl's) are not needed, and the definitions below are the only ones in sight.
#include "tire/math/exp.h"
#include "tire/math/trig.h"

extern "C" {

float sinf(float x) noexcept { return static_cast<float>(tire::cos_sin(x).sin); }

float cosf(float x) noexcept { return static_cast<float>(tire::cos_sin(x).cos); }

void sincosf(float x, float* sin_x, float* cos_x) noexcept {
  const tire::CosSin cs = tire::cos_sin(x);
  *sin_x = static_cast<float>(cs.sin);
  *cos_x = static_cast<float>(cs.cos);
}

float atan2f(float y, float x) noexcept { return static_cast<float>(tire::atan2(y, x)); }

float expf(float x) noexcept { return static_cast<float>(tire::exp(x)); }

}  // extern "C"

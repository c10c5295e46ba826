// Box2D's float sinf, cosf, sincosf, atan2f and expf are the engine's own (box2d_float_math.cpp
// says how and why): the same rotations on every platform.
#pragma once

namespace tire {

// Does nothing; calling it links box2d_float_math.cpp's definitions into the program.
void use_engine_float_math();

}  // namespace tire

// Box2D's rotations are the engine's (engine/rigid/box2d_float_math.cpp): b2Rot built inline in
// this file and rotations made inside libbox2d (b2Body::SetTransform, and the solver's own) give
// the bits of the engine's cos_sin rounded to float, for every angle tried; so do atan2f and expf.
// With the C library's sinf instead, some of these angles give other bits (glibc's and musl's
// differ; tools/libm-diff), and the browser's replays diverge from the native ones.
#include <box2d/box2d.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <vector>

#include "tire/math/exp.h"
#include "tire/math/trig.h"
#include "tire/rigid/rigid_world.h"

namespace {

// Angles in [-1000, 1000] rad from a fixed generator, and the awkward ones.
std::vector<float> angles() {
  std::vector<float> out{0.0f,       -0.0f,      1e-30f,      0.5f,   1.0f,
                         1.5707964f, 3.1415927f, -3.1415927f, 100.0f, 1000.0f};
  std::uint64_t state = 0x9e3779b97f4a7c15u;
  for (int i = 0; i < 20000; ++i) {
    state = state * 6364136223846793005u + 1442695040888963407u;
    const double unit = static_cast<double>(state >> 11) * 0x1p-53;  // [0, 1)
    out.push_back(static_cast<float>((unit * 2.0 - 1.0) * (i % 2 == 0 ? 4.0 : 1000.0)));
  }
  return out;
}

float engine_sin(float a) { return static_cast<float>(tire::cos_sin(a).sin); }
float engine_cos(float a) { return static_cast<float>(tire::cos_sin(a).cos); }

}  // namespace

TEST_CASE("box2d float math: b2Rot made inline is the engine's cos_sin rounded to float") {
  const tire::RigidWorld world({0.0, -9.81});  // links the engine's definitions, as any program with props
  int checked = 0;
  for (const float a : angles()) {
    volatile float angle = a;  // computed at run time, as Box2D's solver does
    const b2Rot q(angle);
    REQUIRE(q.s == engine_sin(a));
    REQUIRE(q.c == engine_cos(a));
    ++checked;
  }
  CHECK(checked == 20010);
}

TEST_CASE("box2d float math: rotations made inside libbox2d are the engine's") {
  b2World world({0.0f, -10.0f});
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.angle = 0.75f;
  b2Body* body = world.CreateBody(&def);
  REQUIRE(body->GetTransform().q.s == engine_sin(0.75f));
  for (const float a : angles()) {
    body->SetTransform({1.0f, 2.0f}, a);
    REQUIRE(body->GetTransform().q.s == engine_sin(a));
    REQUIRE(body->GetTransform().q.c == engine_cos(a));
  }
  // The solver integrates the angle and rebuilds the rotation from it (b2Island::Solve).
  b2PolygonShape box;
  box.SetAsBox(0.5f, 0.5f);
  body->CreateFixture(&box, 1.0f);
  body->SetTransform({0.0f, 0.0f}, 0.3f);
  body->SetAngularVelocity(7.3f);
  for (int i = 0; i < 60; ++i) {
    world.Step(1.0f / 60.0f, 8, 3);
    const float a = body->GetAngle();
    REQUIRE(body->GetTransform().q.s == engine_sin(a));
    REQUIRE(body->GetTransform().q.c == engine_cos(a));
  }
}

TEST_CASE("box2d float math: atan2f and expf are the engine's") {
  const b2Rot q(2.5f);
  CHECK(q.GetAngle() == static_cast<float>(tire::atan2(q.s, q.c)));
  for (const float x : {-87.0f, -1.0f, 0.0f, 0.3f, 1.0f, 10.0f, 88.0f}) {
    volatile float v = x;
    CHECK(expf(v) == static_cast<float>(tire::exp(x)));
  }
}

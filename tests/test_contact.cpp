// Box contacts: the minimal-overlap normal and depth, the inequality constraint's gradient, and
// Coulomb friction's physical meaning.
#include <catch2/catch.hpp>

#include "tire/xpbd/contact.h"
#include "tire/xpbd/particles.h"

using namespace tire;

TEST_CASE("box contact pushes out through the face of least overlap", "[unit][contact]") {
  const Aabb box{{0, 0}, {4, 2}};
  const auto top = box_contact({1.5, 1.9}, box);
  REQUIRE(top);
  CHECK(top->normal == Vec2{0, 1});
  CHECK(top->depth == Approx(0.1));
  const auto left = box_contact({0.05, 1.0}, box);
  REQUIRE(left);
  CHECK(left->normal == Vec2{-1, 0});
  CHECK(left->depth == Approx(0.05));
  const auto right = box_contact({3.8, 1.0}, box);
  REQUIRE(right);
  CHECK(right->normal == Vec2{1, 0});
  const auto bottom = box_contact({2.0, 0.01}, box);
  REQUIRE(bottom);
  CHECK(bottom->normal == Vec2{0, -1});
  CHECK_FALSE(box_contact({-0.1, 1.0}, box));
  CHECK_FALSE(box_contact({1.0, 2.0}, box));  // on the surface is not inside: no margin
  // A tie between top and left prefers the top (ground).
  CHECK(box_contact({0.5, 1.5}, box)->normal == Vec2{0, 1});
}

TEST_CASE("the contact constraint's gradient is its normal", "[unit][contact]") {
  // C(x) = −depth(x) ≥ 0 is the inequality; its gradient must be the normal it pushes along.
  const Aabb box{{-1, -1}, {1, 0}};
  const double eps = 1e-7;
  for (const Vec2 p : {Vec2{0.2, -0.1}, Vec2{-0.95, -0.4}, Vec2{0.97, -0.5}, Vec2{0.1, -0.98}}) {
    const auto c = box_contact(p, box);
    REQUIRE(c);
    const auto C = [&](Vec2 q) { return -box_contact(q, box)->depth; };
    const Vec2 fd{(C(p + Vec2{eps, 0}) - C(p - Vec2{eps, 0})) / (2 * eps),
                  (C(p + Vec2{0, eps}) - C(p - Vec2{0, eps})) / (2 * eps)};
    CHECK(fd.x == Approx(c->normal.x).margin(1e-6));
    CHECK(fd.y == Approx(c->normal.y).margin(1e-6));
    // Resolving it lands exactly on the surface.
    Vec2 x = p;
    ContactRecord rec;
    resolve_contact(x, x, *c, 0.0, 0.0, rec);
    CHECK_FALSE(box_contact(x, box));
  }
}

namespace {
// One particle on the ground y = 0 with initial speed v0 along x, optionally pushed along x by a
// force per unit mass `push`, stepped with the engine's contact and friction code.
struct Slide {
  double distance;
  double speed;
};
Slide slide(double v0, double push, double mu_s, double mu_k, int substeps, double seconds) {
  const Aabb ground{{-100, -1}, {100, 0}};
  const double g = 9.81, h = (1.0 / 60.0) / substeps;
  Particles p;
  p.resize(1);
  p.x = {{0, 0}};
  p.v = {{v0, 0}};
  p.w = {1.0};
  for (int s = 0; s < static_cast<int>(seconds / h); ++s) {
    p.v[0] += Vec2{push, -g} * h;
    predict_positions(p, h);
    ContactRecord rec;
    if (const auto c = box_contact(p.x[0], ground)) resolve_contact(p.x[0], p.x_prev[0], *c, mu_s, mu_k, rec);
    derive_velocities(p, h);
    apply_kinetic_friction(p.v[0], rec, h);
  }
  return {p.x[0].x, p.v[0].x};
}
}  // namespace

TEST_CASE("kinetic friction decelerates a sliding particle at mu*g", "[unit][contact][physics]") {
  // Stopping distance v0²/(2 μ g).
  const double v0 = 3.0, mu = 0.5;
  for (const int substeps : {1, 8, 64}) {
    INFO("substeps " << substeps);
    const Slide s = slide(v0, 0.0, mu, mu, substeps, 3.0);
    CHECK(s.speed == Approx(0.0).margin(1e-9));
    CHECK(s.distance == Approx(v0 * v0 / (2 * mu * 9.81)).epsilon(0.03));
  }
}

TEST_CASE("static friction holds below mu_s*m*g and lets go above it", "[unit][contact][physics]") {
  const double mu_s = 0.6, mu_k = 0.4;
  CHECK(std::abs(slide(0.0, 0.9 * mu_s * 9.81, mu_s, mu_k, 8, 1.0).distance) < 1e-9);
  const Slide pushed = slide(0.0, 1.2 * mu_s * 9.81, mu_s, mu_k, 8, 1.0);
  // Once moving, kinetic friction: a = push − μ_k g
  const double a = 1.2 * mu_s * 9.81 - mu_k * 9.81;
  CHECK(pushed.distance == Approx(0.5 * a * 1.0).epsilon(0.05));
}

// Box contacts: the minimal-overlap normal and depth, the gradient the contact projection uses, and
// Coulomb friction's physical meaning.
#include <algorithm>
#include <catch2/catch.hpp>
#include <functional>

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

TEST_CASE("a particle sent through a thin wall goes back by the face it came in by", "[unit][contact]") {
  const Aabb wall{{5.0, -10.0}, {5.05, 10.0}};  // 5 cm thick
  // From outside, straight through in one substep (the slab test): back to the near face.
  const auto through = swept_box_contact({4.9, 0.0}, {5.2, 0.0}, wall);
  REQUIRE(through);
  CHECK(through->normal == Vec2{-1, 0});
  CHECK(through->depth == Approx(0.2));
  // From a nanometre inside (a resting contact's residue), predicted past the wall's middle: still
  // back by the near face, where the face nearest the predicted point is the far one.
  const auto resting = swept_box_contact({5.0 + 1e-9, 0.0}, {5.04, 0.0}, wall);
  REQUIRE(resting);
  CHECK(resting->normal == Vec2{-1, 0});
  CHECK(resting->depth == Approx(0.04));
  CHECK(box_contact({5.04, 0.0}, wall)->normal == Vec2{1, 0});  // what it got before
  // ... and predicted right through it: back as well.
  const auto beyond = swept_box_contact({5.0 + 1e-9, 0.0}, {5.3, 0.0}, wall);
  REQUIRE(beyond);
  CHECK(beyond->normal == Vec2{-1, 0});
  CHECK(beyond->depth == Approx(0.3));
  // One that started inside near the top and left over it is free.
  CHECK_FALSE(swept_box_contact({5.0 + 1e-9, 10.0 - 1e-3}, {4.9, 10.2}, wall));
  CHECK_FALSE(swept_box_contact({5.0 + 1e-9, 0.0}, {4.9, 0.0}, wall));  // and one that backed out
}

namespace {

// ∂f/∂x by central differences.
template <typename F>
Vec2 central_difference(F&& f, Vec2 x) {
  const double eps = 1e-7;
  return {(f(x + Vec2{eps, 0}) - f(x - Vec2{eps, 0})) / (2 * eps),
          (f(x + Vec2{0, eps}) - f(x - Vec2{0, eps})) / (2 * eps)};
}

}  // namespace

TEST_CASE("the contact projection the solver runs moves along the finite-difference gradient",
          "[unit][contact]") {
  // solve_contacts runs swept_box_contact, then resolve_contact. Its constraint is C(x) ≥ 0 with C
  // the signed distance to the surface: to the nearest face for a particle that started inside, to
  // the face it came in through for one that entered this substep. Each C is written here from the
  // box's bounds, not taken from the engine. One projection (α = 0, the surface of infinite mass,
  // so w cancels) moves the particle by Δx = −C ∇C/|∇C|², times its share for a body of finite mass.
  const Aabb box{{-1, -1}, {1, 0}};
  const auto inside = [&](Vec2 q) {  // −(distance to the nearest face): negative inside
    return -std::min({q.x - box.min.x, box.max.x - q.x, q.y - box.min.y, box.max.y - q.y});
  };
  const auto through_top = [&](Vec2 q) { return q.y - box.max.y; };
  const auto through_left = [&](Vec2 q) { return box.min.x - q.x; };
  const auto through_bottom = [&](Vec2 q) { return box.min.y - q.y; };
  struct Case {
    Vec2 from, to;
    double share;
    std::function<double(Vec2)> C;
  };
  const Case cases[] = {
      {{0.2, -0.1}, {0.2, -0.1}, 1.0, inside},          // started inside: nearest face (top)
      {{-0.95, -0.4}, {-0.95, -0.4}, 1.0, inside},      // left
      {{0.97, -0.5}, {0.97, -0.5}, 0.4, inside},        // right, a body's share
      {{0.1, -0.98}, {0.1, -0.98}, 1.0, inside},        // bottom
      {{0.3, 0.2}, {0.35, -0.05}, 1.0, through_top},    // landed from above
      {{-1.2, -0.5}, {-0.5, -0.3}, 1.0, through_left},  // came in through the left face, nearer the top
      {{-1.5, 0.1}, {-0.8, -0.5}, 0.7, through_left},   // over the corner (slab test): left face last
      {{-1.3, 0.4}, {-0.9, -0.02}, 1.0, through_top},   // over the corner: the top face last
      {{0.5, -1.3}, {0.6, -0.9}, 1.0, through_bottom},  // from below
  };
  for (const Case& k : cases) {
    INFO("from (" << k.from.x << ", " << k.from.y << ") to (" << k.to.x << ", " << k.to.y << ")");
    const auto contact = swept_box_contact(k.from, k.to, box);
    REQUIRE(contact);
    const double C = k.C(k.to);
    REQUIRE(C < 0.0);
    const Vec2 grad = central_difference(k.C, k.to);
    Vec2 x = k.to;
    ContactRecord rec;
    resolve_contact(x, k.from, *contact, 0.0, 0.0, rec, {}, k.share);
    const Vec2 expected = grad * (-C / length_squared(grad) * k.share);
    CHECK((x - k.to).x == Approx(expected.x).margin(1e-8));
    CHECK((x - k.to).y == Approx(expected.y).margin(1e-8));
    CHECK(rec.lambda_n == Approx(-C * k.share).margin(1e-12));  // the correction, as a distance
    // All of it lands exactly on the surface.
    if (k.share == 1.0) CHECK(k.C(x) == Approx(0.0).margin(1e-12));
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
  Particles p(1);
  p.x.assign({{0, 0}});
  p.v.assign({{v0, 0}});
  p.w.assign({1.0});
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

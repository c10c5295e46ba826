// The global method's contacts between tires (tire_neighbours.h): the tires' colours and the
// pushes handed to a neighbour.
#include <catch2/catch.hpp>
#include <numeric>
#include <random>
#include <set>

#include "tire/tire/tire_neighbours.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

TEST_CASE("tires are coloured so that no two neighbours share a colour, each tire once, in order",
          "[unit][soft][global]") {
  std::mt19937 rng(11);
  const std::uint32_t count = 200;
  std::uniform_int_distribution<std::uint32_t> pick(0, count - 1);
  // Each pair once, as the broad phase lists them: random ones, and a tire with 95 neighbours (more
  // than the 64 colours the Gauss–Seidel pairs have).
  std::set<std::pair<std::uint32_t, std::uint32_t>> unique;
  for (std::uint32_t b = 5; b < 100; ++b) unique.insert({0, b});
  for (int k = 0; k < 900; ++k) {
    std::uint32_t a = pick(rng), b = pick(rng);
    if (a == b || a == 0 || b == 0) continue;
    unique.insert({std::min(a, b), std::max(a, b)});
  }
  std::vector<TirePair> pairs;
  for (const auto& [a, b] : unique) pairs.push_back({a, b});
  std::vector<Tire> tires;
  TireNeighbours neighbours;
  neighbours.reserve(tires, pairs.size());
  std::vector<std::uint32_t> all(count);
  std::iota(all.begin(), all.end(), 0u);
  neighbours.set_pairs(count, all, pairs);

  std::vector<int> colour(count, -1);
  std::size_t most_neighbours = 0;
  for (std::size_t c = 0; c < neighbours.colours(); ++c) {
    const auto list = neighbours.tires_of_colour(c);
    REQUIRE(!list.empty());
    for (std::size_t k = 0; k < list.size(); ++k) {
      CHECK(colour[list[k]] == -1);  // each tire in one colour only
      colour[list[k]] = static_cast<int>(c);
      if (k > 0) CHECK(list[k - 1] < list[k]);  // in tire order
    }
  }
  for (std::uint32_t i = 0; i < count; ++i) {
    REQUIRE(colour[i] >= 0);
    most_neighbours = std::max(most_neighbours, neighbours.neighbours(i).size());
  }
  for (const TirePair& p : pairs) CHECK(colour[p.a] != colour[p.b]);
  CHECK(neighbours.neighbours(0).size() == 95);
  CHECK(neighbours.colours() <= most_neighbours + 1);  // greedy: at most one more than the most
}

namespace {
// Two tires side by side, captured, with tire 0 owing tire 1 `push` at tire 1's leftmost tread
// point.
struct Pushed {
  std::vector<Tire> tires;
  TireNeighbours neighbours;
  Vec2 point;
  explicit Pushed(Vec2 push) {
    tires.emplace_back(0, tire_at({-1.0, 0.0}));
    tires.emplace_back(1, tire_at({0.0, 0.0}));
    neighbours.reserve(tires, 1);
    const std::uint32_t both[] = {0, 1};
    neighbours.set_pairs(tires.size(), both, {{0, 1}});
    neighbours.capture(tires, 1.0 / 120.0);
    std::uint32_t leftmost = 0;
    for (std::uint32_t k = 0; k < tires[1].n; ++k)
      if (tires[1].particles.x[k].x < tires[1].particles.x[leftmost].x) leftmost = k;
    point = tires[1].particles.x[leftmost];
    neighbours.reactions(0).push_back({1, leftmost, point, push, false});
  }
};
}  // namespace

TEST_CASE("a push handed to a neighbour moves it as a rigid body: momentum kept", "[unit][soft][global]") {
  // The push μ n (kg·m) of a contact solved in tire 0's system: tire 1 takes −μ n as a rigid
  // displacement, so its mass-weighted displacement is −μ n and its angular one −r × μ n.
  const Vec2 push{-0.004, 0.001};  // small: well inside the clamp
  Pushed s(push);
  const Tire& b = s.tires[1];
  std::vector<Vec2> before(b.particles.x.begin(), b.particles.x.end());
  const RigidMotion rigid = b.rigid_motion();
  s.neighbours.apply_reactions(s.tires, 1.0, 1.0 / 480, 0);  // tire 1's turn is still to come
  Vec2 linear;
  double angular = 0.0;
  double stretch = 0.0;
  for (std::size_t k = 0; k < before.size(); ++k) {
    const Vec2 dx = b.particles.x[k] - before[k];
    const double m = 1.0 / b.particles.w[k];
    linear += dx * m;
    angular += cross(before[k] - rigid.centroid, dx) * m;
    for (std::size_t j = k + 1; j < before.size(); j += 7)  // it moved without deforming
      stretch = std::max(
          stretch, std::abs(length(b.particles.x[k] - b.particles.x[j]) - length(before[k] - before[j])));
  }
  CHECK(linear.x == Approx(-push.x).margin(1e-12));
  CHECK(linear.y == Approx(-push.y).margin(1e-12));
  CHECK(angular == Approx(-cross(s.point - rigid.centroid, push)).margin(1e-12));
  CHECK(stretch < 1e-6);                     // a rotation's linearisation: second order in the turn
  CHECK(s.neighbours.reactions(0).empty());  // handed over once
}

TEST_CASE("a push a substep could not carry is clamped to the anti-tunnelling limit",
          "[unit][soft][global]") {
  Pushed s(Vec2{-5.0, 0.0});  // would move the 10 kg tire 0.5 m
  const Tire& b = s.tires[1];
  std::vector<Vec2> before(b.particles.x.begin(), b.particles.x.end());
  const double clamp = 1.5;
  s.neighbours.apply_reactions(s.tires, clamp, 1.0 / 480, 0);
  double farthest = 0.0;
  Vec2 mean;
  for (std::size_t k = 0; k < before.size(); ++k) {
    farthest = std::max(farthest, length(b.particles.x[k] - before[k]));
    mean += b.particles.x[k] - before[k];
  }
  CHECK(farthest == Approx(clamp * b.segment_length).epsilon(1e-9));  // at the limit, not beyond
  CHECK(mean.x > 0.0);  // still the push's way (it pushes tire 1 to the right: −μ n with μ n to the left)
}

TEST_CASE("a push owed to a tire already solved this substep waits for its next prediction, momentum kept",
          "[unit][soft][global]") {
  // Tire 1 (colour 1) pushed after its own colour was solved: it does not move now; the push waits
  // in late_push as a rigid change of velocity whose momentum is the push's, −μ n / h.
  const Vec2 push{-0.004, 0.001};
  Pushed s(push);
  const Tire& b = s.tires[1];
  std::vector<Vec2> before(b.particles.x.begin(), b.particles.x.end());
  const RigidMotion rigid = b.rigid_motion();
  const double h = 1.0 / 480;
  s.neighbours.apply_reactions(s.tires, 1.0, h, 1);
  for (std::size_t k = 0; k < before.size(); ++k) CHECK(b.particles.x[k] == before[k]);
  REQUIRE(b.late_push.any);
  Vec2 momentum;
  double angular = 0.0;
  const double m = b.particle_mass();
  for (const Vec2& x : b.particles.x) {
    const Vec2 dv = b.late_push.velocity + perp(x - b.late_push.centre) * b.late_push.spin;
    momentum += dv * m;
    angular += cross(x - rigid.centroid, dv) * m;
  }
  CHECK(momentum.x * h == Approx(-push.x).margin(1e-12));
  CHECK(momentum.y * h == Approx(-push.y).margin(1e-12));
  CHECK(angular * h == Approx(-cross(s.point - rigid.centroid, push)).margin(1e-12));
}

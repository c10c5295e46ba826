// A tire's own state in one block (issue 12), and what a move does to it: nothing a step can see.
#include <catch2/catch.hpp>
#include <cstring>
#include <span>
#include <type_traits>
#include <utility>

#include "tire/tire/tire_solver.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

// World keeps a std::vector<Tire>: it moves them as it grows and as tires are removed. Nothing copies
// one (a copy would need every view re-pointed into a block of its own).
static_assert(!std::is_copy_constructible_v<Tire> && !std::is_copy_assignable_v<Tire>);
static_assert(std::is_nothrow_move_constructible_v<Tire> && std::is_nothrow_move_assignable_v<Tire>);

namespace {

const Vec2 kGravity{0.0, -9.81};

// Every array of a fixed size lies in the tire's block.
bool arrays_in_block(const Tire& t) {
  const ArrayBlock& b = t.arrays;
  return b.holds(t.particles.x) && b.holds(t.particles.x_prev) && b.holds(t.particles.v) &&
         b.holds(t.particles.w) && b.holds(t.contacts) && b.holds(t.contact_mask) &&
         b.holds(t.grounded_flags) && b.holds(t.soft_lambda) && b.holds(t.on_tire);
}

template <typename T>
bool same_bytes(std::span<const T> a, std::span<const T> b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size_bytes()) == 0;
}

void tick(Tire& t, RigidWorld& rigid, const SolverConfig& config, const TickInput& input) {
  tick_lone_tire(t, rigid, config, kGravity, input);
}

RigidWorld ground_with_a_bump() {
  RigidWorld rigid(kGravity);
  rigid.add_obstacle({{{-100.0, -1.0}, {100.0, 0.0}}});
  rigid.add_obstacle({{{2.0, 0.0}, {2.6, 0.15}}});
  return rigid;
}

}  // namespace

TEST_CASE("a tire keeps its fixed-size arrays in its one block", "[unit][memory]") {
  TireSpec spec = tire_at({0.0, 0.52});
  spec.segments = 20;
  const Tire t(0, spec);
  CHECK(arrays_in_block(t));
  CHECK(t.particles.size() == 40);
  CHECK(t.contacts.size() == 40);
  CHECK(t.contact_mask.size() == 1);
  CHECK(t.soft_lambda.size() == 20);
  CHECK(t.sizes_consistent());
}

TEST_CASE("a moved tire steps to the same bits as one never moved", "[unit][memory][determinism]") {
  const SolverConfig config;
  TireSpec spec = tire_at({0.0, 0.6});
  RigidWorld reference_rigid = ground_with_a_bump(), moved_rigid = ground_with_a_bump();
  Tire reference(0, spec);
  Tire source(0, spec);
  const auto input_at = [](int tick) {
    return TickInput{tick < 200 ? 1.0 : -0.5, tick == 90 || tick == 260};
  };
  const auto compare = [&](const Tire& t, int tick) {
    CAPTURE(tick);
    REQUIRE(same_bytes<Vec2>(t.particles.x, reference.particles.x));
    REQUIRE(same_bytes<Vec2>(t.particles.v, reference.particles.v));
    REQUIRE(same_bytes<std::uint8_t>(t.grounded_flags, reference.grounded_flags));
  };
  int tick_count = 0;
  for (; tick_count < 100; ++tick_count) {
    tick(reference, reference_rigid, config, input_at(tick_count));
    tick(source, moved_rigid, config, input_at(tick_count));
  }
  compare(source, tick_count);

  // Mid-run (contacts, λ and the prepared masses all live), moved into a new tire...
  const Vec2* where = source.particles.x.data();
  Tire moved(std::move(source));
  CHECK(moved.particles.x.data() == where);
  CHECK(arrays_in_block(moved));
  for (; tick_count < 200; ++tick_count) {
    tick(reference, reference_rigid, config, input_at(tick_count));
    tick(moved, moved_rigid, config, input_at(tick_count));
    compare(moved, tick_count);
  }

  // ... then over a tire of another shape, whose block it frees.
  TireSpec other = tire_at({5.0, 2.0});
  other.segments = 12;
  Tire assigned(1, other);
  assigned = std::move(moved);
  CHECK(assigned.particles.x.data() == where);
  CHECK(arrays_in_block(assigned));
  CHECK(assigned.sizes_consistent());
  for (; tick_count < 300; ++tick_count) {
    tick(reference, reference_rigid, config, input_at(tick_count));
    tick(assigned, moved_rigid, config, input_at(tick_count));
    compare(assigned, tick_count);
  }
  CHECK(reference.centroid().x > 1.0);  // it went somewhere: over the bump and back
}

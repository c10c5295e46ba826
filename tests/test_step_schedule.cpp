// The step as the algorithm: World::step's plain schedule (Small Steps' Algorithm 1, one phase at a
// time) and its fused one (the default: fewer sweeps over the tires) give the same bits, and a
// World with one tire does to it exactly what the tire solver's plain substep() loop does.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "tire/math/state_hash.h"
#include "tire/tire/tire_solver.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {

// Steering both ways and at part strength, stopping, and jumps (only a grounded tire jumps).
TickInput input_at(int tick) {
  const double steer = tick < 150 ? 1.0 : tick < 260 ? -1.0 : tick < 330 ? 0.0 : 0.6;
  return {steer, tick == 70 || tick == 210 || tick == 400};
}

std::unique_ptr<LevelSession> session_of(const std::string& level_file,
                                         const std::vector<std::string>& overrides, StepSchedule schedule,
                                         unsigned threads) {
  const LevelLoad load = load_level_file(source_path(level_file), overrides);
  REQUIRE(load.errors.empty());
  auto session = make_session(*load.level);
  session->world().set_schedule(schedule);
  session->world().set_threads(threads);
  return session;
}

// Bytes, not ==: the same bits (−0.0 against 0.0 would count as a difference).
template <typename T>
bool same_bytes(std::span<const T> a, std::span<const T> b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size_bytes()) == 0);
}
template <typename T>
bool same_bytes(const ArrayView<T>& a, const ArrayView<T>& b) {
  return same_bytes(std::span<const T>(a), std::span<const T>(b));
}

}  // namespace

TEST_CASE("the fused and plain schedules give the same bits on the shipped levels",
          "[unit][determinism][schedule][long]") {
  struct Case {
    const char* level;
    std::vector<std::string> overrides;
    int ticks;
    unsigned threads;
  };
  // 01, 03 (a chain terrain) and 05 (kinematic platforms) have no dynamic prop, so the fused
  // schedule carries each velocity pass into the next substep's sweep; 04 and 07 have crates, so it
  // does not. 06 rains 24 tires onto each other (tire pairs), also with three iterations a
  // substep; 08 rains 300 (small ones, in columns), enough in the second half for two threads.
  const Case c =
      GENERATE(Case{"levels/01-first-roll.json", {}, 480, 1}, Case{"levels/01-first-roll.json", {}, 480, 2},
               Case{"levels/03-hills.json", {}, 480, 1}, Case{"levels/03-hills.json", {}, 480, 2},
               Case{"levels/04-crates.json", {}, 480, 1}, Case{"levels/05-platforms.json", {}, 480, 1},
               Case{"levels/05-platforms.json", {}, 480, 2}, Case{"levels/06-tire-rain.json", {}, 480, 1},
               Case{"levels/06-tire-rain.json", {}, 480, 2},
               Case{"levels/06-tire-rain.json", {"solver.iterations=3"}, 420, 1},
               Case{"levels/07-sandbox.json", {}, 480, 2}, Case{"levels/08-three-hundred.json", {}, 480, 2});
  CAPTURE(c.level, c.overrides, c.threads);
  auto fused = session_of(c.level, c.overrides, StepSchedule::fused, c.threads);
  auto plain = session_of(c.level, c.overrides, StepSchedule::plain, c.threads);
  CHECK(fused->world().schedule() == StepSchedule::fused);
  CHECK(plain->world().schedule() == StepSchedule::plain);
  const std::uint64_t start = fused->state_hash();
  std::size_t most_pairs = 0;
  int parallel_ticks = 0;
  for (int tick = 0; tick < c.ticks; ++tick) {
    fused->step(input_at(tick));
    plain->step(input_at(tick));
    CAPTURE(tick);
    REQUIRE(fused->state_hash() == plain->state_hash());
    most_pairs = std::max(most_pairs, fused->world().tire_pair_count());
    if (fused->world().threads_in_use() > 1) ++parallel_ticks;
  }
  CHECK(fused->state_hash() != start);  // something moved
  CHECK(fused->world().warnings().empty());
  const std::string level = c.level;
  if (level == "levels/06-tire-rain.json" || level == "levels/08-three-hundred.json") CHECK(most_pairs > 0);
  if (level == "levels/08-three-hundred.json") CHECK(parallel_ticks > 100);
}

TEST_CASE("the default schedule is the fused one", "[unit][schedule]") {
  World world(SolverConfig{}, {0, -9.81});
  CHECK(world.schedule() == StepSchedule::fused);
}

TEST_CASE("a world with one tire steps it exactly as the plain substep loop does",
          "[unit][determinism][schedule]") {
  // The World adds nothing to a lone tire (with sleeping off): the same particle positions, velocities and
  // grounded flags, bit for bit, as begin_tick, then substep() for each substep, between the rigid world's
  // begin_tick and end_tick. With a crate, the same impulses handed to it too: one on the ground in
  // the tire's way (a supported prop: Box2D alone moves it), or one dropped onto the tire (a free
  // prop: each impulse moves it at once, so when friction's are handed over matters).
  enum class Crate { none, ahead, on_top };
  const StepSchedule schedule = GENERATE(StepSchedule::fused, StepSchedule::plain);
  const int iterations = GENERATE(1, 3);
  const Crate crate = GENERATE(Crate::none, Crate::ahead, Crate::on_top);
  CAPTURE(schedule == StepSchedule::fused, iterations, static_cast<int>(crate));
  // Gauss–Seidel's schedules. The global method's world adds what the plain loop has not: the
  // refinement of a tick's substeps, and Box2D stepped with the substeps (rigid_world.h).
  SolverConfig config = SolverConfig::gauss_seidel_8x1();
  config.iterations = iterations;
  config.sleep = false;  // the plain loop has no sleeping: the world must add nothing else
  const Vec2 gravity{0.0, -9.81};
  const Obstacle ground{{{-100.0, -1.0}, {100.0, 0.0}}};
  TireSpec spec = tire_at({0.0, 0.52});
  PropSpec box;
  box.type = PropType::dynamic_body;
  box.size = {0.6, 0.6};
  box.density = 20;
  box.position = crate == Crate::on_top ? Vec2{0.1, 1.6} : Vec2{2.5, 0.3};

  World world(config, gravity);
  world.set_schedule(schedule);
  world.add_obstacle(ground);
  if (crate != Crate::none) world.add_prop(box);
  const TireId id = world.add_tire(spec);

  RigidWorld rigid(gravity);
  rigid.add_obstacle(ground);
  if (crate != Crate::none) rigid.add_prop(box);
  Tire tire(id, spec);

  double farthest = 0.0;
  for (int tick = 0; tick < 480; ++tick) {
    const TickInput input = input_at(tick);
    world.step(input);

    tick_lone_tire(tire, rigid, config, gravity, input);
    // The world keeps Box2D from putting a prop near an awake tire to sleep (sleep_islands.h): so
    // does the plain loop.
    if (crate != Crate::none)
      rigid.set_sleeping_allowed(0, std::find(tire.prop_candidates.begin(), tire.prop_candidates.end(), 0u) ==
                                        tire.prop_candidates.end());

    CAPTURE(tick);
    const Tire& stepped = world.tires().front();
    REQUIRE(same_bytes(stepped.particles.x, tire.particles.x));
    REQUIRE(same_bytes(stepped.particles.v, tire.particles.v));
    REQUIRE(same_bytes(stepped.grounded_flags, tire.grounded_flags));
    StateHash a, b;
    world.rigid().hash_into(a);
    rigid.hash_into(b);
    REQUIRE(a.digest() == b.digest());
    farthest = std::max(farthest, tire.centroid().x);
  }
  // It rolled (to +x, then back), and the crate ahead was pushed, the one on top thrown off.
  CHECK(farthest > 2.0);
  if (crate != Crate::none) CHECK(std::abs(rigid.current_pose(0).position.x - box.position.x) > 0.1);
}

// Same binary, same input: the same state, bit for bit, every tick.
#include <catch2/catch.hpp>

#include "state_hash.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {
TickInput scripted_input(int tick) {
  return {tick < 100 ? 1.0 : tick < 200 ? -0.5 : 0.0, tick == 80 || tick == 150};
}
}  // namespace

TEST_CASE("the same input twice gives the same hash at every tick", "[unit][determinism]") {
  const Level level = default_level();
  World a(level.solver, level.gravity), b(level.solver, level.gravity);
  populate_world(level, a);
  populate_world(level, b);
  for (int tick = 0; tick < 300; ++tick) {
    if (tick == 120) a.add_tire(tire_at({2, 3})), b.add_tire(tire_at({2, 3}));
    a.step(scripted_input(tick));
    b.step(scripted_input(tick));
    REQUIRE(a.state_hash() == b.state_hash());
  }
}

TEST_CASE("a different input gives a different hash", "[unit][determinism]") {
  const Level level = default_level();
  World a(level.solver, level.gravity), b(level.solver, level.gravity);
  populate_world(level, a);
  populate_world(level, b);
  for (int tick = 0; tick < 60; ++tick) {
    a.step({});
    b.step({tick == 30 ? 0.01 : 0.0, false});
  }
  CHECK(a.state_hash() != b.state_hash());
  CHECK(to_hex(a.state_hash()).size() == 16);
}

// The step loop must not touch the heap once a world is built: counted with a global operator new.
#include <atomic>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <new>

#include "tire_fixtures.h"

namespace {
std::atomic<long> allocations{0};
}

void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace tire;
using namespace tire::test;

TEST_CASE("stepping a world does not allocate", "[unit][performance]") {
  SolverConfig config;
  World world(config, {0, -9.81});
  world.add_obstacle({{{-100, -1}, {100, 0}}});
  for (int i = 0; i < 20; ++i) world.add_obstacle({{{3.0 * i, 0}, {3.0 * i + 1, 0.3}}});
  for (int i = 0; i < 4; ++i) world.add_tire(tire_at({1.5 * i, 0.6 + i}));
  for (int i = 0; i < 10; ++i) world.step({1.0, false});  // warm up: candidate lists reach their size
  const long before = allocations.load();
  for (int i = 0; i < 600; ++i) world.step({i % 100 < 50 ? 1.0 : -1.0, i % 60 == 0});
  CHECK(allocations.load() - before == 0);
}

TEST_CASE("stepping a pile of tires on two threads does not allocate", "[unit][performance]") {
  // The parallel path: tire pairs, their colours, the worker pool, and crates taking impulses.
  World world(SolverConfig{}, {0, -9.81});
  world.set_threads(2);
  world.add_obstacle({{{-1, -1}, {13, 0}}});
  world.add_obstacle({{{-1, 0}, {0, 50}}});
  world.add_obstacle({{{12, 0}, {13, 50}}});
  for (int i = 0; i < 64; ++i) world.add_tire(tire_at({0.6 + 1.05 * (i % 11) + 0.2 * ((i / 11) % 2), 0.5 + 1.0 * (i / 11)}));
  PropSpec crate;
  crate.type = PropType::dynamic_body;
  crate.size = {0.6, 0.6};
  crate.position = {5.0, 8.0};
  world.add_prop(crate);
  for (int i = 0; i < 10; ++i) world.step({0.0, false});  // the pool starts its threads
  const long before = allocations.load();
  for (int i = 0; i < 300; ++i) world.step({1.0, i % 60 == 0});
  CHECK(allocations.load() - before == 0);
}

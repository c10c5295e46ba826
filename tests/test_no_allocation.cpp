// The step loop must not touch the heap once a world is built. Three witnesses, because each sees
// what another cannot:
//  - every replaceable global operator new and delete, replaced here: plain and array, aligned
//    (the distance batches are alignas(32): std::vector<Batch> allocates with operator
//    new(size_t, align_val_t)), nothrow and aligned nothrow, and every delete that matches them;
//  - malloc and friends (malloc, calloc, realloc, free, aligned_alloc, posix_memalign, memalign,
//    valloc), interposed by this executable and forwarded to glibc's own (__libc_malloc, ...), so
//    that callers that never see operator new are counted too: Box2D's b2Alloc is malloc, and
//    libbox2d is a shared library whose calls bind to the definitions here;
//  - glibc's mallinfo2: the bytes the allocator has handed out (uordblks, arenas of every thread,
//    plus hblkhd, the mmapped chunks). It cannot see a block taken and given back within the loop
//    (a freed small block stays "in use" in its thread's cache), but it sees any net growth, even
//    one that bypassed the symbols above.
// "the allocation counters see ..." checks that each witness sees what it is meant to.
//
// Under AddressSanitizer (tools/sanitize-test) malloc must stay ASan's: the interposition is left
// out and operator new goes to std::malloc; mallinfo2 then reports ASan's figures (zeros). That
// build does not run this binary (the exclusion in tools/sanitize-test).
#include <malloc.h>

#include <atomic>
#include <catch2/catch.hpp>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include "tire/engine.h"
#include "tire_fixtures.h"

#if defined(__SANITIZE_ADDRESS__)
#define TIRE_INTERPOSE_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TIRE_INTERPOSE_MALLOC 0
#endif
#endif
#ifndef TIRE_INTERPOSE_MALLOC
#define TIRE_INTERPOSE_MALLOC 1
#endif

namespace {

// Relaxed atomics: they never allocate, and the worker threads count too.
constinit std::atomic<long> news{0};          // operator new, new[] and their nothrow forms
constinit std::atomic<long> aligned_news{0};  // the align_val_t forms
constinit std::atomic<long> deletes{0};       // every operator delete of a non-null pointer
constinit std::atomic<long> mallocs{0};       // malloc, calloc, realloc, aligned_alloc, ... (not via new)
constinit std::atomic<long> frees{0};         // free of a non-null pointer (not via delete)

void count(std::atomic<long>& c) { c.fetch_add(1, std::memory_order_relaxed); }

}  // namespace

#if TIRE_INTERPOSE_MALLOC
// glibc's allocator under its own names (exported by libc.so.6 since 2.2.5): what malloc and the
// rest would have been without the definitions below.
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void __libc_free(void* p);
void* __libc_memalign(std::size_t alignment, std::size_t size);
void* __libc_valloc(std::size_t size);
}

namespace {
void* raw_malloc(std::size_t size) { return __libc_malloc(size); }
void* raw_aligned(std::size_t alignment, std::size_t size) { return __libc_memalign(alignment, size); }
void raw_free(void* p) { __libc_free(p); }
}  // namespace

extern "C" {
void* malloc(std::size_t size) noexcept {
  count(mallocs);
  return __libc_malloc(size);
}
void* calloc(std::size_t n, std::size_t size) noexcept {
  count(mallocs);
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t size) noexcept {
  count(mallocs);
  return __libc_realloc(p, size);
}
void free(void* p) noexcept {
  if (p) count(frees);
  __libc_free(p);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) noexcept {
  count(mallocs);
  if (alignment == 0 || (alignment & (alignment - 1)) != 0) {
    errno = EINVAL;
    return nullptr;
  }
  return __libc_memalign(alignment, size);
}
void* memalign(std::size_t alignment, std::size_t size) noexcept {
  count(mallocs);
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) noexcept {
  count(mallocs);
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* p = __libc_memalign(alignment, size);
  if (!p) return ENOMEM;
  *out = p;
  return 0;
}
void* valloc(std::size_t size) noexcept {
  count(mallocs);
  return __libc_valloc(size);
}
}
#else
namespace {
void* raw_malloc(std::size_t size) { return std::malloc(size); }
void* raw_aligned(std::size_t alignment, std::size_t size) {
  return std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
}
void raw_free(void* p) { std::free(p); }
}  // namespace
#endif

namespace {
void* counted_new(std::size_t size) {
  count(news);
  return raw_malloc(size == 0 ? 1 : size);
}
void* counted_aligned_new(std::size_t size, std::align_val_t alignment) {
  count(aligned_news);
  return raw_aligned(static_cast<std::size_t>(alignment), size == 0 ? 1 : size);
}
void counted_delete(void* p) {
  if (!p) return;
  count(deletes);
  raw_free(p);
}
}  // namespace

// All eight replaceable allocation functions and all twelve deallocation functions, so that
// whatever form the library picks, allocation and release go through the same allocator.
void* operator new(std::size_t size) {
  if (void* p = counted_new(size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  if (void* p = counted_new(size)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return counted_new(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return counted_new(size); }
void* operator new(std::size_t size, std::align_val_t alignment) {
  if (void* p = counted_aligned_new(size, alignment)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
  if (void* p = counted_aligned_new(size, alignment)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  return counted_aligned_new(size, alignment);
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  return counted_aligned_new(size, alignment);
}
void operator delete(void* p) noexcept { counted_delete(p); }
void operator delete[](void* p) noexcept { counted_delete(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { counted_delete(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { counted_delete(p); }
void operator delete(void* p, std::size_t) noexcept { counted_delete(p); }
void operator delete[](void* p, std::size_t) noexcept { counted_delete(p); }
void operator delete(void* p, std::align_val_t) noexcept { counted_delete(p); }
void operator delete[](void* p, std::align_val_t) noexcept { counted_delete(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { counted_delete(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { counted_delete(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { counted_delete(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { counted_delete(p); }

using namespace tire;
using namespace tire::test;

namespace {

// What the three witnesses have seen so far.
struct HeapActivity {
  long news = 0, aligned_news = 0, deletes = 0, mallocs = 0, frees = 0;
  std::size_t in_use = 0;  // mallinfo2: uordblks + hblkhd (bytes)

  static HeapActivity now() {
    const struct mallinfo2 m = mallinfo2();
    return {::news.load(),    ::aligned_news.load(), ::deletes.load(),
            ::mallocs.load(), ::frees.load(),        m.uordblks + m.hblkhd};
  }
};

// Checks that nothing touched the heap between `before` and now.
void check_untouched(const HeapActivity& before) {
  const HeapActivity after = HeapActivity::now();
  CHECK(after.news - before.news == 0);
  CHECK(after.aligned_news - before.aligned_news == 0);
  CHECK(after.deletes - before.deletes == 0);
  CHECK(after.mallocs - before.mallocs == 0);
  CHECK(after.frees - before.frees == 0);
  CHECK(after.in_use == before.in_use);
}

// Where the self-test's blocks go, so the compiler cannot drop an allocation it sees freed unused.
void* volatile sink;

struct alignas(32) Lanes {
  double v[4];
};

}  // namespace

TEST_CASE("the allocation counters see aligned new, nothrow new, arrays and malloc", "[unit][performance]") {
  // Each block is measured by one snapshot before and one after, with no check in between (a
  // failing check allocates its message).
  HeapActivity before = HeapActivity::now();
  {
    std::vector<Lanes> lanes;  // as the distance batches are stored
    lanes.resize(3);
    sink = lanes.data();
  }
  HeapActivity after = HeapActivity::now();
  CHECK(after.aligned_news - before.aligned_news == 1);
  CHECK(after.news - before.news == 0);
  CHECK(after.deletes - before.deletes == 1);

  before = HeapActivity::now();
  Lanes* one = new (std::nothrow) Lanes;
  sink = one;
  delete one;
  auto* many = new Lanes[2];
  sink = many;
  delete[] many;
  after = HeapActivity::now();
  CHECK(after.aligned_news - before.aligned_news == 2);
  CHECK(after.deletes - before.deletes == 2);

  before = HeapActivity::now();
  auto* ints = new int[5];
  sink = ints;
  delete[] ints;
  auto* nothrow_int = new (std::nothrow) int(3);
  sink = nothrow_int;
  delete nothrow_int;
  after = HeapActivity::now();
  CHECK(after.news - before.news == 2);
  CHECK(after.aligned_news - before.aligned_news == 0);
  CHECK(after.deletes - before.deletes == 2);

#if TIRE_INTERPOSE_MALLOC
  // As b2Alloc does: a plain malloc, which operator new never sees. Bigger than a thread cache's
  // largest block, so that mallinfo2 sees it held.
  before = HeapActivity::now();
  void* block = std::malloc(64 * 1024);
  sink = block;
  const HeapActivity holding = HeapActivity::now();
  std::free(block);
  after = HeapActivity::now();
  CHECK(holding.mallocs - before.mallocs == 1);
  CHECK(holding.news - before.news == 0);
  CHECK(holding.in_use >= before.in_use + 64 * 1024);
  CHECK(after.frees - before.frees == 1);

  before = HeapActivity::now();
  void* zeroed = std::calloc(4, 16);
  void* moved = std::realloc(zeroed, 4096);
  void* aligned = std::aligned_alloc(64, 128);
  void* posix = nullptr;
  const int posix_result = posix_memalign(&posix, 64, 128);
  sink = moved;
  sink = aligned;
  sink = posix;
  std::free(moved);
  std::free(aligned);
  std::free(posix);
  after = HeapActivity::now();
  CHECK(posix_result == 0);
  CHECK(after.mallocs - before.mallocs == 4);
  CHECK(after.frees - before.frees == 3);
#endif
}

TEST_CASE("stepping a world does not allocate", "[unit][performance]") {
  const StepSchedule schedule = GENERATE(StepSchedule::fused, StepSchedule::plain);
  CAPTURE(schedule == StepSchedule::fused);
  SolverConfig config;
  config.method = GENERATE(SolverMethod::gauss_seidel, SolverMethod::global);
  CAPTURE(method_name(config.method));
  World world(config, {0, -9.81});
  world.set_schedule(schedule);
  world.add_obstacle({{{-100, -1}, {100, 0}}});
  for (int i = 0; i < 20; ++i) world.add_obstacle({{{3.0 * i, 0}, {3.0 * i + 1, 0.3}}});
  for (int i = 0; i < 4; ++i) world.add_tire(tire_at({1.5 * i, 0.6 + i}));
  for (int i = 0; i < 10; ++i) world.step({1.0, false});  // warm up: candidate lists reach their size
  const HeapActivity before = HeapActivity::now();
  for (int i = 0; i < 600; ++i) world.step({i % 100 < 50 ? 1.0 : -1.0, i % 60 == 0});
  check_untouched(before);
}

TEST_CASE("driving a vehicle over bumps, with its brake and lean, does not allocate", "[unit][performance]") {
  SolverConfig config;
  config.sleep = false;
  World world(config, {0, -9.81});
  world.add_obstacle({{{-100, -1}, {100, 0}}});
  for (int i = 0; i < 20; ++i) world.add_obstacle({{{3.0 * i + 2, 0}, {3.0 * i + 2.4, 0.08}}});
  VehicleSpec car;
  car.chassis.size = {1.6, 0.3};
  car.chassis.density = 200;
  car.chassis.position = {0, 1.0};
  for (const double x : {-0.7, 0.7}) {
    WheelSpec w;
    w.axle.point = {x, -0.4};
    w.axle.stiffness = 8000;  // both on springs, the front one damped and on its 10 mm travel's stop
    w.axle.damping = x > 0 ? 400.0 : 0.0;
    w.axle.travel = x > 0 ? 0.01 : 0.0;
    car.wheels.push_back(w);
  }
  const std::optional<std::uint32_t> v = world.add_vehicle(car);
  REQUIRE(v);
  REQUIRE(world.set_player_vehicle(*v));
  for (int i = 0; i < 10; ++i) world.step({1.0, false});  // warm up
  const HeapActivity before = HeapActivity::now();
  for (int i = 0; i < 300; ++i) {
    TickInput in;
    in.steer = i % 100 < 70 ? 1.0 : 0.0;
    in.brake = i % 100 >= 85;
    in.lean = i % 40 < 20 ? -1.0 : 0.5;
    world.step(in);
  }
  check_untouched(before);
}

TEST_CASE("reading a simulation's views, as a game does every frame, does not allocate",
          "[unit][performance]") {
  Simulation sim(SolverConfig{}, {0, -9.81});
  sim.add_obstacle({{{-100, -1}, {100, 0}}});
  PropSpec crate;
  crate.type = PropType::dynamic_body;
  crate.position = {3.0, 0.5};
  sim.add_prop(crate);
  for (int i = 0; i < 4; ++i) sim.add_tire(tire_at({1.5 * i, 0.6 + i}));
  for (int i = 0; i < 10; ++i) sim.step({1.0, false});
  const HeapActivity before = HeapActivity::now();
  double sum = 0.0;
  for (int frame = 0; frame < 60; ++frame) {
    for (std::size_t i = 0; const std::optional<TireView> t = sim.tire_at(i); ++i)
      sum += t->positions.front().x + t->outer_radius + (t->grab ? 1.0 : 0.0);
    for (PropId i = 0; i < sim.prop_count(); ++i)
      if (const std::optional<PropView> p = sim.prop(i))
        sum += p->state.pose.position.x + static_cast<double>(p->vertices.size());
    for (const Obstacle& o : sim.obstacles()) sum += o.box.min.x;
    sum += static_cast<double>(sim.regions().size() + sim.messages().size());
  }
  check_untouched(before);
  CHECK(std::isfinite(sum));
}

TEST_CASE("stepping a pile of tires on two threads does not allocate", "[unit][performance]") {
  // The parallel path: tire pairs, their colours, the worker pool, and crates taking impulses
  // (Box2D steps them: its contacts come and go through its own allocators, over malloc).
  const StepSchedule schedule = GENERATE(StepSchedule::fused, StepSchedule::plain);
  CAPTURE(schedule == StepSchedule::fused);
  SolverConfig config;
  config.method = GENERATE(SolverMethod::gauss_seidel, SolverMethod::global);
  CAPTURE(method_name(config.method));
  config.island_tires = GENERATE(0, 64);  // the global method's pile solved as one island
  CAPTURE(config.island_tires);
  World world = pile_under_a_crate(config, 64, 8.0);
  world.set_schedule(schedule);
  world.set_threads(2);
  // The pool starts its threads, and the crate lands on the pile: the first contact Box2D makes for
  // it takes a 16 KiB chunk for its block allocator (b2ContactManager::AddPair, seen in gdb), which
  // with the global method came after the first 10 ticks.
  for (int i = 0; i < 120; ++i) world.step({0.0, false});
  const HeapActivity before = HeapActivity::now();
  for (int i = 0; i < 300; ++i) world.step({1.0, i % 60 == 0});
  check_untouched(before);
}

TEST_CASE("a tire along a long chain and a heap of tires past solver.tire_neighbours do not allocate",
          "[unit][performance]") {
  // A chain's contacts ask its edge tree (a stack of its own, no list); the broad phase between
  // tires, past the limit, keeps each crowded tire's nearest in scratch that reaches its size on
  // the first tick, when the heap is tightest.
  SolverConfig config;
  config.method = GENERATE(SolverMethod::gauss_seidel, SolverMethod::global);
  CAPTURE(method_name(config.method));
  config.tire_neighbours = 6;
  World world(config, {0, -9.81});
  PropSpec chain;
  chain.shape = PropShape::chain;
  for (int k = 0; k < 5000; ++k) chain.points.push_back({-500.0 + 0.2 * k, 0.02 * std::sin(0.2 * k)});
  world.add_prop(chain);
  world.add_tire(tire_at({-50.0, 0.6}, true));
  for (int i = 0; i < 40; ++i) world.add_tire(tire_at({20.0 + 0.01 * (i % 5), 0.6 + 0.01 * (i / 5)}));
  for (int i = 0; i < 3; ++i) world.step({1.0, false});
  const HeapActivity before = HeapActivity::now();
  for (int i = 0; i < 120; ++i) world.step({1.0, false});
  check_untouched(before);
}

TEST_CASE("falling asleep and waking do not allocate", "[unit][performance]") {
  // Islands form, sleep (tires and a crate lying on one), and wake whole, again and again.
  // Gauss–Seidel 8 × 1: with the global method 7 of the 12 sleep within 900 ticks (tires touching
  // tires rest, but do not all sleep yet: docs/at-rest.md).
  World world(SolverConfig::gauss_seidel_8x1(), {0, -9.81});
  world.add_obstacle({{{-50, -1}, {50, 0}}});
  std::vector<TireId> ids;
  for (int i = 0; i < 12; ++i)
    ids.push_back(world.add_tire(tire_at({1.05 * i - 6.0, 0.5 + (i % 3 == 0 ? 1.0 : 0.0)})));
  PropSpec crate;
  crate.type = PropType::dynamic_body;
  crate.size = {0.6, 0.3};
  crate.position = {0.3, 1.3};
  world.add_prop(crate);
  const auto cycle = [&](int k) {
    for (int i = 0; i < 900 && world.asleep_count() < ids.size(); ++i) world.step({});
    REQUIRE(world.asleep_count() == ids.size());
    world.apply_impulse_to_tire(ids[static_cast<std::size_t>(k) % ids.size()], {0.0, 20.0});
    world.step({});
  };
  cycle(0);  // warm up: every scratch list reaches its size
  const HeapActivity before = HeapActivity::now();
  for (int k = 1; k < 4; ++k) cycle(k);
  check_untouched(before);
}

TEST_CASE("a tire's own state is one block, plus its broad-phase lists", "[unit][performance]") {
  // Issue 12: everything of a tire's own whose size its particle and constraint counts fix
  // (particles, the distance set's lanes, contact records and flags) is one aligned block; the
  // topology is shared by the tires of its shape.
  TireSpec spec = tire_at({0.0, 0.6});
  const std::shared_ptr<const TireTopology> topology =
      std::make_shared<const TireTopology>(TireShape::of(spec));
  const HeapActivity before = HeapActivity::now();
  Tire tire(0, spec, topology);
  const HeapActivity after = HeapActivity::now();
  sink = tire.particles.x.data();
  CHECK(after.aligned_news - before.aligned_news == 1);  // the block (64-byte lines)
  // candidates, prop_candidates, prop_frames, pairs and prop_impulses: growable, their length is
  // the scene's, so each is a vector reserved for a usual scene (tire.h).
  CHECK(after.news - before.news == 5);
  CHECK(after.mallocs - before.mallocs == 0);
}

TEST_CASE("adding a tire to a world takes a bounded number of allocations", "[unit][performance]") {
  // The figure is printed and bounded, so a regression shows. It was 45 before the topology was
  // shared and 23 before the tire's own state became one block.
  // With islands solved as one problem, the room for the largest is made with the second tire.
  SolverConfig config;
  config.island_tires = GENERATE(0, 64);
  CAPTURE(config.island_tires);
  World world(config, {0, -9.81});
  world.add_tire(tire_at({0.0, 0.6}));  // the shape's first tire also builds the shared topology
  world.add_tire(tire_at({1.5, 0.6}));
  // Each added tire: its own block (the one aligned allocation), its five broad-phase lists
  // (tire.h) and its list of pushes owed to neighbours (tire_neighbours.h). The world's arrays sized
  // by the tire count (its tires, tire pairs and colours, the global method's neighbours) at least
  // double when they grow: over 64 additions they reallocate six or seven times each.
  constexpr int kAdded = 64;
  HeapActivity before = HeapActivity::now();
  for (int k = 0; k < kAdded; ++k) world.add_tire(tire_at({3.0 + 1.5 * k, 0.6}));
  const HeapActivity after = HeapActivity::now();
  const double aligned = static_cast<double>(after.aligned_news - before.aligned_news) / kAdded;
  const double plain = static_cast<double>(after.news - before.news) / kAdded;
  WARN("allocations per add_tire, over " << kAdded << " added: " << aligned + plain << " (" << aligned
                                         << " aligned)");
  CHECK(aligned == 1.0);
  CHECK(plain <= 6 + 3);
  CHECK(after.mallocs - before.mallocs == 0);
}

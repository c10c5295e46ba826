// Arrays in one allocation (tire/math/array_block.h): where the layout puts them, what the block
// hands out, and that a move keeps them where they are.
#include <catch2/catch.hpp>
#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>

#include "tire/math/array_block.h"
#include "tire/math/geometry.h"

using namespace tire;

namespace {

struct alignas(32) Lanes {
  double v[4];
};

struct Record {
  Vec2 normal;
  double lambda = 0.0;
  std::int32_t prop = -1;  // a default that is not zero: value-initialisation must give it
  bool active = false;
};

std::uintptr_t address(const void* p) { return reinterpret_cast<std::uintptr_t>(p); }

}  // namespace

// A view reads like the member array it replaced, and cannot be copied (only moved with its block).
static_assert(!std::is_copy_constructible_v<ArrayView<double>> &&
              !std::is_copy_assignable_v<ArrayView<double>>);
static_assert(std::is_nothrow_move_constructible_v<ArrayView<double>> &&
              std::is_nothrow_move_assignable_v<ArrayView<double>>);
static_assert(std::is_same_v<decltype(std::declval<const ArrayView<double>&>()[0]), const double&>,
              "const is deep: a const holder's elements are const");
static_assert(std::is_convertible_v<const ArrayView<double>&, std::span<const double>>);
static_assert(!std::is_convertible_v<const ArrayView<double>&, std::span<double>>);
static_assert(!std::is_copy_constructible_v<ArrayBlock> && std::is_nothrow_move_constructible_v<ArrayBlock>);

TEST_CASE("a block layout puts each array on a cache line of its own, at least at its alignment",
          "[unit][memory]") {
  BlockLayout layout;
  const BlockSlot<std::uint8_t> flags = layout.add<std::uint8_t>(3);
  const BlockSlot<Lanes> lanes = layout.add<Lanes>(5);
  const BlockSlot<Vec2> points = layout.add<Vec2>(7);
  const BlockSlot<double> none = layout.add<double>(0);
  const BlockSlot<Record> records = layout.add<Record>(2);
  CHECK(flags.offset == 0);
  CHECK(lanes.offset == 64);  // the next line after 3 bytes
  CHECK(points.offset == 64 + 5 * 32 + 32);
  CHECK(records.offset % 64 == 0);
  CHECK(records.offset >= points.offset + 7 * sizeof(Vec2));
  CHECK(none.count == 0);
  CHECK(layout.size() == records.offset + 2 * sizeof(Record));
  CHECK(layout.alignment() == 64);
}

TEST_CASE("a block hands out its arrays value-initialised, aligned and inside it", "[unit][memory]") {
  BlockLayout layout;
  const BlockSlot<double> a = layout.add<double>(5);
  const BlockSlot<Lanes> b = layout.add<Lanes>(3);
  const BlockSlot<Record> c = layout.add<Record>(4);
  ArrayBlock block(layout);
  CHECK(block.size() == layout.size());
  ArrayView<double> doubles = block.construct(a);
  ArrayView<Lanes> lanes = block.construct(b);
  ArrayView<Record> records = block.construct(c);
  REQUIRE(doubles.size() == 5);
  REQUIRE(lanes.size() == 3);
  REQUIRE(records.size() == 4);
  for (double d : doubles) CHECK(d == 0.0);
  for (const Record& r : records) {
    CHECK(r.prop == -1);
    CHECK(!r.active);
  }
  CHECK(address(doubles.data()) % 64 == 0);
  CHECK(address(lanes.data()) % 64 == 0);
  CHECK(address(records.data()) % 64 == 0);
  CHECK(block.holds(doubles));
  CHECK(block.holds(lanes));
  CHECK(block.holds(records));
  // The arrays do not overlap: each written value is read back.
  for (std::size_t i = 0; i < doubles.size(); ++i) doubles[i] = 1.0 + static_cast<double>(i);
  for (Lanes& l : lanes) l.v[3] = -1.0;
  for (Record& r : records) r.lambda = 2.0;
  for (std::size_t i = 0; i < doubles.size(); ++i) CHECK(doubles[i] == 1.0 + static_cast<double>(i));
  for (const Record& r : records) CHECK(r.lambda == 2.0);

  ArrayBlock other(layout);
  CHECK(!other.holds(doubles));
}

TEST_CASE("a moved block keeps its arrays where they are", "[unit][memory]") {
  BlockLayout layout;
  const BlockSlot<Vec2> slot = layout.add<Vec2>(6);
  ArrayBlock block(layout);
  ArrayView<Vec2> points = block.construct(slot);
  points[5] = {3.0, 4.0};
  const Vec2* where = points.data();

  ArrayBlock moved(std::move(block));
  ArrayView<Vec2> moved_points(std::move(points));
  CHECK(moved.holds(moved_points));
  CHECK(moved_points.data() == where);
  CHECK(moved_points[5] == Vec2{3.0, 4.0});
  CHECK(points.empty());  // a moved-from view is empty, not a second alias
  CHECK(block.size() == 0);

  ArrayBlock assigned;
  ArrayView<Vec2> assigned_points;
  assigned = std::move(moved);
  assigned_points = std::move(moved_points);
  CHECK(assigned_points.data() == where);
  CHECK(assigned_points[5] == Vec2{3.0, 4.0});
}

TEST_CASE("a view copies values in with assign, never by aliasing", "[unit][memory]") {
  BlockLayout layout;
  const BlockSlot<double> first = layout.add<double>(3);
  const BlockSlot<double> second = layout.add<double>(3);
  ArrayBlock block(layout);
  ArrayView<double> a = block.construct(first);
  ArrayView<double> b = block.construct(second);
  a.assign({1.0, 2.0, 3.0});
  b.assign(a);
  b[0] = 9.0;
  CHECK(a[0] == 1.0);
  CHECK(b[1] == 2.0);
  CHECK(a.front() == 1.0);
  CHECK(a.back() == 3.0);
  const std::span<const double> s = a;
  CHECK(s.data() == a.data());
  CHECK(s.size() == 3);
}

// Several fixed-size arrays in one heap allocation: a BlockLayout places them (an offset each,
// computed up front), an ArrayBlock allocates the whole once, and construct() hands out each array
// as an ArrayView into it. A tire keeps everything whose size its particle and constraint counts
// fix in one such block (issue 12): one allocation per tire instead of one per array, and the
// arrays a substep streams through sit next to each other.
//
// Every array starts on a 64-byte cache line, and so does the block: an array never shares a line
// with another (as separate allocations did not), a 64-byte record (the distance constraints'
// LaneState) fills exactly one line, and two tires solved on different threads never write to the
// same line. A type that asks for more (alignas) gets what it asks.
//
// Elements must be trivially destructible: the block frees its memory without running destructors.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

#include "tire/math/array_view.h"
#include "tire/math/check.h"

namespace tire {

// Where one array of T goes in a block: its byte offset and its element count.
template <typename T>
struct BlockSlot {
  std::size_t offset = 0;
  std::size_t count = 0;
};

// The arrays of a block, placed one after the other, each at its alignment.
class BlockLayout {
 public:
  static constexpr std::size_t kCacheLine = 64;

  template <typename T>
  BlockSlot<T> add(std::size_t count) {
    static_assert(std::is_trivially_destructible_v<T>, "a block frees its arrays without destroying them");
    constexpr std::size_t alignment = std::max(alignof(T), kCacheLine);
    const std::size_t offset = (size_ + alignment - 1) / alignment * alignment;
    size_ = offset + count * sizeof(T);
    alignment_ = std::max(alignment_, alignment);
    return {offset, count};
  }

  std::size_t size() const { return size_; }  // bytes
  std::size_t alignment() const { return alignment_; }

 private:
  std::size_t size_ = 0;
  std::size_t alignment_ = kCacheLine;
};

// One heap allocation holding the arrays of a BlockLayout (one aligned operator new, released by
// the matching delete). Move-only; a move hands the allocation over and never moves it, so the
// views construct() gave stay valid.
class ArrayBlock {
 public:
  ArrayBlock() = default;
  explicit ArrayBlock(const BlockLayout& layout);
  ~ArrayBlock();
  ArrayBlock(ArrayBlock&& o) noexcept
      : bytes_(std::exchange(o.bytes_, nullptr)),
        size_(std::exchange(o.size_, 0)),
        alignment_(std::exchange(o.alignment_, BlockLayout::kCacheLine)) {}
  ArrayBlock& operator=(ArrayBlock&& o) noexcept;
  ArrayBlock(const ArrayBlock&) = delete;
  ArrayBlock& operator=(const ArrayBlock&) = delete;

  // Starts the lifetime of the slot's elements, value-initialised (as std::vector::resize does),
  // and returns them. Once per slot: a second call would start them afresh.
  template <typename T>
  ArrayView<T> construct(BlockSlot<T> slot) {
    TIRE_ASSERT(slot.offset % alignof(T) == 0 && slot.offset + slot.count * sizeof(T) <= size_,
                "a slot that is not of this block's layout");
    if (slot.count == 0) return {};
    T* first = std::launder(reinterpret_cast<T*>(bytes_ + slot.offset));
    std::uninitialized_value_construct_n(first, slot.count);
    return {first, slot.count};
  }

  std::size_t size() const { return size_; }  // bytes
  // Whether `view`'s elements lie in this block.
  template <typename T>
  bool holds(const ArrayView<T>& view) const {
    const auto first = reinterpret_cast<std::uintptr_t>(view.data());
    const auto begin = reinterpret_cast<std::uintptr_t>(bytes_);
    return view.empty() || (first >= begin && first - begin + view.size() * sizeof(T) <= size_);
  }

 private:
  void release() noexcept;

  std::byte* bytes_ = nullptr;
  std::size_t size_ = 0;
  std::size_t alignment_ = BlockLayout::kCacheLine;
};

}  // namespace tire

// Hints to the CPU to start loading memory a loop is about to read; they change no result.
#pragma once

#include <ranges>

namespace tire {

// Every 64-byte line of the elements of a contiguous range (a std::vector, an ArrayView).
template <std::ranges::contiguous_range R>
void prefetch(const R& range) {
  const char* p = reinterpret_cast<const char*>(std::ranges::data(range));
  const char* const end = reinterpret_cast<const char*>(std::ranges::data(range) + std::ranges::size(range));
  for (; p < end; p += 64) __builtin_prefetch(p, 1);
}

}  // namespace tire

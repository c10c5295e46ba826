// Hints to the CPU to start loading memory a loop is about to read; they change no result.
#pragma once

#include <vector>

namespace tire {

// Every 64-byte line of v's elements.
template <typename T>
void prefetch(const std::vector<T>& v) {
  const char* p = reinterpret_cast<const char*>(v.data());
  const char* const end = reinterpret_cast<const char*>(v.data() + v.size());
  for (; p < end; p += 64) __builtin_prefetch(p, 1);
}

}  // namespace tire

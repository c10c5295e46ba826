// FNV-1a (64-bit) over the exact bytes of the simulation state. Not cryptographic: it tells two
// states apart, bit for bit, which is what replays and determinism tests need. The bytes hashed
// are the same on every platform: fixed-width integers, IEEE doubles and floats, bools, never a
// type whose size is the platform's (std::size_t, long, pointers: 4 bytes in WebAssembly, 8 here),
// which add() refuses where that size differs from 8.
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>

namespace tire {

class StateHash {
 public:
  void add_bytes(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      h_ ^= bytes[i];
      h_ *= 0x100000001b3ULL;
    }
  }
  template <typename T>
  void add(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    static_assert(!std::is_pointer_v<T>, "a pointer is no state");
    static_assert(sizeof(long) == 8 || !(std::is_same_v<T, long> || std::is_same_v<T, unsigned long>),
                  "std::size_t and long differ in size between platforms: hash a std::uint64_t");
    add_bytes(&value, sizeof(T));
  }
  std::uint64_t digest() const { return h_; }

 private:
  std::uint64_t h_ = 0xcbf29ce484222325ULL;
};

}  // namespace tire

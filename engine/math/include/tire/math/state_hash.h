// FNV-1a (64-bit) over the exact bytes of the simulation state. Not cryptographic: it tells two
// states apart, bit for bit, which is what replays and determinism tests need.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
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
    add_bytes(&value, sizeof(T));
  }
  std::uint64_t digest() const { return h_; }

 private:
  std::uint64_t h_ = 0xcbf29ce484222325ULL;
};

std::string to_hex(std::uint64_t value);

}  // namespace tire

// libFuzzer target: see fuzz_common.h and docs/testing.md, "Hardening".
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tire::fuzz::fuzz_level(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}

// libFuzzer target: see fuzz_session.h and docs/testing.md, "Hardening". Built as a plain program too, with
// session_main.cpp for its main (the test suite's fuzz run).
#include "fuzz_session.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tire::fuzz::fuzz_session(std::string(reinterpret_cast<const char*>(data), size),
                           tire::fuzz::session_budget());
  return 0;
}

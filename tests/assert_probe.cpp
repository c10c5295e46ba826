// TIRE_ASSERT does what engine/math/include/tire/math/check.h says: without NDEBUG a false
// condition prints file:line, the condition and the message, and aborts; with NDEBUG the condition
// is not even evaluated. Run by ctest, which matches the output (tests/CMakeLists.txt).
#include <csignal>
#include <cstdio>
#include <cstdlib>

#include "tire/math/check.h"

namespace {

int evaluated = 0;

bool count_and_fail() {
  ++evaluated;
  return false;
}

#ifndef NDEBUG
extern "C" void on_abort(int) { std::_Exit(0); }
#endif

}  // namespace

int main() {
#ifdef NDEBUG
  TIRE_ASSERT(count_and_fail(), "probe");
  if (evaluated != 0) {
    std::puts("probe: with NDEBUG a TIRE_ASSERT condition was evaluated");
    return 1;
  }
  std::puts("probe: with NDEBUG TIRE_ASSERT is compiled out");
  return 0;
#else
  std::signal(SIGABRT, on_abort);  // the abort is the expected outcome: exit 0 from it
  TIRE_ASSERT(count_and_fail(), "probe");
  std::printf("probe: a failed TIRE_ASSERT returned (evaluated %d times)\n", evaluated);
  return 1;
#endif
}

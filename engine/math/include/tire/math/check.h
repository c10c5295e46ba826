// TIRE_ASSERT(condition, "message"): an invariant of the engine, checked in builds without NDEBUG
// (Debug, which CI runs the whole suite in). A broken one prints file:line, the condition and the
// message to stderr and aborts, at the first place the bug shows rather than ticks later as a NaN
// or a wrong replay hash.
//
// With NDEBUG (Release, RelWithDebInfo) it compiles to nothing: the condition is not evaluated (it
// only appears in an unevaluated sizeof, so what it names still counts as used and no variable
// kept for a check warns), and the code generated is that of the function without the check. So a
// condition may call a loop (all particles finite, say) at no cost to a release build, but must
// have no side effect the program relies on.
#pragma once

#ifdef NDEBUG

#define TIRE_ASSERT(condition, message) static_cast<void>(sizeof(!(condition)))

#else

#include <cstdio>
#include <cstdlib>

namespace tire::detail {

[[noreturn]] inline void assert_failed(const char* condition, const char* message, const char* file,
                                       int line) noexcept {
  std::fprintf(stderr, "%s:%d: TIRE_ASSERT(%s) failed: %s\n", file, line, condition, message);
  std::fflush(stderr);
  std::abort();
}

}  // namespace tire::detail

#define TIRE_ASSERT(condition, message) \
  ((condition) ? static_cast<void>(0)   \
               : ::tire::detail::assert_failed(#condition, message, __FILE__, __LINE__))

#endif

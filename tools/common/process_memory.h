// How much memory this process holds, for the tools that watch it over long runs (tirectl bench,
// tire-soak). Linux: /proc and getrusage; glibc for the heap.
#pragma once

#include <sys/resource.h>
#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <fstream>

namespace tire_tools {

// Resident memory now (MiB), from /proc/self/statm; -1 where unknown.
inline double rss_mib() {
  std::ifstream statm("/proc/self/statm");
  double pages_total = 0.0, pages_resident = -1.0;
  if (!(statm >> pages_total >> pages_resident)) return -1.0;
  return pages_resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// Peak resident memory so far (MiB).
inline double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

// Bytes allocated and not yet freed (glibc's count), in MiB: unlike RSS it does not move with the
// allocator's caching and fragmentation. -1 where unknown.
inline double heap_mib() {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
  const struct mallinfo2 m = mallinfo2();
  return static_cast<double>(m.uordblks + m.hblkhd) / (1024.0 * 1024.0);
#else
  return -1.0;
#endif
}

}  // namespace tire_tools

// A small pool of threads for the world's data-parallel phases (standard library only). Work is
// split into contiguous, equal index ranges, one per thread, so which thread does what never
// affects a result: the phases it runs touch disjoint data, and anything shared is applied
// afterwards in a fixed order by the caller.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>
#include <vector>

namespace tire {

class WorkerPool {
 public:
  // `threads` in all, counting the caller; 1 runs everything on the caller.
  explicit WorkerPool(unsigned threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  unsigned threads() const { return static_cast<unsigned>(workers_.size()) + 1; }

  // Calls fn(begin, end) on [0, n) split into threads() ranges; returns when all are done.
  // Allocation-free: `fn` is passed by reference, not stored.
  template <typename F>
  void parallel_for(std::size_t n, F& fn) {
    if (workers_.empty() || n < 2) {
      fn(std::size_t{0}, n);
      return;
    }
    dispatch(n, [](void* f, std::size_t b, std::size_t e) { (*static_cast<F*>(f))(b, e); }, &fn);
  }

 private:
  using Call = void (*)(void*, std::size_t, std::size_t);
  void dispatch(std::size_t n, Call call, void* fn);
  void work(unsigned index);
  std::size_t begin_of(unsigned part, std::size_t n) const { return n * part / threads(); }

  std::vector<std::jthread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  std::atomic<std::uint64_t> generation_{0};  // bumped per job: workers wait for a new value
  std::atomic<unsigned> sleeping_{0};          // workers asleep on wake_
  std::atomic<unsigned> pending_{0};           // workers not done with the current job
  std::atomic<bool> stop_{false};
  // The current job, published by the increment of generation_.
  std::size_t n_ = 0;
  Call call_ = nullptr;
  void* fn_ = nullptr;
};

}  // namespace tire

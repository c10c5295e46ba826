// A small pool of threads for the world's data-parallel phases (standard library only). A phase's
// index range is cut into a few chunks per thread, which the threads (the caller among them) claim
// one at a time: a thread the OS has put aside leaves its chunks to the others instead of holding
// up the step. Which thread solves which chunk never affects a result: the phases it runs touch
// disjoint data, and anything shared is applied afterwards in a fixed order by the caller.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
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

  // Calls fn(begin, end) on consecutive ranges covering [0, n); returns when all are done.
  // Allocation-free: `fn` is passed by reference, not stored.
  template <typename F>
  void parallel_for(std::size_t n, F& fn) {
    if (workers_.empty() || n < 2) {
      fn(std::size_t{0}, n);
      return;
    }
    dispatch(
        n, [](void* f, std::size_t b, std::size_t e) { (*static_cast<F*>(f))(b, e); }, &fn);
  }

 private:
  using Call = void (*)(void*, std::size_t, std::size_t);
  void dispatch(std::size_t n, Call call, void* fn);
  void work();
  // Claims and runs chunks of job `generation` until none is left or a later job has begun.
  void run_chunks(std::uint32_t generation);

  // Joined by the destructor (std::thread, not jthread: libc++ 14, as in emscripten, has none).
  std::vector<std::thread> workers_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint32_t> generation_{0};  // bumped per job; sleeping workers wait on it
  std::atomic<unsigned> sleeping_{0};         // workers asleep (or about to be) on generation_
  std::atomic<bool> caller_waiting_{false};   // the caller sleeps on chunks_done_
  // The ticket: the job's generation in the high 32 bits, the next unclaimed chunk in the low 32.
  // Claiming is a compare-and-swap on both, so a thread late for one job can never claim a chunk
  // of the next with the last one's call.
  std::atomic<std::uint64_t> ticket_{0};
  std::atomic<std::uint32_t> chunks_done_{0};
  // The current job, written before its ticket is published (relaxed atomics: a late thread may
  // read them while the next job is written, but then its claim fails and it runs nothing).
  std::atomic<std::size_t> n_{0};
  std::atomic<std::uint32_t> chunks_{0};
  std::atomic<Call> call_{nullptr};
  std::atomic<void*> fn_{nullptr};
};

}  // namespace tire

#include "worker_pool.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace tire {

namespace {

// How long a waiting thread stays awake before it sleeps: a step hands out a job every few tens of
// µs, and waking a sleeping thread costs about as much as such a job. Past these counts (a few
// hundred µs) the thread sleeps, so an idle pool between frames costs nothing.
constexpr int kSpinPauses = 4000;
constexpr int kSpinYields = 200;

void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

}  // namespace

WorkerPool::WorkerPool(unsigned threads) {
  for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this, i] { work(i); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    stop_.store(true);
  }
  wake_.notify_all();
}

void WorkerPool::dispatch(std::size_t n, Call call, void* fn) {
  n_ = n;
  call_ = call;
  fn_ = fn;
  pending_.store(static_cast<unsigned>(workers_.size()), std::memory_order_relaxed);
  // Publishes the job. Sequentially consistent with the load of sleeping_ below, as a worker's
  // increment of sleeping_ is with its load of generation_: either it sees this job before it
  // sleeps, or this sees it asleep and wakes it.
  generation_.fetch_add(1);
  if (sleeping_.load() > 0) {
    std::lock_guard lock(mutex_);
    wake_.notify_all();
  }
  call(fn, begin_of(0, n), begin_of(1, n));  // the caller's own share
  for (int spin = 0; pending_.load(std::memory_order_acquire) != 0; ++spin) {
    if (spin < kSpinPauses) {
      cpu_relax();
    } else if (spin < kSpinPauses + kSpinYields) {
      std::this_thread::yield();
    } else {
      std::unique_lock lock(mutex_);
      done_.wait(lock, [this] { return pending_.load(std::memory_order_acquire) == 0; });
      break;
    }
  }
}

void WorkerPool::work(unsigned index) {
  std::uint64_t seen = 0;
  for (;;) {
    std::uint64_t generation = generation_.load(std::memory_order_acquire);
    for (int spin = 0; generation == seen && !stop_.load(std::memory_order_relaxed); ++spin) {
      if (spin < kSpinPauses) {
        cpu_relax();
      } else if (spin < kSpinPauses + kSpinYields) {
        std::this_thread::yield();
      } else {
        std::unique_lock lock(mutex_);
        sleeping_.fetch_add(1);
        wake_.wait(lock, [&] { return stop_.load() || generation_.load() != seen; });
        sleeping_.fetch_sub(1);
        spin = 0;
      }
      generation = generation_.load(std::memory_order_acquire);
    }
    if (stop_.load()) return;
    seen = generation;
    call_(fn_, begin_of(index, n_), begin_of(index + 1, n_));
    if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
      std::lock_guard lock(mutex_);
      done_.notify_one();
    }
  }
}

}  // namespace tire

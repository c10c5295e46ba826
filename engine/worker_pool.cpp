#include "worker_pool.h"

namespace tire {

WorkerPool::WorkerPool(unsigned threads) {
  for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this, i] { work(i); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
}

void WorkerPool::dispatch(std::size_t n, Call call, void* fn) {
  {
    std::lock_guard lock(mutex_);
    n_ = n;
    call_ = call;
    fn_ = fn;
    pending_.store(static_cast<unsigned>(workers_.size()), std::memory_order_relaxed);
    ++generation_;
  }
  wake_.notify_all();
  call(fn, begin_of(0, n), begin_of(1, n));  // the caller's own share
  // The phases are short (tens of µs): spin briefly before sleeping.
  for (int spin = 0; spin < 20000 && pending_.load(std::memory_order_acquire) != 0; ++spin) std::this_thread::yield();
  std::unique_lock lock(mutex_);
  done_.wait(lock, [this] { return pending_.load(std::memory_order_acquire) == 0; });
}

void WorkerPool::work(unsigned index) {
  std::uint64_t seen = 0;
  for (;;) {
    std::size_t n;
    Call call;
    void* fn;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      n = n_;
      call = call_;
      fn = fn_;
    }
    call(fn, begin_of(index, n), begin_of(index + 1, n));
    if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
      std::lock_guard lock(mutex_);
      done_.notify_one();
    }
  }
}

}  // namespace tire

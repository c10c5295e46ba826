#include "worker_pool.h"

#include <algorithm>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace tire {

namespace {

// How long a waiting worker stays awake before it sleeps: a step hands out a job every few tens of
// µs, and waking a sleeping thread costs about as much as such a job. Past these counts (a few
// hundred µs) it sleeps, so an idle pool between frames costs nothing.
constexpr int kSpinPauses = 4000;
constexpr int kSpinYields = 200;
// Chunks per thread: enough that one thread can take over another's share, few enough that
// claiming costs nothing next to a chunk of tires.
constexpr std::size_t kChunksPerThread = 4;

void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

std::uint32_t generation_of(std::uint64_t ticket) { return static_cast<std::uint32_t>(ticket >> 32); }

}  // namespace

WorkerPool::WorkerPool(unsigned threads) {
  for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this] { work(); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    stop_.store(true);
  }
  wake_.notify_all();
}

void WorkerPool::run_chunks(std::uint32_t generation) {
  const std::size_t n = n_.load(std::memory_order_relaxed);
  const std::uint32_t chunks = chunks_.load(std::memory_order_relaxed);
  const Call call = call_.load(std::memory_order_relaxed);
  void* const fn = fn_.load(std::memory_order_relaxed);
  std::uint64_t ticket = ticket_.load(std::memory_order_acquire);
  for (;;) {
    if (generation_of(ticket) != generation) return;  // a later job: these fields may be stale
    const auto chunk = static_cast<std::uint32_t>(ticket);
    if (chunk >= chunks) return;
    // Success proves the job is still this one, so the fields read above were its own.
    if (!ticket_.compare_exchange_weak(ticket, ticket + 1, std::memory_order_acq_rel)) continue;
    call(fn, n * chunk / chunks, n * (chunk + 1) / chunks);
    chunks_done_.fetch_add(1, std::memory_order_acq_rel);
    ticket = ticket_.load(std::memory_order_acquire);
  }
}

void WorkerPool::dispatch(std::size_t n, Call call, void* fn) {
  const auto chunks = static_cast<std::uint32_t>(std::min(n, threads() * kChunksPerThread));
  const std::uint32_t generation = generation_of(ticket_.load(std::memory_order_relaxed)) + 1;
  n_.store(n, std::memory_order_relaxed);
  chunks_.store(chunks, std::memory_order_relaxed);
  call_.store(call, std::memory_order_relaxed);
  fn_.store(fn, std::memory_order_relaxed);
  chunks_done_.store(0, std::memory_order_relaxed);
  // Publishes the job. Sequentially consistent with the load of sleeping_ below, as a worker's
  // increment of sleeping_ is with its load of ticket_: either it sees this job before it sleeps,
  // or this sees it asleep and wakes it.
  ticket_.store(std::uint64_t{generation} << 32);
  if (sleeping_.load() > 0) {
    std::lock_guard lock(mutex_);
    wake_.notify_all();
  }
  run_chunks(generation);
  // Every chunk is claimed; wait for those still running on other threads.
  for (int spin = 0; chunks_done_.load(std::memory_order_acquire) != chunks; ++spin) {
    if (spin < kSpinPauses) cpu_relax();
    else std::this_thread::yield();
  }
}

void WorkerPool::work() {
  std::uint32_t seen = 0;
  for (;;) {
    std::uint32_t generation = generation_of(ticket_.load(std::memory_order_acquire));
    for (int spin = 0; generation == seen && !stop_.load(std::memory_order_relaxed); ++spin) {
      if (spin < kSpinPauses) {
        cpu_relax();
      } else if (spin < kSpinPauses + kSpinYields) {
        std::this_thread::yield();
      } else {
        std::unique_lock lock(mutex_);
        sleeping_.fetch_add(1);
        wake_.wait(lock, [&] { return stop_.load() || generation_of(ticket_.load()) != seen; });
        sleeping_.fetch_sub(1);
        spin = 0;
      }
      generation = generation_of(ticket_.load(std::memory_order_acquire));
    }
    if (stop_.load()) return;
    seen = generation;
    run_chunks(generation);
  }
}

}  // namespace tire

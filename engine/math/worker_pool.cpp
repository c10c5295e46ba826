#include "tire/math/worker_pool.h"

#include <algorithm>
#include <system_error>

#include "tire/math/check.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace tire {

namespace {

// How long a thread that waits spins before it sleeps (on a futex, through std::atomic::wait).
// The phases of a step follow each other within microseconds, so a worker that spins a little
// catches the next one without a wake-up; past that it sleeps, and a machine busy with other
// programs gets the core back instead of watching it spin.
constexpr int kWorkerSpins = 1000;  // a few tens of µs of pause instructions
constexpr int kCallerSpins = 4000;  // the caller expects the others' last chunks soon
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
  // Where no thread can be started (a program built without threads, as in the browser, or a
  // system out of them), the pool keeps those it has: with none, every job runs on the caller.
  // Which thread runs a chunk never changes a result.
  try {
    for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this] { work(); });
  } catch (const std::system_error&) {
  }
}

WorkerPool::~WorkerPool() {
  stop_.store(true);
  generation_.fetch_add(1);
  generation_.notify_all();
  for (std::thread& t : workers_) t.join();
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
    // Success proves the job is still this one (a finished job's ticket is closed before the next
    // job's fields are written), so the fields read above were its own.
    if (!ticket_.compare_exchange_weak(ticket, ticket + 1, std::memory_order_acq_rel)) continue;
    call(fn, n * chunk / chunks, n * (chunk + 1) / chunks);
    // Sequentially consistent with the load of caller_waiting_, as the caller's store of it is with
    // its load of chunks_done_: either the caller sees this chunk done, or this sees it waiting.
    [[maybe_unused]] const std::uint32_t done_before = chunks_done_.fetch_add(1);
    // More chunks done than the job has is a chunk run twice (the caller would wait forever).
    TIRE_ASSERT(done_before < chunks, "a chunk of a job was run twice");
    if (caller_waiting_.load()) chunks_done_.notify_one();
    ticket = ticket_.load(std::memory_order_acquire);
  }
}

void WorkerPool::dispatch(std::size_t n, Call call, void* fn) {
  const auto chunks = static_cast<std::uint32_t>(std::min(n, threads() * kChunksPerThread));
  const std::uint32_t generation = generation_.load(std::memory_order_relaxed) + 1;
  TIRE_ASSERT(chunks >= 1 && chunks <= n && chunks < 0xFFFFFFFFu,
              "a job cut into no chunk, or more chunks than items");
  // The last job's ticket is closed (its generation, no chunk left to claim), or this is the first.
  TIRE_ASSERT(generation_of(ticket_.load()) == generation - 1 &&
                  (static_cast<std::uint32_t>(ticket_.load()) == 0xFFFFFFFFu || generation == 1),
              "a job published while the last one's ticket is still open");
  n_.store(n, std::memory_order_relaxed);
  chunks_.store(chunks, std::memory_order_relaxed);
  call_.store(call, std::memory_order_relaxed);
  fn_.store(fn, std::memory_order_relaxed);
  chunks_done_.store(0, std::memory_order_relaxed);
  ticket_.store(std::uint64_t{generation} << 32, std::memory_order_release);
  // Publishes the job. Sequentially consistent with the load of sleeping_, as a worker's increment
  // of sleeping_ is with its load of generation_: either it sees this job before it sleeps, or this
  // sees it asleep and wakes it.
  generation_.store(generation);
  if (sleeping_.load() > 0) generation_.notify_all();
  run_chunks(generation);
  // Every chunk is claimed; wait for those still running on other threads.
  for (int spin = 0;; ++spin) {
    std::uint32_t done = chunks_done_.load(std::memory_order_acquire);
    if (done == chunks) break;
    if (spin < kCallerSpins) {
      cpu_relax();
      continue;
    }
    caller_waiting_.store(true);
    done = chunks_done_.load();
    if (done != chunks) chunks_done_.wait(done);
    caller_waiting_.store(false, std::memory_order_relaxed);
  }
  TIRE_ASSERT(
      static_cast<std::uint32_t>(ticket_.load()) == chunks && generation_of(ticket_.load()) == generation,
      "a job finished with a chunk unclaimed, or with another job's ticket");
  // Closes the job before the next one's fields are written: a thread still on its way into this
  // job may read those fields, and must then find no chunk left to claim under this generation
  // (with the ticket left at `chunks`, a next job with more chunks would let it claim one).
  ticket_.store((std::uint64_t{generation} << 32) | 0xFFFFFFFFu, std::memory_order_release);
}

void WorkerPool::work() {
  std::uint32_t seen = 0;
  for (;;) {
    std::uint32_t generation = generation_.load(std::memory_order_acquire);
    for (int spin = 0; generation == seen && !stop_.load(std::memory_order_relaxed); ++spin) {
      if (spin < kWorkerSpins) {
        cpu_relax();
      } else {
        sleeping_.fetch_add(1);
        if (generation_.load() == seen && !stop_.load()) generation_.wait(seen);
        sleeping_.fetch_sub(1);
      }
      generation = generation_.load(std::memory_order_acquire);
    }
    if (stop_.load()) return;
    seen = generation;
    run_chunks(generation);
  }
}

}  // namespace tire

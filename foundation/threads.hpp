#pragma once
// Threads where the platform has them, one flow of control where it has not.
// The host renders rows and rasterizes lattices on every core; the firmware
// (GCC's "single" thread model, newlib, no OS: docs/firmware.md) has neither
// std::thread nor std::mutex. The core uses these names instead, so the same
// sources build for both, and a single-threaded build runs the same work in
// the same order the one-thread host run does (so the output is identical).
//
// Method: kHasThreads follows libstdc++'s _GLIBCXX_HAS_GTHREADS. runWorkers(n,
// work) calls work(0..n-1) at once, work(0) in the caller's thread (a worker
// thread would get an allocator arena of its own, resident long after), and
// rethrows the first exception any of them raised (one leaving a thread would
// end the process without a message); without threads it calls work(0) with
// n = 1. hardwareThreads() is 1 there.
#include <algorithm>
#include <exception>
#include <mutex>
#include <vector>
#if defined(__GLIBCXX__) && !defined(_GLIBCXX_HAS_GTHREADS)
#define LATTICE_HAS_THREADS 0
#else
#define LATTICE_HAS_THREADS 1
#include <thread>
#endif

namespace lattice {

inline constexpr bool kHasThreads = LATTICE_HAS_THREADS;

// Per-thread storage where there are threads; plain static storage where
// there is one flow of control (a bare-metal target has no thread pointer
// for thread_local to use).
#if LATTICE_HAS_THREADS
#define LATTICE_THREAD_LOCAL thread_local
#else
#define LATTICE_THREAD_LOCAL static
#endif

#if LATTICE_HAS_THREADS
using Mutex = std::mutex;
inline unsigned hardwareThreads() { return std::max(1u, std::thread::hardware_concurrency()); }
#else
// Nothing to exclude with one flow of control.
class Mutex {
 public:
  void lock() {}
  void unlock() {}
  bool try_lock() { return true; }
};
inline unsigned hardwareThreads() { return 1; }
#endif

// Calls work(w) for w in [0, workers) concurrently (one at a time without
// threads: then workers must be 1, the caller's resolved count). After the
// first exception, stop() is called so the other workers can finish early.
template <typename Work, typename Stop>
void runWorkers(unsigned workers, Work&& work, Stop&& stop) {
  if (workers <= 1 || !kHasThreads) {
    (void)stop;  // one worker: nothing to stop
    work(0u);
    return;
  }
#if LATTICE_HAS_THREADS
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto guarded = [&](unsigned w) {
    try {
      work(w);
    } catch (...) {
      std::lock_guard lock(failureMutex);
      if (!failure) failure = std::current_exception();
      stop();
    }
  };
  std::vector<std::jthread> pool;
  pool.reserve(workers - 1);
  for (unsigned w = 1; w < workers; ++w) pool.emplace_back(guarded, w);
  guarded(0);
  pool.clear();  // joins
  if (failure) std::rethrow_exception(failure);
#endif
}

}  // namespace lattice

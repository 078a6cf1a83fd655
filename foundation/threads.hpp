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
// n = 1. hardwareThreads() is 1 there. WorkerPool keeps its threads for its
// whole life, for work handed out again and again (the renderer's bands of
// rows): start(work) wakes them and returns, wait() waits and rethrows;
// without threads start() does the work in the caller at once.
#include <algorithm>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <utility>
#include <vector>
#if defined(__GLIBCXX__) && !defined(_GLIBCXX_HAS_GTHREADS)
#define LATTICE_HAS_THREADS 0
#else
#define LATTICE_HAS_THREADS 1
#include <condition_variable>
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

// Threads started once and given one job at a time: work(w) for w in
// [0, workers) on the pool's own threads (the caller is free meanwhile).
// start() must not be called again before wait() has returned.
class WorkerPool {
 public:
  using Work = std::function<void(unsigned)>;
  using Stop = std::function<void()>;

#if LATTICE_HAS_THREADS
  explicit WorkerPool(unsigned workers) : workers_(std::max(1u, workers)) {
    threads_.reserve(workers_);
    for (unsigned w = 0; w < workers_; ++w) threads_.emplace_back([this, w] { loop(w); });
  }
  ~WorkerPool() {
    {
      std::unique_lock lock(mutex_);
      done_.wait(lock, [&] { return running_ == 0; });
      quit_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
  }
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  unsigned workers() const { return workers_; }

  // After the first exception, stop() is called so the others finish early.
  void start(Work work, Stop stop) {
    {
      std::lock_guard lock(mutex_);
      work_ = std::move(work);
      stop_ = std::move(stop);
      failure_ = nullptr;
      running_ = workers_;
      ++generation_;
    }
    wake_.notify_all();
  }
  void wait() {
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return running_ == 0; });
    if (std::exception_ptr failure = std::exchange(failure_, nullptr)) std::rethrow_exception(failure);
  }

 private:
  void loop(unsigned w) {
    std::uint64_t seen = 0;
    for (;;) {
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return quit_ || generation_ != seen; });
        if (quit_) return;
        seen = generation_;
      }
      try {
        work_(w);  // work_ stays put until every worker has reported
      } catch (...) {
        std::lock_guard lock(mutex_);
        if (!failure_) failure_ = std::current_exception();
        if (stop_) stop_();
      }
      std::lock_guard lock(mutex_);
      if (--running_ == 0) done_.notify_all();
    }
  }

  unsigned workers_;
  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  Work work_;
  Stop stop_;
  std::exception_ptr failure_;
  std::uint64_t generation_ = 0;
  unsigned running_ = 0;
  bool quit_ = false;
#else
  // One flow of control: the work is done inside start().
  explicit WorkerPool(unsigned) {}
  unsigned workers() const { return 1; }
  void start(Work work, Stop) {
    try {
      work(0u);
    } catch (...) {
      failure_ = std::current_exception();
    }
  }
  void wait() {
    if (std::exception_ptr failure = std::exchange(failure_, nullptr)) std::rethrow_exception(failure);
  }

 private:
  std::exception_ptr failure_;
#endif
};

}  // namespace lattice

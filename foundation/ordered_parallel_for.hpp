#pragma once
// A loop over indices 0..n-1 spread over threads that fails as the plain loop
// would: the error it raises is the one of the lowest index that fails, so a
// scene with two bad objects names the same one at every thread count.
//
// Method: the indices are handed out in order from one counter (uneven items
// balance out; which thread runs an item never changes what it makes, as
// long as work(i) writes only item i's own slot). When item i fails, no
// index above i is handed out any more, but every index below it still is:
// the lowest failing index is then the one the plain loop stops at, and its
// exception is rethrown. Without threads (the firmware) this is the plain loop.
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>

#include "foundation/threads.hpp"

namespace lattice {

template <typename Work>
void orderedParallelFor(std::size_t n, unsigned threads, Work&& work) {
  if constexpr (kHasThreads) {
    if (threads > 1 && n > 1) {
      std::atomic<std::size_t> next{0};
      std::atomic<std::size_t> limit{n};  // no index at or above it is handed out
      Mutex failureMutex;  // threads.hpp's: the firmware has no std::mutex
      std::size_t failedAt = n;
      std::exception_ptr failure;
      runWorkers(
          static_cast<unsigned>(std::min<std::size_t>(threads, n)),
          [&](unsigned) {
            for (std::size_t i = next.fetch_add(1); i < limit.load(); i = next.fetch_add(1)) {
              try {
                work(i);
              } catch (...) {
                const std::lock_guard lock(failureMutex);
                if (i < failedAt) {
                  failedAt = i;
                  failure = std::current_exception();
                  limit.store(i);
                }
              }
            }
          },
          [] {});  // every failure is caught above
      if (failure) std::rethrow_exception(failure);
      return;
    }
  }
  for (std::size_t i = 0; i < n; ++i) work(i);
}

}  // namespace lattice

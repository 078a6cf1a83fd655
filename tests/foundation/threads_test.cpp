// foundation/threads.hpp: runWorkers and the WorkerPool the renderer keeps for
// its bands. Every worker index runs exactly once per job, on threads that
// live across jobs (the same thread ids every job), the caller is free while
// a job runs, a worker's exception reaches wait() and stops the others early,
// and the pool takes more jobs after one failed.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "foundation/threads.hpp"

using namespace lattice;

TEST_CASE("threads: runWorkers calls every worker once and rethrows the first error") {
  std::vector<std::atomic<int>> calls(4);
  runWorkers(4, [&](unsigned w) { ++calls[w]; }, [] {});
  for (const auto& c : calls) CHECK(c.load() == 1);
  CHECK_THROWS_AS(runWorkers(3, [](unsigned w) { if (w == 2) throw std::runtime_error("two"); }, [] {}),
                  std::runtime_error);
}

TEST_CASE("threads: a worker pool runs job after job on the same threads") {
  WorkerPool pool(3);
  REQUIRE(pool.workers() == 3);
  std::set<std::thread::id> firstIds;
  for (int job = 0; job < 200; ++job) {
    std::vector<std::atomic<int>> calls(3);
    std::vector<std::thread::id> ids(3);
    pool.start([&](unsigned w) { ++calls[w]; ids[w] = std::this_thread::get_id(); }, [] {});
    pool.wait();
    for (const auto& c : calls) REQUIRE(c.load() == 1);
    const std::set<std::thread::id> seen(ids.begin(), ids.end());
    REQUIRE(seen.size() == 3);  // three threads, none of them the caller
    REQUIRE(seen.count(std::this_thread::get_id()) == 0);
    if (job == 0) firstIds = seen;
    REQUIRE(seen == firstIds);  // kept, not started again
  }
}

TEST_CASE("threads: the caller works while a pool job runs, and errors reach wait() and stop the rest") {
  WorkerPool pool(2);
  std::atomic<bool> release{false};
  std::atomic<int> released{0};
  pool.start(
      [&](unsigned) {
        // Waits for the caller, for 5 s at most (a start() that ran the job
        // itself would time out here and fail below, not hang).
        const auto giveUp = std::chrono::steady_clock::now() + std::chrono::seconds(5);
        while (!release.load() && std::chrono::steady_clock::now() < giveUp) std::this_thread::yield();
        if (release.load()) ++released;
      },
      [] {});
  release = true;  // start() returned while both workers wait for this
  pool.wait();
  CHECK(released.load() == 2);

  std::atomic<int> next{0};
  std::atomic<int> items{0};
  const int limit = 1 << 30;
  pool.start(
      [&](unsigned) {
        for (int i = next.fetch_add(1); i < limit; i = next.fetch_add(1)) {
          if (i == 10) throw std::runtime_error("item 10");
          ++items;
        }
      },
      [&] { next.store(limit); });
  CHECK_THROWS_WITH(pool.wait(), "item 10");
  CHECK(items.load() < 1000000);  // stopped early, not run to the end
  // The pool still works after a failed job.
  std::atomic<int> again{0};
  pool.start([&](unsigned) { ++again; }, [] {});
  pool.wait();
  CHECK(again.load() == 2);
}

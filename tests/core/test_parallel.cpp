// The persistent worker pool behind parallel_items: every item once, worker indices in range, threads
// started once for many casts, nested and concurrent casts still complete.
#include <atomic>
#include <catch2/catch.hpp>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "raycam/parallel.h"

using namespace raycam::detail;

TEST_CASE("parallel_items runs every item once, on workers in range", "[parallel]") {
  for (int workers : {1, 2, 3, 8})
    for (int items : {0, 1, 2, 7, 1000}) {
      std::vector<std::atomic<int>> runs(std::size_t(items) + 1);
      std::atomic<int> bad_worker{0};
      parallel_items(items, workers, [&](int worker, int item) {
        if (worker < 0 || worker >= std::max(1, std::min(workers, items))) ++bad_worker;
        ++runs[std::size_t(item)];
      });
      for (int i = 0; i < items; ++i) CHECK(runs[std::size_t(i)] == 1);
      CHECK(bad_worker == 0);
    }
}

TEST_CASE("the pool's threads are started once, not per cast", "[parallel]") {
  parallel_items(64, 3, [](int, int) {});
  const int started = pool_threads_started();
  CHECK(started >= 2);  // three workers: the caller and two helpers
  std::set<std::thread::id> seen;
  std::mutex seen_mutex;
  for (int cast = 0; cast < 200; ++cast)
    parallel_items(64, 3, [&](int, int) {
      std::lock_guard<std::mutex> lock(seen_mutex);
      seen.insert(std::this_thread::get_id());
    });
  CHECK(pool_threads_started() == started);
  CHECK(seen.size() <= std::size_t(started) + 1);  // the same threads served all 200 casts
}

TEST_CASE("a cast nested in a work item, and casts from two threads at once, complete", "[parallel]") {
  std::atomic<int> inner{0};
  parallel_items(8, 2, [&](int, int) { parallel_items(10, 2, [&](int, int) { ++inner; }); });
  CHECK(inner == 80);
  std::atomic<long long> total{0};
  auto caster = [&] {
    for (int cast = 0; cast < 50; ++cast) parallel_items(100, 2, [&](int, int item) { total += item; });
  };
  std::thread other(caster);
  caster();
  other.join();
  CHECK(total == 2LL * 50 * (99 * 100 / 2));
}

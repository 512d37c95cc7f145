// Work sharing for the casters: items (bands of rows, chunks of objects) handed out through one atomic
// counter, so a band that is all background costs its thread nothing and the other picks up the rest.
// No shared mutable state beyond the counter: each worker writes its own items and its own scratch.
#pragma once

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace raycam::detail {

// 0 means every hardware thread.
inline int resolve_threads(int requested) {
  if (requested > 0) return requested;
  return std::max(1, int(std::thread::hardware_concurrency()));
}

// Calls work(worker, item) for every item in [0, items), worker in [0, workers). Runs inline when one
// worker suffices (starting a thread costs tens of microseconds: more than a small cast).
template <class Work>
void parallel_items(int items, int workers, Work&& work) {
  workers = std::max(1, std::min(workers, items));
  if (workers == 1) {
    for (int item = 0; item < items; ++item) work(0, item);
    return;
  }
  std::atomic<int> next{0};
  auto loop = [&](int worker) {
    for (int item = next++; item < items; item = next++) work(worker, item);
  };
  std::vector<std::thread> helpers;
  for (int worker = 1; worker < workers; ++worker) helpers.emplace_back(loop, worker);
  loop(0);
  for (std::thread& helper : helpers) helper.join();
}

}  // namespace raycam::detail

// Work sharing for the casters and the benchmarks: items (bands of rows, chunks of objects) handed out
// through one atomic counter, so a band that is all background costs its thread nothing and the others
// pick up the rest. The threads are a persistent pool, started once per process on first use and parked
// between casts: a cast pays a wake-up (microseconds), not a thread start (tens of microseconds each).
// No shared mutable state beyond the counter: each worker writes its own items and its own scratch.
#pragma once

#include <algorithm>
#include <thread>

namespace raycam::detail {

// 0 means every hardware thread.
inline int resolve_threads(int requested) {
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
  (void)requested;
  return 1;  // the web page is built without threads: every cast runs on the calling thread
#endif
  if (requested > 0) return requested;
  return std::max(1, int(std::thread::hardware_concurrency()));
}

// Runs body(context, worker, item) for every item in [0, items) on `workers` threads of the process's pool
// (the calling thread is worker 0). Another cast already using the pool (another thread's, or one nested in
// a work item) runs inline on its calling thread instead: the result is the same, only slower.
void run_on_pool(int items, int workers, void (*body)(void* context, int worker, int item), void* context);

// Threads the pool has started since the process began (its helpers; the caller is never one).
int pool_threads_started();

// Calls work(worker, item) for every item in [0, items), worker in [0, workers). Runs inline when one
// worker suffices.
template <class Work>
void parallel_items(int items, int workers, Work&& work) {
  workers = std::max(1, std::min(workers, items));
  if (workers == 1) {
    for (int item = 0; item < items; ++item) work(0, item);
    return;
  }
  using WorkType = std::remove_reference_t<Work>;
  run_on_pool(
      items, workers,
      [](void* context, int worker, int item) { (*static_cast<WorkType*>(context))(worker, item); },
      const_cast<void*>(static_cast<const void*>(&work)));
}

}  // namespace raycam::detail

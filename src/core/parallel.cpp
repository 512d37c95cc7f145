// The persistent worker pool behind detail::parallel_items (raycam/parallel.h).
//
// One job at a time: the caller publishes it (body, items, how many workers) under the mutex, bumps the
// generation and wakes the helpers; helper i (1…) takes part when i < workers, pulling items from the
// shared counter; the caller works as worker 0 and then waits until every helper that took part is done.
// Helpers are started on demand, up to the largest worker count ever asked for, and live until exit.
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "raycam/parallel.h"

namespace raycam::detail {

namespace {

thread_local bool in_pool_job = false;  // a work item that casts again runs that cast inline

class WorkerPool {
 public:
  ~WorkerPool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& helper : helpers_) helper.join();
  }

  // False when the pool is busy with another job: the caller then runs the job itself.
  int started() {
    std::lock_guard<std::mutex> lock(mutex_);
    return int(helpers_.size());
  }

  bool try_run(int items, int workers, void (*body)(void*, int, int), void* context) {
    std::unique_lock<std::mutex> busy(job_mutex_, std::try_to_lock);
    if (!busy.owns_lock()) return false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      while (int(helpers_.size()) < workers - 1) {
        const int index = int(helpers_.size()) + 1;
        helpers_.emplace_back([this, index] { helper_loop(index); });
      }
      body_ = body;
      context_ = context;
      items_ = items;
      workers_ = workers;
      next_.store(0, std::memory_order_relaxed);
      pending_ = workers - 1;
      ++generation_;
    }
    wake_.notify_all();
    std::exception_ptr error;
    try {
      work(0);
    } catch (...) {  // let the helpers finish with the caller's context before it goes
      error = std::current_exception();
      next_.store(items_);
    }
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    if (error) std::rethrow_exception(error);
    return true;
  }

 private:
  void work(int worker) {
    in_pool_job = true;
    struct Leave {
      ~Leave() { in_pool_job = false; }
    } leave;
    for (int item = next_.fetch_add(1); item < items_; item = next_.fetch_add(1))
      body_(context_, worker, item);
  }

  void helper_loop(int index) {
    unsigned long long seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      if (index >= workers_) continue;  // this job wants fewer workers
      lock.unlock();
      work(index);
      lock.lock();
      if (--pending_ == 0) done_.notify_one();
    }
  }

  std::mutex job_mutex_;  // held by the caller for the whole job
  std::mutex mutex_;      // guards what follows but the counter
  std::condition_variable wake_, done_;
  std::vector<std::thread> helpers_;
  unsigned long long generation_ = 0;
  void (*body_)(void*, int, int) = nullptr;
  void* context_ = nullptr;
  int items_ = 0, workers_ = 0, pending_ = 0;
  bool stopping_ = false;
  std::atomic<int> next_{0};
};

WorkerPool& pool() {
  static WorkerPool shared;
  return shared;
}

}  // namespace

int pool_threads_started() { return pool().started(); }

void run_on_pool(int items, int workers, void (*body)(void*, int, int), void* context) {
  if (!in_pool_job && pool().try_run(items, workers, body, context)) return;
  for (int item = 0; item < items; ++item) body(context, 0, item);
}

}  // namespace raycam::detail

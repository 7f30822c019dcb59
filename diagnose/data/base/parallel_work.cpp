// SPDX-License-Identifier: MIT
#include "parallel_work.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace flange::diagnose {
namespace {

// The worker threads not in use. The thread that starts the process holds one from the start;
// a helper takes one when it starts and gives it back when it ends.
class ThreadBudget {
 public:
  static ThreadBudget& process() {
    static ThreadBudget budget;
    return budget;
  }

  void set(int threads) {
    const std::lock_guard<std::mutex> lock(mutex_);
    free_ += threads - threads_;
    threads_ = threads;
  }
  int threads() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return threads_;
  }
  bool try_take() {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (free_ <= 0) return false;
    --free_;
    return true;
  }
  // Waits until a thread is free (a thread resuming after it gave its place back to helpers).
  void take() {
    std::unique_lock<std::mutex> lock(mutex_);
    freed_.wait(lock, [&] { return free_ > 0; });
    --free_;
  }
  void give_back() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      ++free_;
    }
    freed_.notify_one();
  }

 private:
  ThreadBudget()
      : threads_(std::max(1, static_cast<int>(std::thread::hardware_concurrency()))),
        free_(threads_ - 1) {}
  std::mutex mutex_;
  std::condition_variable freed_;
  int threads_;
  int free_;
};

// One call of run_in_parallel: the pieces left to claim and the helpers taken on for them.
class Pieces {
 public:
  Pieces(int count, int most_threads, const std::function<void(int)>& work)
      : count_(count), most_threads_(most_threads), work_(work) {}

  // Claims and runs pieces until none is left, taking on a helper before each piece while a
  // thread is free and more pieces are left than threads run them.
  void work_through() {
    for (int i = next_++; i < count_; i = next_++) {
      take_on_helper_if_free(count_ - i - 1);
      try {
        work_(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (!failure_) failure_ = std::current_exception();
      }
    }
  }

  // Waits for every helper, its own place given back meanwhile; then rethrows the first failure.
  void finish() {
    const bool had_helpers = !helpers_empty();
    if (had_helpers) ThreadBudget::process().give_back();
    for (;;) {
      std::thread helper;
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (helpers_.empty()) break;
        helper = std::move(helpers_.back());
        helpers_.pop_back();
      }
      helper.join();
    }
    if (had_helpers) ThreadBudget::process().take();
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  bool helpers_empty() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return helpers_.empty();
  }

  void take_on_helper_if_free(int pieces_left) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (pieces_left <= running_ - 1 || running_ >= most_threads_) return;
    if (!ThreadBudget::process().try_take()) return;
    ++running_;
    helpers_.emplace_back([this] {
      work_through();
      ThreadBudget::process().give_back();
    });
  }

  const int count_;
  const int most_threads_;
  const std::function<void(int)>& work_;
  std::atomic<int> next_{0};
  std::mutex mutex_;
  int running_ = 1;  // the calling thread and the helpers taken on
  std::vector<std::thread> helpers_;
  std::exception_ptr failure_;
};

}  // namespace

void set_worker_threads(int threads) { ThreadBudget::process().set(std::clamp(threads, 1, 64)); }

int worker_threads() { return ThreadBudget::process().threads(); }

void run_in_parallel(int count, int jobs, const std::function<void(int)>& work) {
  if (count <= 0) return;
  Pieces pieces(count, jobs > 0 ? jobs : count, work);
  pieces.work_through();
  pieces.finish();
}

void run_both(const std::function<void()>& first, const std::function<void()>& second) {
  run_in_parallel(2, 0, [&](int i) { i == 0 ? first() : second(); });
}

}  // namespace flange::diagnose

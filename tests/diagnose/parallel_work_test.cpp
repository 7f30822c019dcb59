// SPDX-License-Identifier: MIT
// The diagnosis's pool (diagnose/data/base/parallel_work.h): results in index order whatever
// order the threads finish in, every piece run once, a failure rethrown after all stop, one
// worker thread running everything on the calling thread, and nested work sharing the budget.
#include "parallel_work.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "worker_threads_guard.h"

namespace flange::diagnose {
namespace {

TEST(ParallelWork, MapKeepsIndexOrderWhateverOrderPiecesFinishIn) {
  // Early pieces take longest, so later ones finish first on the other threads.
  const std::vector<long> squares = parallel_map<long>(12, [](std::size_t i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2 * (12 - static_cast<int>(i))));
    return static_cast<long>(i * i);
  });
  ASSERT_EQ(squares.size(), 12u);
  for (std::size_t i = 0; i < squares.size(); ++i) EXPECT_EQ(squares[i], static_cast<long>(i * i));
}

TEST(ParallelWork, EveryPieceRunsOnceOnAnyNumberOfThreads) {
  for (const int jobs : {1, 2, 5}) {
    std::vector<std::atomic<int>> runs(40);
    run_in_parallel(40, jobs, [&](int i) { ++runs[static_cast<std::size_t>(i)]; });
    for (const std::atomic<int>& r : runs) EXPECT_EQ(r.load(), 1) << jobs << " threads";
  }
}

TEST(ParallelWork, AFailureIsRethrownOnceAllPiecesStop) {
  std::atomic<int> finished{0};
  EXPECT_THROW(run_in_parallel(8, 2,
                               [&](int i) {
                                 if (i == 3) throw std::runtime_error("piece 3");
                                 ++finished;
                               }),
               std::runtime_error);
  EXPECT_EQ(finished.load(), 7);
}

using testing::WorkerThreads;

// How many pieces run at once, at most, over a run.
class InFlight {
 public:
  void enter() {
    const std::lock_guard<std::mutex> lock(mutex_);
    most_ = std::max(most_, ++now_);
  }
  void leave() {
    const std::lock_guard<std::mutex> lock(mutex_);
    --now_;
  }
  int most() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return most_;
  }

 private:
  std::mutex mutex_;
  int now_ = 0, most_ = 0;
};

TEST(ParallelWork, OneWorkerThreadRunsEverythingOnTheCallingThread) {
  const WorkerThreads one(1);
  std::mutex mutex;
  std::set<std::thread::id> threads;
  const auto note_thread = [&] {
    const std::lock_guard<std::mutex> lock(mutex);
    threads.insert(std::this_thread::get_id());
  };
  run_in_parallel(6, 0, [&](int) {
    note_thread();
    run_in_parallel(4, 0, [&](int) { note_thread(); });
  });
  run_both(note_thread, note_thread);
  EXPECT_EQ(threads, std::set<std::thread::id>{std::this_thread::get_id()});
}

TEST(ParallelWork, AJobsOfOneKeepsACallOnTheCallingThread) {
  const WorkerThreads four(4);
  std::mutex mutex;
  std::set<std::thread::id> threads;
  run_in_parallel(8, 1, [&](int) {
    const std::lock_guard<std::mutex> lock(mutex);
    threads.insert(std::this_thread::get_id());
  });
  EXPECT_EQ(threads, std::set<std::thread::id>{std::this_thread::get_id()});
}

TEST(ParallelWork, NestedWorkSharesTheBudgetRatherThanMultiplyingIt) {
  const WorkerThreads two(2);
  InFlight inner;
  std::vector<std::vector<int>> squares(4);
  run_in_parallel(4, 0, [&](int i) {
    squares[static_cast<std::size_t>(i)] = parallel_map<int>(5, [&](std::size_t j) {
      inner.enter();
      std::this_thread::sleep_for(std::chrono::milliseconds(3));
      inner.leave();
      return static_cast<int>(j * j);
    });
  });
  EXPECT_LE(inner.most(), 2);
  for (const std::vector<int>& of_piece : squares)
    EXPECT_EQ(of_piece, (std::vector<int>{0, 1, 4, 9, 16}));
}

TEST(ParallelWork, AThreadWaitingForItsHelpersLendsItsPlace) {
  // The first of two pieces ends at once; the second's own pieces then find a thread free.
  const WorkerThreads two(2);
  InFlight inner;
  run_both([] { std::this_thread::sleep_for(std::chrono::milliseconds(1)); },
           [&] {
             run_in_parallel(8, 0, [&](int) {
               inner.enter();
               std::this_thread::sleep_for(std::chrono::milliseconds(40));
               inner.leave();
             });
           });
  EXPECT_EQ(inner.most(), 2);
}

TEST(ParallelWork, AFailureInNestedWorkReachesTheOuterCaller) {
  const WorkerThreads two(2);
  EXPECT_THROW(run_in_parallel(3, 0,
                               [&](int i) {
                                 run_in_parallel(3, 0, [&](int j) {
                                   if (i == 1 && j == 2) throw std::runtime_error("1.2");
                                 });
                               }),
               std::runtime_error);
  // The budget is whole again: two pieces still run at once.
  InFlight after;
  run_in_parallel(6, 0, [&](int) {
    after.enter();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    after.leave();
  });
  EXPECT_EQ(after.most(), 2);
}

TEST(ParallelWork, NothingToDoRunsNothing) {
  EXPECT_TRUE(parallel_map<int>(0, [](std::size_t) { return 1; }).empty());
}

}  // namespace
}  // namespace flange::diagnose

// SPDX-License-Identifier: MIT
// The diagnosis's pool (diagnose/data/base/parallel_work.h): results in index order whatever
// order the threads finish in, every piece run once, and a failure rethrown after all stop.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "parallel_work.h"

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

TEST(ParallelWork, NothingToDoRunsNothing) {
  EXPECT_TRUE(parallel_map<int>(0, [](std::size_t) { return 1; }).empty());
}

}  // namespace
}  // namespace flange::diagnose

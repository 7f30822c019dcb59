// SPDX-License-Identifier: MIT
// Pieces claimed longest first (diagnose/data/base/longest_first.h): kinds never timed in index
// order, then the longest of the last run first; the results in index order whatever the claims.
#include "longest_first.h"

#include <gtest/gtest.h>

#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "worker_threads_guard.h"

namespace flange::diagnose {
namespace {

using testing::WorkerThreads;

TEST(LongestFirst, KindsNeverTimedComeFirstInIndexOrderThenTheLongest) {
  note_piece_seconds("longest_first_test a", 0.1);
  note_piece_seconds("longest_first_test b", 0.3);
  note_piece_seconds("longest_first_test c", 0.2);
  const std::vector<std::size_t> order =
      longest_first({"longest_first_test a", "longest_first_test new 1", "longest_first_test b",
                     "longest_first_test c", "longest_first_test new 2", "longest_first_test a"});
  EXPECT_EQ(order, (std::vector<std::size_t>{1, 4, 2, 3, 0, 5}));
}

TEST(LongestFirst, AKindNeverTimedTakesTheTimeOfTheKindItIsLike) {
  note_piece_seconds("longest_first_test screen x", 0.5);
  note_piece_seconds("longest_first_test screen y", 0.1);
  note_piece_seconds("longest_first_test refit z", 0.3);
  const std::vector<std::size_t> order = longest_first(
      {"longest_first_test refit y", "longest_first_test refit z", "longest_first_test refit x",
       "longest_first_test refit w"},
      {"longest_first_test screen y", "longest_first_test screen x", "longest_first_test screen x",
       ""});
  // y: 0.1 (its screen), z: 0.3 (its own time, not x's screen), x: 0.5 (its screen), w: unknown.
  EXPECT_EQ(order, (std::vector<std::size_t>{3, 2, 1, 0}));
}

TEST(LongestFirst, TheNextMapClaimsThePieceThatTookLongestFirst) {
  const WorkerThreads one(1);  // one thread: the claims are the order the pieces run in
  const std::vector<std::string> kinds = {"longest_first_test quick", "longest_first_test slow",
                                          "longest_first_test middling"};
  const std::vector<int> sleep_ms = {0, 30, 10};
  for (const std::vector<std::size_t>& expected :
       {std::vector<std::size_t>{0, 1, 2}, std::vector<std::size_t>{1, 2, 0}}) {
    std::vector<std::size_t> ran;
    const std::vector<std::size_t> squares =
        parallel_map_longest_first<std::size_t>(kinds, [&](std::size_t i) {
          std::this_thread::sleep_for(std::chrono::milliseconds(sleep_ms[i]));
          ran.push_back(i);
          return i * i;
        });
    EXPECT_EQ(ran, expected);
    EXPECT_EQ(squares, (std::vector<std::size_t>{0, 1, 4}));
  }
}

TEST(LongestFirst, ResultsKeepIndexOrderOnSeveralThreads) {
  const WorkerThreads three(3);
  std::vector<std::string> kinds;
  for (int i = 0; i < 12; ++i) kinds.push_back("longest_first_test piece " + std::to_string(i));
  for (int run = 0; run < 2; ++run) {
    const std::vector<long> squares = parallel_map_longest_first<long>(kinds, [](std::size_t i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(static_cast<int>(i % 4)));
      return static_cast<long>(i * i);
    });
    for (std::size_t i = 0; i < squares.size(); ++i) EXPECT_EQ(squares[i], static_cast<long>(i * i));
  }
}

}  // namespace
}  // namespace flange::diagnose

// SPDX-License-Identifier: MIT
#include "longest_first.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>

namespace flange::diagnose {
namespace {

class PieceSeconds {
 public:
  static PieceSeconds& process() {
    static PieceSeconds seconds;
    return seconds;
  }
  void note(const std::string& kind, double seconds) {
    const std::lock_guard<std::mutex> lock(mutex_);
    last_[kind] = seconds;
  }
  // The kind's last time, or +infinity when none ran yet.
  double of(const std::string& kind) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto found = last_.find(kind);
    return found == last_.end() ? std::numeric_limits<double>::infinity() : found->second;
  }

 private:
  std::mutex mutex_;
  std::map<std::string, double> last_;
};

}  // namespace

void note_piece_seconds(const std::string& kind, double seconds) {
  PieceSeconds::process().note(kind, seconds);
}

std::vector<std::size_t> longest_first(const std::vector<std::string>& kinds,
                                       const std::vector<std::string>& like) {
  std::vector<double> seconds;
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    double last = PieceSeconds::process().of(kinds[i]);
    if (std::isinf(last) && i < like.size() && !like[i].empty()) {
      last = PieceSeconds::process().of(like[i]);
    }
    seconds.push_back(last);
  }
  std::vector<std::size_t> order(kinds.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return seconds[a] > seconds[b]; });
  return order;
}

void run_longest_first(const std::vector<std::string>& kinds, const std::vector<std::string>& like,
                       const std::function<void(std::size_t)>& work) {
  const std::vector<std::size_t> order = longest_first(kinds, like);
  run_in_parallel(static_cast<int>(order.size()), 0, [&](int claimed) {
    const std::size_t i = order[static_cast<std::size_t>(claimed)];
    const auto start = std::chrono::steady_clock::now();
    work(i);
    note_piece_seconds(kinds[i], std::chrono::duration<double>(
                                     std::chrono::steady_clock::now() - start).count());
  });
}

}  // namespace flange::diagnose

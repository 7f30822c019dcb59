// SPDX-License-Identifier: MIT
#include "block_resamples.h"

#include <algorithm>
#include <random>

namespace flange::diagnose {

BlockResamples::BlockResamples(std::size_t n, int rounds, std::uint64_t seed) : n_(n) {
  const std::size_t block = std::max<std::size_t>(32, n / 20);
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<std::size_t> start(0, n > block ? n - block : 0);
  resamples_.resize(static_cast<std::size_t>(std::max(rounds, 0)));
  for (std::vector<Block>& blocks : resamples_) {
    std::size_t taken = 0;
    while (taken < n) {
      const std::size_t s = start(random);
      const std::size_t length = std::min({block, n - s, n - taken});
      blocks.push_back({s, length});
      taken += length;
    }
  }
}

std::vector<std::size_t> BlockResamples::indices(std::size_t r) const {
  std::vector<std::size_t> set;
  set.reserve(n_);
  for (const Block& b : resamples_[r]) {
    for (std::size_t i = b.start; i < b.start + b.length; ++i) set.push_back(i);
  }
  return set;
}

std::vector<double> BlockResamples::mean_squares(const std::vector<double>& e) const {
  std::vector<double> running(e.size() + 1, 0.0);  // running[i]: the sum of e^2 before i
  for (std::size_t i = 0; i < e.size(); ++i) running[i + 1] = running[i] + e[i] * e[i];
  std::vector<double> means;
  means.reserve(resamples_.size());
  for (const std::vector<Block>& blocks : resamples_) {
    double sum = 0.0;
    for (const Block& b : blocks) sum += running[b.start + b.length] - running[b.start];
    means.push_back(n_ == 0 ? 0.0 : sum / static_cast<double>(n_));
  }
  return means;
}

}  // namespace flange::diagnose

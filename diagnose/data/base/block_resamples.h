// SPDX-License-Identifier: MIT
// Block-bootstrap resamples of a series: each is as many values as the series holds, taken as
// blocks of consecutive ones (the gap's slow correlation stays inside a block) at random starts,
// with replacement. A resample is kept as its blocks, not its indices: the held-out selection
// scores every candidate's mean square on every resample of a 270,000-row part, which index sets
// made a 200 MB copy per selection and a pass over every index per score; from the blocks and a
// running sum of squares, a score costs one subtraction per block.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace flange::diagnose {

class BlockResamples {
 public:
  BlockResamples() = default;
  // `rounds` resamples of a series of `n` values, in blocks of max(32, n / 20) drawn from
  // std::mt19937_64(seed); the last block of a resample is cut where it reaches n values.
  BlockResamples(std::size_t n, int rounds, std::uint64_t seed);

  std::size_t size() const { return resamples_.size(); }
  bool empty() const { return resamples_.empty(); }
  // The indices resample `r` takes, in order (for statistics other than a mean square).
  std::vector<std::size_t> indices(std::size_t r) const;
  // The mean square of `e` (n values) on each resample.
  std::vector<double> mean_squares(const std::vector<double>& e) const;

 private:
  struct Block {
    std::size_t start, length;
  };
  std::size_t n_ = 0;
  std::vector<std::vector<Block>> resamples_;
};

}  // namespace flange::diagnose

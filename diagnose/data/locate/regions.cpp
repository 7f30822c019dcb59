// SPDX-License-Identifier: MIT
#include "regions.h"

#include <algorithm>

#include "block_resamples.h"
#include "series_statistics.h"
#include "series_arithmetic.h"

namespace flange::diagnose {

int RegionGrid::cell(double c, double t) const {
  const int ci = std::clamp(static_cast<int>((c - c_lo) / c_step), 0, kClearanceCells - 1);
  const int ti = std::clamp(static_cast<int>((t - t_lo) / t_step), 0, kTempCells - 1);
  return ti * kClearanceCells + ci;
}

RegionGrid region_grid_for(const RecordingSeries& s) {
  const auto [c_min, c_max] = std::minmax_element(s.clearance_mm.begin(), s.clearance_mm.end());
  const auto [t_min, t_max] = std::minmax_element(s.temp_c.begin(), s.temp_c.end());
  return {*c_min, std::max(*c_max - *c_min, 1e-9) / kClearanceCells, *t_min,
          std::max(*t_max - *t_min, 1e-9) / kTempCells};
}

std::vector<RegionCell> region_cells(const RecordingSeries& s, const std::vector<double>& gap,
                                     const RegionGrid& grid, int rounds, std::uint64_t seed) {
  std::vector<std::vector<std::size_t>> members(kClearanceCells * kTempCells);
  for (std::size_t i = 0; i < s.size(); ++i) {
    members[static_cast<std::size_t>(grid.cell(s.clearance_mm[i], s.temp_c[i]))].push_back(i);
  }
  std::vector<RegionCell> cells;
  for (int k = 0; k < kClearanceCells * kTempCells; ++k) {
    const int ci = k % kClearanceCells, ti = k / kClearanceCells;
    RegionCell cell;
    cell.clearance_lo = grid.c_lo + ci * grid.c_step;
    cell.clearance_hi = cell.clearance_lo + grid.c_step;
    cell.temp_lo = grid.t_lo + ti * grid.t_step;
    cell.temp_hi = cell.temp_lo + grid.t_step;
    const auto& idx = members[static_cast<std::size_t>(k)];
    cell.n = idx.size();
    if (!idx.empty()) {
      std::vector<double> values;
      for (std::size_t i : idx) values.push_back(gap[i]);
      cell.bias_v = mean_of(values);
      cell.rms_v = rms_of(values);
      // Blocks of consecutive in-cell samples keep the gap's slow correlation in the interval.
      std::vector<double> biases, rmss;
      const BlockResamples resamples(values.size(), rounds, seed + static_cast<unsigned>(k));
      for (std::size_t r = 0; r < resamples.size(); ++r) {
        std::vector<double> drawn;
        for (std::size_t i : resamples.indices(r)) drawn.push_back(values[i]);
        biases.push_back(mean_of(drawn));
        rmss.push_back(rms_of(drawn));
      }
      cell.bias_lo = quantile(biases, 0.025);
      cell.bias_hi = quantile(biases, 0.975);
      cell.rms_lo = quantile(rmss, 0.025);
      cell.rms_hi = quantile(rmss, 0.975);
    }
    cells.push_back(cell);
  }
  return cells;
}

std::vector<std::size_t> samples_in(const RecordingSeries& s, const RegionCell& cell) {
  std::vector<std::size_t> in;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.clearance_mm[i] >= cell.clearance_lo && s.clearance_mm[i] <= cell.clearance_hi &&
        s.temp_c[i] >= cell.temp_lo && s.temp_c[i] <= cell.temp_hi) {
      in.push_back(i);
    }
  }
  return in;
}

}  // namespace flange::diagnose

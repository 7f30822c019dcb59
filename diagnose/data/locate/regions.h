// SPDX-License-Identifier: MIT
// The operating region where a gap lies: the calibration part split into clearance x
// temperature cells, each with its gap's bias and RMS and their block-bootstrap intervals.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "findings.h"
#include "recording_series.h"

namespace flange::diagnose {

inline constexpr int kClearanceCells = 5, kTempCells = 4;

// Cells of equal width over a series' clearance and temperature ranges.
struct RegionGrid {
  double c_lo, c_step, t_lo, t_step;
  int cell(double c, double t) const;  // ti * kClearanceCells + ci, clamped to the grid
};

RegionGrid region_grid_for(const RecordingSeries& s);

// The samples of `s` (another part, say) that lie in `cell`, in order.
std::vector<std::size_t> samples_in(const RecordingSeries& s, const RegionCell& cell);

// The cells of `grid` with the bias and RMS of `gap` in each, and 95 % intervals from `rounds`
// resamples of blocks of consecutive in-cell samples (which keep the gap's slow correlation).
std::vector<RegionCell> region_cells(const RecordingSeries& s, const std::vector<double>& gap,
                                     const RegionGrid& grid, int rounds, std::uint64_t seed);

}  // namespace flange::diagnose

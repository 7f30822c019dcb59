// SPDX-License-Identifier: MIT
#include "parts.h"

#include <optional>

#include "parallel_work.h"
#include "shared_grid.h"

namespace flange::diagnose {

Parts replay_parts(const RecordingSeries& calibration, const RecordingSeries& heldout,
                   const DiagnoseOptions& options, double age_offset_s, bool heldout_age_unknown) {
  // The two replays and the grid at once, as far as worker threads are free.
  std::optional<TwinReplay> cal_replay, ho_replay;
  std::optional<AdcGrid> grid;
  run_in_parallel(3, 0, [&](int piece) {
    if (piece == 0) cal_replay.emplace(calibration, options.twin.nominal);
    if (piece == 1) ho_replay.emplace(heldout, options.twin.nominal, age_offset_s);
    if (piece == 2) grid = shared_grid(calibration, heldout);
  });
  return Parts{calibration,         heldout,        std::move(*cal_replay), std::move(*ho_replay),
               heldout_age_unknown, std::move(grid)};
}

}  // namespace flange::diagnose

// SPDX-License-Identifier: MIT
#include "parts.h"

#include <future>

#include "shared_grid.h"

namespace flange::diagnose {

Parts replay_parts(const RecordingSeries& calibration, const RecordingSeries& heldout,
                   const DiagnoseOptions& options, double age_offset_s, bool heldout_age_unknown) {
  auto ho_replay = std::async(std::launch::async, [&] {
    return TwinReplay(heldout, options.twin.nominal, age_offset_s);
  });
  auto grid = std::async(std::launch::async, [&] { return shared_grid(calibration, heldout); });
  return Parts{calibration,
               heldout,
               TwinReplay(calibration, options.twin.nominal),
               ho_replay.get(),
               heldout_age_unknown,
               grid.get()};
}

}  // namespace flange::diagnose

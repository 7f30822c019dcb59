// SPDX-License-Identifier: MIT
#include "heldout_age.h"

#include <fmt/format.h>

#include "grid_search.h"
#include "ridge_solve.h"
#include "sensor_age.h"

namespace flange::diagnose::free_shapes {

// One sensor records one session at a time, so the held-out session lies wholly after the
// calibration session or wholly before it. A shift that overlapped them would replay the
// calibration session's own ages, and a curve of age could then follow anything that happens at
// the same time into each session (a gain step halfway through each would be matched by a wavy
// curve of age with the held-out session placed a minute before the calibration one): the shifts
// tried start a minute clear of the calibration session and grow by a quarter each time.
void place_heldout_age(const LinearFamily& shape, const Eigen::VectorXd& beta,
                       const RecordingSeries& calibration, const RecordedPart& heldout,
                       const std::vector<double>& ho_gap_v, FreeShapeFit& fit) {
  const double session_s = calibration.t_s.back() - calibration.t_s.front();
  const double heldout_s = heldout.series.t_s.back() - heldout.series.t_s.front();
  std::vector<double> shifts;
  for (double after = 60.0; after <= 30.0 * kSecondsPerDay; after *= 1.25) {
    shifts.push_back(session_s + after);
    shifts.push_back(-heldout_s - after);
  }
  // Searched on the held-out rows a parameter search runs on (TwinReplay::search_replay), then
  // evaluated on every row.
  const TwinReplay& rows = heldout.replay.search_replay();
  const std::vector<double> gap = heldout.replay.at_search_rows(ho_gap_v);
  const auto sse_at = [&](double shift) {
    const Eigen::VectorXd predicted =
        shape.columns(RecordedPart{rows.series(), rows, shift}) * beta;
    double sse = 0.0;
    for (std::size_t i = 0; i < gap.size(); ++i) {
      const double e = gap[i] - predicted(static_cast<Eigen::Index>(i));
      sse += e * e;
    }
    return sse;
  };
  SearchPoint best{{shifts.front()}};
  search_points(
      lattice({shifts}), [&](const std::vector<double>& at) { return sse_at(at[0]); }, best);
  const double best_shift = best.at[0];
  fit.heldout_voltage_v =
      as_vector(shape.columns(RecordedPart{heldout.series, heldout.replay, best_shift}) * beta);
  fit.heldout_values = 1;
  fit.params["heldout_start_after_calibration_start_days"] = best_shift / kSecondsPerDay;
  fit.description += fmt::format(
      "; the held-out session's age is not known (its clock restarts at 0, no start times): "
      "placed where the curve fits it best, {:.3g} days after the calibration session's start",
      best_shift / kSecondsPerDay);
}

}  // namespace flange::diagnose::free_shapes

// SPDX-License-Identifier: MIT
// A batch of runs added to `wheel_fit` (wheel_fit_table.h) from the rows the batch writes,
// without reading `wheel_runs`: the per-wheel sums of the batch are formed here, then one
// statement adds them to each wheel's row. Reading the stored wheel rows back, as the sums did
// before, cost time that grew with the history (a year of a 1,000-locomotive fleet: hours).
// What lands in `wheel_fit` is what the set-based sums over the stored rows give (up to the
// order of floating-point additions).
#pragma once

#include <soci/soci.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "store_url.h"

namespace flange::host {

class WheelFitBatch {
 public:
  // One wheel row of a run written in this transaction.
  void add_run(long long wheel_id, const std::string& started_at, long long run_id,
               double odometer_km, const std::optional<double>& wear_mm);
  // One alarm event of such a run on this wheel.
  void add_alarm(long long wheel_id);
  // Adds the batch to the wheels' rows (created when missing), locking them first so that a
  // maintenance event written at once by another process restarts the fit after or before the
  // batch, never in the middle.
  void apply(soci::session& sql, StoreBackend backend);

 private:
  struct Row {
    std::string started_at;
    long long run_id = 0;
    double odometer_km = 0.0;
    std::optional<double> wear_mm;
  };
  struct Wheel {
    std::vector<Row> rows;
    long long alarms = 0;
  };
  std::vector<std::string> lock_rows(soci::session& sql, StoreBackend backend) const;

  std::map<long long, Wheel> wheels_;
};

}  // namespace flange::host

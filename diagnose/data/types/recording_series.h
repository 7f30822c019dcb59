// SPDX-License-Identifier: MIT
// One recording in memory, in time order, as the diagnosis reads it: every row must carry the
// reference clearance and time must increase. Also the split of one recording into a calibration
// part and a held-out part.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace flange::diagnose {

// The recording format's columns (host/recording).
struct RecordingSeries {
  std::string path;  // where it came from, for messages ("" when built in memory)
  std::vector<double> t_s, clearance_mm, temp_c, voltage_v;
  // When t_s = 0 was, in UTC seconds since 1970, if known (flange diagnose --real-start and
  // --holdout-start): it puts two sessions whose clocks each restart at 0 on one time line, so
  // that an effect of the sensor's age is carried from one session to the other.
  std::optional<double> start_utc_s;
  std::size_t size() const { return t_s.size(); }
};

// For each pair of neighbouring rows, whether the micrometer rests across it (the clearance
// changes by at most 1e-4 mm); empty where it rests for less than a quarter of the pairs (a sweep)
// or there are fewer than two rows.
std::vector<bool> pairs_at_rest(const std::vector<double>& clearance_mm);

// Reads a recording strictly; every row needs the reference clearance. Throws host::InputError
// naming the file, line and field.
RecordingSeries read_recording_series(const std::string& path);

// Rows [begin, end) of `series`, named `label`.
RecordingSeries slice_recording_series(const RecordingSeries& series, std::size_t begin,
                                       std::size_t end, const std::string& label);

struct HoldoutSplit {
  RecordingSeries calibration;
  RecordingSeries heldout;
  std::string heldout_name;  // "last 0.3 of real.csv"
};

// The last `fraction` (0.05 to 0.5) of `real` held out. Throws host::InputError when either part
// would be shorter than 256 rows (the message says how many rows the fraction needs).
HoldoutSplit split_holdout(const RecordingSeries& real, double fraction);

}  // namespace flange::diagnose

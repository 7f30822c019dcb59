// SPDX-License-Identifier: MIT
// `flange run`: a recording through the whole chain, one row at a time: regression, conversion
// to sample words, the filter engine, the thresholds. Memory stays flat: rows stream from the
// input to the output, and the report keeps only bounded summaries (decimated traces, binned
// errors, averaged spectra).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "filtered_extent.h"
#include "thresholds.h"
#include "welch_spectrum.h"

namespace flange::host {

struct RunOptions {
  std::string input;        // recording CSV
  std::string calibration;  // model.json from flange calibrate
  std::string coeffs;       // filter.json from flange design
  std::string engine = "model";
  // The core's channel this recording is filtered on: its coefficient set when the set has one
  // per channel (docs/core.md#channels); 0 for a one-channel set.
  int channel = 0;
  std::optional<std::string> out_csv;
  std::optional<std::string> report_dir;
  bool lenient = false;  // flag bad rows instead of stopping at the first
  // 1: everything on one thread; 2: the recording is read and checked on a thread of its own,
  // ahead of the filter, and the output CSV written on another, behind it (same output); 0: 2 for
  // a recording over 1 MiB on a machine with two cores.
  int threads = 0;
  ThresholdConfig thresholds;
};

struct ErrorStats {
  double sum_abs = 0.0, sum_sq = 0.0, max_abs = 0.0;
  std::uint64_t n = 0;
  void add(double error);
  double mae() const { return n ? sum_abs / static_cast<double>(n) : 0.0; }
  double rmse() const;
};

struct AlarmEvent {
  double t_s = 0.0;
  std::string what;  // "warning", "critical", "none" (cleared) or "wear_step 0.73 mm"
};

// Bounded data for the report.
struct RunTrace {
  // Decimated traces: at most about kMaxPoints points, evenly strided.
  static constexpr std::size_t kMaxPoints = 8000;
  std::size_t stride = 1;
  std::uint64_t seen = 0;
  std::vector<double> t_s, raw_mm, filt_mm, reference_mm, temp_c;
  void add(double t, double raw, double filt, double reference, double temp);

  // Mean absolute error by clearance (1 mm bins, 0-12 mm) and temperature (10 C bins,
  // 0-120 C), before and after filtering; out-of-grid values go to the edge bins.
  static constexpr int kClearanceBins = 12, kTempBins = 12;
  std::vector<ErrorStats> region_before = std::vector<ErrorStats>(kClearanceBins * kTempBins);
  std::vector<ErrorStats> region_after = std::vector<ErrorStats>(kClearanceBins * kTempBins);

  std::optional<WelchSpectrum> spectrum_raw, spectrum_filt;
};

struct RunSummary {
  std::string engine;
  double fs_hz = 0.0;
  std::uint64_t rows_read = 0;
  std::uint64_t rows_flagged = 0;         // rows with any flag below
  std::uint64_t bad_rows = 0;             // lenient: unusable rows (the filter held its input)
  std::uint64_t outside_calibration = 0;  // V or T beyond the calibrated range
  std::uint64_t clipped_samples = 0;      // clearance outside the sample word's range
  std::uint64_t saturated_outputs = 0;    // the core clipped an output
  std::uint64_t rtl_mismatches = 0;       // rtl engine: outputs unequal to the model
  std::vector<AlarmEvent> alarm_events;
  std::string final_alarm = "none";
  bool has_reference = false;
  ErrorStats before, after;                   // against the reference; after is delay-aligned
  double group_delay_s = 0.0;                 // the filter's group delay at DC
  int delay_samples = 0;                      // ... rounded to samples, used to align
  std::uint64_t settle_samples = 0;           // start-up transient left out of the after errors
  std::vector<std::string> bad_row_messages;  // the first few, for the summary
  FilteredExtent filtered;                    // the filter output, every row
};

// Throws InputError (bad input: exit status 2) and std::runtime_error (I/O: exit status 1).
RunSummary run_pipeline(const RunOptions& options, RunTrace* trace);

}  // namespace flange::host

// SPDX-License-Identifier: MIT
#include "run_pipeline.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include "calibration.h"
#include "filter_engine.h"
#include "filter_json.h"
#include "input_error.h"
#include "recording_batch_reader.h"
#include "run_output_csv.h"
#include "sample_scaling.h"

namespace flange::host {

void ErrorStats::add(double error) {
  sum_abs += std::abs(error);
  sum_sq += error * error;
  max_abs = std::max(max_abs, std::abs(error));
  ++n;
}

double ErrorStats::rmse() const { return n ? std::sqrt(sum_sq / static_cast<double>(n)) : 0.0; }

void RunTrace::add(double t, double raw, double filt, double reference, double temp) {
  if (seen++ % stride != 0) return;
  t_s.push_back(t);
  raw_mm.push_back(raw);
  filt_mm.push_back(filt);
  reference_mm.push_back(reference);
  temp_c.push_back(temp);
  if (t_s.size() >= kMaxPoints) {
    // Keep every other point and double the stride: bounded memory, even coverage.
    for (std::vector<double>* v : {&t_s, &raw_mm, &filt_mm, &reference_mm, &temp_c}) {
      for (std::size_t k = 0; 2 * k < v->size(); ++k) (*v)[k] = (*v)[2 * k];
      v->resize((v->size() + 1) / 2);
    }
    stride *= 2;
  }
}

namespace {

// Samples until the slowest pole has decayed to 1 %: the start-up transient from the core's
// zero state, left out of the after-filtering errors.
std::uint64_t settle_samples(const model::FloatDesign& design) {
  double radius = 0.0;
  for (const auto& row : design.sos) {
    // |poles| of a0 + a1 z^-1 + a2 z^-2: sqrt(a2/a0) when complex, else the larger real root.
    const double p = row[4] / row[3], q = row[5] / row[3];
    const double disc = p * p / 4.0 - q;
    const double r = disc < 0.0 ? std::sqrt(q) : std::abs(-p / 2.0) + std::sqrt(disc);
    radius = std::max(radius, r);
  }
  if (radius <= 0.0 || radius >= 1.0) return 0;
  return static_cast<std::uint64_t>(std::ceil(std::log(0.01) / std::log(radius)));
}

int region_index(double clearance_mm, double temp_c) {
  const int c =
      std::clamp(static_cast<int>(std::floor(clearance_mm)), 0, RunTrace::kClearanceBins - 1);
  const int t = std::clamp(static_cast<int>(std::floor(temp_c / 10.0)), 0, RunTrace::kTempBins - 1);
  return t * RunTrace::kClearanceBins + c;
}

// Rows wait in a block for the engine; everything after the filter runs once it returns.
constexpr std::size_t kBlock = 4096;

// What the stages after the filter need of a row.
struct PendingRow {
  double t_s = 0.0;
  double temp_c = 0.0;
  std::optional<double> reference;  // the row's clearance_mm; none for a bad row
  double raw_mm = 0.0;
  unsigned flags = 0;  // RowFlag bits
  bool good() const { return (flags & kBadRow) == 0; }
};

// The coefficient file's float design and core format; its errors are bad input.
struct FilterFile {
  model::FloatDesign design;
  model::CoreConfig core;
};

FilterFile load_filter_file(const std::string& coeffs, int channel) {
  FilterFile file;
  try {
    file.core = model::load_core_config(coeffs);
    if (channel < 0 || channel >= file.core.num_channels) {
      throw InputError(fmt::format("{}: channel {}: the set has channels 0 to {}", coeffs, channel,
                                   file.core.num_channels - 1));
    }
    file.core = file.core.channel_config(channel);
    file.design = model::load_float_design(coeffs, channel);
  } catch (const model::FilterJsonError& error) {
    throw InputError(error.what());
  }
  return file;
}

// The output CSV must not replace a file the run reads: the recording would be gone before it was
// read, a calibration or coefficient file after.
void check_output_is_not_an_input(const RunOptions& options) {
  if (!options.out_csv) return;
  const std::pair<const char*, const std::string*> inputs[] = {
      {"--input", &options.input},
      {"--calibration", &options.calibration},
      {"--coeffs", &options.coeffs}};
  for (const auto& [option, path] : inputs) {
    std::error_code error;  // a file that does not exist yet is none of them
    if (std::filesystem::equivalent(*options.out_csv, *path, error)) {
      throw InputError(
          fmt::format("{}: the output CSV is the file given to {}; choose another --out",
                      *options.out_csv, option));
    }
  }
}

std::unique_ptr<FilterEngine> load_engine(const RunOptions& options) {
  try {
    return make_filter_engine(options.engine, options.coeffs, options.channel);
  } catch (const std::invalid_argument& error) {
    throw InputError(error.what());
  }
}

// What the errors of one row were measured against.
struct References {
  std::optional<double> reference;  // the row's own; none for a bad row or an unknown one
  double aligned = 0.0;             // the one delay_samples earlier; NaN when there is none
  bool settled = false;             // past the filter's start-up transient
};

// One run through the chain: its stages, the output file, the summary, and the bookkeeping
// that carries over from row to row and block to block.
class Pipeline {
 public:
  // Loads the calibration, the filter and the engine, and opens the output CSV, written on a
  // thread of its own when `write_behind`.
  Pipeline(const RunOptions& options, RunTrace* trace, bool write_behind);

  // Calibrates one row and queues it for the engine; a full block goes through at once.
  void add(const RecordingRow& row);
  // Filters what is still queued and completes the summary.
  RunSummary finish(std::size_t rows_read);

 private:
  void start_summary();
  void flag_bad_row(const RecordingRow& row, PendingRow& p);
  void check_sample_rate(const RecordingRow& row);
  void convert_to_sample(const RecordingRow& row, PendingRow& p);
  void finish_block();
  void finish_row(PendingRow& p, const EngineOutput& output);
  ThresholdOutput raise_alarms(double t_s, double filt_mm);
  References add_errors(const PendingRow& p, double filt_mm);
  void add_to_trace(const PendingRow& p, double filt_mm, const References& references);

  const RunOptions& options_;
  RunTrace* const trace_;
  const Calibration calibration_;
  const FilterFile filter_;
  const std::unique_ptr<FilterEngine> engine_;
  ThresholdStage thresholds_;
  const SampleScaling scaling_;

  RunSummary summary_;
  std::optional<RunOutputCsv> out_;
  std::vector<RunOutputRow> out_rows_;  // the block's, handed to out_ once it is done
  // The last delay_samples + 1 references (NaN for none), a ring: for delay-aligned errors.
  std::vector<double> recent_reference_;
  std::size_t recent_next_ = 0;  // where the next reference goes
  EngineSample last_input_;
  std::optional<double> previous_t_;
  std::string previous_run_;
  bool rate_checked_ = false;
  AlarmLevel final_level_ = AlarmLevel::kNone;
  std::uint64_t rows_done_ = 0;

  std::vector<PendingRow> pending_;
  std::vector<EngineSample> inputs_;
  std::vector<EngineOutput> outputs_;
};

Pipeline::Pipeline(const RunOptions& options, RunTrace* trace, bool write_behind)
    : options_(options),
      trace_(trace),
      calibration_(load_calibration(options.calibration)),
      filter_(load_filter_file(options.coeffs, options.channel)),
      engine_(load_engine(options)),
      thresholds_(options.thresholds),
      scaling_{filter_.core.sample_width},
      last_input_{scaling_.to_unit(SampleScaling::kCenterMm), 0} {
  start_summary();
  if (trace_ != nullptr) {
    trace_->spectrum_raw.emplace(256, filter_.design.fs_hz);
    trace_->spectrum_filt.emplace(256, filter_.design.fs_hz);
  }
  if (options_.out_csv) out_.emplace(*options_.out_csv, write_behind);
  if (summary_.delay_samples >= 0) {
    recent_reference_.assign(static_cast<std::size_t>(summary_.delay_samples) + 1,
                             std::numeric_limits<double>::quiet_NaN());
  }
  pending_.reserve(kBlock);
  inputs_.reserve(kBlock);
}

void Pipeline::start_summary() {
  summary_.engine = engine_->name();
  summary_.fs_hz = filter_.design.fs_hz;
  const double delay = model::dc_group_delay_samples(filter_.design);
  summary_.delay_samples = static_cast<int>(std::lround(delay));
  summary_.group_delay_s = delay / filter_.design.fs_hz;
  summary_.settle_samples = settle_samples(filter_.design);
}

void Pipeline::add(const RecordingRow& row) {
  PendingRow& p = pending_.emplace_back();
  p.t_s = row.t_s;
  p.temp_c = row.temp_c;
  if (!row.problem.empty()) {
    flag_bad_row(row, p);
  } else {
    p.reference = row.clearance_mm;
    check_sample_rate(row);
    convert_to_sample(row, p);
  }
  inputs_.push_back(last_input_);
  if (pending_.size() == kBlock) finish_block();
}

// Lenient: the filter holds its last valid input, so its timing stays intact.
void Pipeline::flag_bad_row(const RecordingRow& row, PendingRow& p) {
  p.flags |= kBadRow;
  ++summary_.bad_rows;
  if (summary_.bad_row_messages.size() < 5) {
    summary_.bad_row_messages.push_back(
        fmt::format("{}:{}: {}", options_.input, row.line, row.problem));
  }
}

// The filter was designed for fs: a recording at another rate would move its cut-off.
void Pipeline::check_sample_rate(const RecordingRow& row) {
  if (rate_checked_) return;  // once per run is enough
  if (previous_t_ && row.run == previous_run_) {
    const double dt = row.t_s - *previous_t_;
    if (std::abs(dt * filter_.design.fs_hz - 1.0) > 0.02) {
      throw InputError(fmt::format(
          "{}:{}: column t_s: sample interval {:.6g} s does not match the filter's fs = "
          "{:.6g} Hz ({}); resample the recording or design the filter for {:.6g} Hz",
          options_.input, row.line, dt, filter_.design.fs_hz, options_.coeffs, 1.0 / dt));
    }
    rate_checked_ = true;
  }
  previous_t_ = row.t_s;
  previous_run_ = row.run;
}

// Voltage and temperature to clearance, then to the engine's input.
void Pipeline::convert_to_sample(const RecordingRow& row, PendingRow& p) {
  const Calibration::Estimate estimate = calibration_.estimate(row.voltage_v, row.temp_c);
  p.raw_mm = estimate.clearance_mm;
  if (estimate.outside_calibration) {
    p.flags |= kOutsideCalibration;
    ++summary_.outside_calibration;
  }
  bool clipped = false;
  last_input_.word = scaling_.to_word(p.raw_mm, clipped);
  last_input_.unit = scaling_.to_unit(p.raw_mm);
  if (clipped) {
    p.flags |= kClipped;
    ++summary_.clipped_samples;
  }
}

void Pipeline::finish_block() {
  engine_->process(inputs_, outputs_);
  for (std::size_t k = 0; k < pending_.size(); ++k) finish_row(pending_[k], outputs_[k]);
  pending_.clear();
  inputs_.clear();
  if (out_) out_->write(out_rows_);  // block by block, as far as the run got
}

void Pipeline::finish_row(PendingRow& p, const EngineOutput& output) {
  if (output.saturated) {
    p.flags |= kSaturated;
    ++summary_.saturated_outputs;
  }
  const double filt_mm = scaling_.unit_to_mm(output.unit);
  const ThresholdOutput alarm = raise_alarms(p.t_s, filt_mm);
  if (p.flags != 0) ++summary_.rows_flagged;
  if (out_) out_rows_.push_back({p.t_s, p.raw_mm, filt_mm, alarm.flange_mm, alarm.level, p.flags});
  const References references = add_errors(p, filt_mm);
  summary_.filtered.add(filt_mm, references.settled);
  if (trace_ != nullptr && p.good()) add_to_trace(p, filt_mm, references);
}

ThresholdOutput Pipeline::raise_alarms(double t_s, double filt_mm) {
  const ThresholdOutput alarm = thresholds_.step(t_s, filt_mm);
  final_level_ = alarm.level;
  if (alarm.level_changed) {
    summary_.alarm_events.push_back({t_s, alarm_name(alarm.level)});
  }
  if (alarm.wear_step_mm) {
    summary_.alarm_events.push_back({t_s, fmt::format("wear_step {:.3f} mm", *alarm.wear_step_mm)});
  }
  return alarm;
}

// Errors against the reference: before filtering sample by sample, after filtering against
// the reference delay_samples earlier (the filter's lag is not an error).
References Pipeline::add_errors(const PendingRow& p, double filt_mm) {
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  References references;
  references.reference = p.reference;
  if (references.reference) {
    summary_.has_reference = true;
    summary_.before.add(p.raw_mm - *references.reference);
  }
  // NaN when there is no aligned reference (start of the run, or a row without one).
  references.aligned = kNone;
  if (!recent_reference_.empty()) {
    recent_reference_[recent_next_] = references.reference.value_or(kNone);
    if (++recent_next_ == recent_reference_.size()) recent_next_ = 0;
    // The oldest of the ring, once it has filled: this row's reference delay_samples ago.
    if (rows_done_ + 1 >= recent_reference_.size()) {
      references.aligned = recent_reference_[recent_next_];
    }
  }
  ++rows_done_;
  references.settled = rows_done_ > summary_.settle_samples;
  if (!std::isnan(references.aligned) && p.good() && references.settled) {
    summary_.after.add(filt_mm - references.aligned);
  }
  return references;
}

void Pipeline::add_to_trace(const PendingRow& p, double filt_mm, const References& references) {
  const std::optional<double>& reference = references.reference;
  const double aligned = references.aligned;
  trace_->add(p.t_s, p.raw_mm, filt_mm,
              reference.value_or(std::numeric_limits<double>::quiet_NaN()), p.temp_c);
  trace_->spectrum_raw->push(p.raw_mm);
  trace_->spectrum_filt->push(filt_mm);
  if (reference) {
    trace_->region_before[static_cast<std::size_t>(region_index(*reference, p.temp_c))].add(
        p.raw_mm - *reference);
  }
  if (!std::isnan(aligned) && references.settled) {
    trace_->region_after[static_cast<std::size_t>(region_index(aligned, p.temp_c))].add(filt_mm -
                                                                                        aligned);
  }
}

RunSummary Pipeline::finish(std::size_t rows_read) {
  if (!pending_.empty()) finish_block();
  summary_.rows_read = rows_read;
  summary_.rtl_mismatches = engine_->mismatches();
  summary_.final_alarm = alarm_name(final_level_);
  if (out_) out_->finish();
  return std::move(summary_);
}

// Whether threads of their own should read the recording ahead and write the output behind: not
// for a small file, where starting them costs more than it saves, nor on one core.
bool use_helper_threads(const RunOptions& options) {
  if (options.threads != 0) return options.threads >= 2;
  constexpr std::uintmax_t kSmallRecordingBytes = std::uintmax_t{1} << 20;
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(options.input, error);
  return std::thread::hardware_concurrency() >= 2 && !error && bytes > kSmallRecordingBytes;
}

}  // namespace

RunSummary run_pipeline(const RunOptions& options, RunTrace* trace) {
  check_output_is_not_an_input(options);
  const bool helpers = use_helper_threads(options);
  Pipeline pipeline(options, trace, helpers);
  RecordingBatchReader reader(options.input, options.lenient, helpers);
  for (std::span<const RecordingRow> rows; !(rows = reader.next_rows()).empty();) {
    for (const RecordingRow& row : rows) pipeline.add(row);
  }
  return pipeline.finish(reader.rows_read());
}

}  // namespace flange::host

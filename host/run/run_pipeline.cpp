// SPDX-License-Identifier: MIT
#include "run_pipeline.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <deque>
#include <fstream>
#include <iterator>

#include "calibration.h"
#include "filter_engine.h"
#include "filter_json.h"
#include "fixed_decimals.h"
#include "input_error.h"
#include "recording_csv.h"
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

// Group delay at DC of b/a: sum n c_n / sum c_n of the numerator minus the denominator's.
double dc_group_delay_samples(const model::FloatDesign& design) {
  double delay = 0.0;
  for (const auto& row : design.sos) {
    auto centroid = [](double c0, double c1, double c2) {
      const double sum = c0 + c1 + c2;
      return sum == 0.0 ? 0.0 : (c1 + 2.0 * c2) / sum;
    };
    delay += centroid(row[0], row[1], row[2]) - centroid(row[3], row[4], row[5]);
  }
  return delay;
}

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

// One output row; a bad row has no raw clearance.
void format_row(fmt::memory_buffer& buffer, double t, const double* raw, double filt, double flange,
                const char* alarm, const std::string& flags) {
  append_fixed6(buffer, t);
  buffer.push_back(',');
  if (raw != nullptr) append_fixed6(buffer, *raw);
  buffer.push_back(',');
  append_fixed6(buffer, filt);
  buffer.push_back(',');
  append_fixed6(buffer, flange);
  buffer.push_back(',');
  buffer.append(std::string_view(alarm));
  buffer.push_back(',');
  buffer.append(flags);
  buffer.push_back('\n');
}

}  // namespace

RunSummary run_pipeline(const RunOptions& options, RunTrace* trace) {
  const Calibration calibration = load_calibration(options.calibration);
  model::FloatDesign design;
  model::CoreConfig core;
  try {
    design = model::load_float_design(options.coeffs);
    core = model::load_core_config(options.coeffs);
  } catch (const model::FilterJsonError& error) {
    throw InputError(error.what());
  }
  std::unique_ptr<FilterEngine> engine;
  try {
    engine = make_filter_engine(options.engine, options.coeffs);
  } catch (const std::invalid_argument& error) {
    throw InputError(error.what());
  }
  ThresholdStage thresholds(options.thresholds);
  const SampleScaling scaling{core.sample_width};

  RunSummary summary;
  summary.engine = engine->name();
  summary.fs_hz = design.fs_hz;
  const double delay = dc_group_delay_samples(design);
  summary.delay_samples = static_cast<int>(std::lround(delay));
  summary.group_delay_s = delay / design.fs_hz;
  summary.settle_samples = settle_samples(design);
  if (trace != nullptr) {
    trace->spectrum_raw.emplace(256, design.fs_hz);
    trace->spectrum_filt.emplace(256, design.fs_hz);
  }

  std::ofstream out;
  if (options.out_csv) {
    out.open(*options.out_csv, std::ios::binary);
    if (!out) throw std::runtime_error("cannot write " + *options.out_csv);
    out << "t_s,clearance_raw_mm,clearance_filt_mm,flange_mm,alarm,flags\n";
  }

  RecordingReader reader(options.input, options.lenient);
  std::deque<std::optional<double>> recent_reference;  // for delay-aligned errors
  EngineSample last_input{scaling.to_unit(SampleScaling::kCenterMm), 0};
  std::optional<double> previous_t;
  std::string previous_run;
  bool rate_checked = false;
  AlarmLevel final_level = AlarmLevel::kNone;
  std::uint64_t rows_done = 0;

  // Rows wait in a block for the engine; everything after the filter runs once it returns.
  struct PendingRow {
    RecordingRow row;
    std::string flags;
    double raw_mm = 0.0;
  };
  fmt::memory_buffer out_buffer;
  constexpr std::size_t kBlock = 4096;
  std::vector<PendingRow> pending;
  std::vector<EngineSample> inputs;
  std::vector<EngineOutput> outputs;
  pending.reserve(kBlock);
  inputs.reserve(kBlock);

  auto add_flag = [](std::string& flags, const char* name) {
    flags += flags.empty() ? name : std::string("|") + name;
  };

  auto finish_block = [&]() {
    engine->process(inputs, outputs);
    for (std::size_t k = 0; k < pending.size(); ++k) {
      PendingRow& p = pending[k];
      const RecordingRow& row = p.row;
      if (outputs[k].saturated) {
        add_flag(p.flags, "saturated");
        ++summary.saturated_outputs;
      }
      const double filt_mm = scaling.unit_to_mm(outputs[k].unit);
      const ThresholdOutput alarm = thresholds.step(row.t_s, filt_mm);
      final_level = alarm.level;
      if (alarm.level_changed) {
        summary.alarm_events.push_back({row.t_s, alarm_name(alarm.level)});
      }
      if (alarm.wear_step_mm) {
        summary.alarm_events.push_back(
            {row.t_s, fmt::format("wear_step {:.3f} mm", *alarm.wear_step_mm)});
      }
      if (!p.flags.empty()) ++summary.rows_flagged;
      if (out.is_open()) {
        format_row(out_buffer, row.t_s, row.problem.empty() ? &p.raw_mm : nullptr, filt_mm,
                   alarm.flange_mm, alarm_name(alarm.level), p.flags);
      }
      // Errors against the reference: before filtering sample by sample, after filtering
      // against the reference delay_samples earlier (the filter's lag is not an error).
      const bool good = row.problem.empty();
      const std::optional<double> reference = good ? row.clearance_mm : std::nullopt;
      recent_reference.push_back(reference);
      if (recent_reference.size() > static_cast<std::size_t>(summary.delay_samples) + 1) {
        recent_reference.pop_front();
      }
      if (reference) {
        summary.has_reference = true;
        summary.before.add(p.raw_mm - *reference);
      }
      // NaN when there is no aligned reference (start of the run, or a row without one).
      const double aligned =
          recent_reference.size() == static_cast<std::size_t>(summary.delay_samples) + 1
              ? recent_reference.front().value_or(std::nan(""))
              : std::nan("");
      ++rows_done;
      const bool settled = rows_done > summary.settle_samples;
      if (!std::isnan(aligned) && good && settled) summary.after.add(filt_mm - aligned);
      if (trace != nullptr && good) {
        trace->add(row.t_s, p.raw_mm, filt_mm, reference.value_or(std::nan("")), row.temp_c);
        trace->spectrum_raw->push(p.raw_mm);
        trace->spectrum_filt->push(filt_mm);
        if (reference) {
          trace->region_before[static_cast<std::size_t>(region_index(*reference, row.temp_c))].add(
              p.raw_mm - *reference);
        }
        if (!std::isnan(aligned) && settled) {
          trace->region_after[static_cast<std::size_t>(region_index(aligned, row.temp_c))].add(
              filt_mm - aligned);
        }
      }
    }
    pending.clear();
    inputs.clear();
    out.write(out_buffer.data(), static_cast<std::streamsize>(out_buffer.size()));
    out_buffer.clear();
  };

  while (std::optional<RecordingRow> row = reader.next()) {
    PendingRow p;
    if (!row->problem.empty()) {
      // Lenient: the filter holds its last valid input, so its timing stays intact.
      add_flag(p.flags, "bad_row");
      ++summary.bad_rows;
      if (summary.bad_row_messages.size() < 5) {
        summary.bad_row_messages.push_back(
            fmt::format("{}:{}: {}", options.input, row->line, row->problem));
      }
    } else {
      // The filter was designed for fs: a recording at another rate would move its cut-off.
      if (previous_t && row->run == previous_run && !rate_checked) {
        const double dt = row->t_s - *previous_t;
        if (std::abs(dt * design.fs_hz - 1.0) > 0.02) {
          throw InputError(fmt::format(
              "{}:{}: column t_s: sample interval {:.6g} s does not match the filter's fs = "
              "{:.6g} Hz ({}); resample the recording or design the filter for {:.6g} Hz",
              options.input, row->line, dt, design.fs_hz, options.coeffs, 1.0 / dt));
        }
        rate_checked = true;
      }
      previous_t = row->t_s;
      previous_run = row->run;
      const Calibration::Estimate estimate = calibration.estimate(row->voltage_v, row->temp_c);
      p.raw_mm = estimate.clearance_mm;
      if (estimate.outside_calibration) {
        add_flag(p.flags, "outside_calibration");
        ++summary.outside_calibration;
      }
      bool clipped = false;
      last_input.word = scaling.to_word(p.raw_mm, clipped);
      last_input.unit = scaling.to_unit(p.raw_mm);
      if (clipped) {
        add_flag(p.flags, "clipped");
        ++summary.clipped_samples;
      }
    }
    p.row = std::move(*row);
    pending.push_back(std::move(p));
    inputs.push_back(last_input);
    if (pending.size() == kBlock) finish_block();
  }
  if (!pending.empty()) finish_block();
  summary.rows_read = reader.rows_read();
  summary.rtl_mismatches = engine->mismatches();
  summary.final_alarm = alarm_name(final_level);
  if (out.is_open() && !out) throw std::runtime_error("cannot write " + *options.out_csv);
  return summary;
}

}  // namespace flange::host

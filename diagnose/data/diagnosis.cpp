// SPDX-License-Identifier: MIT
// The diagnosis (docs/diagnose.md): noise estimate, where the gap lies, greedy selection of
// library effects scored on held-out data, noise-type signatures, bootstrap inclusion, verdict.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <random>

#include "diagnosis_detail.h"
#include "effect_fit.h"
#include "float_design.h"
#include "gaussian_source.h"
#include "input_error.h"
#include "thresholds.h"
#include "twin_replay.h"

namespace flange::diagnose {

using host::AlarmLevel;
using host::ThresholdConfig;
using host::ThresholdOutput;
using host::ThresholdStage;

using host::InputError;
namespace {

constexpr std::size_t kMinSamples = 256;  // enough for a 16-sample spectrum and the tests
constexpr std::size_t kMaxLag = 25;
constexpr int kMaxSelected = 3;
// A gap exists when the held-out RMS exceeds the noise by 5 %, and is explained when what is
// left after the selected effects is within 10 % of the noise.
constexpr double kGapRatio = 1.05;
constexpr double kExplainedRatio = 1.10;
// A candidate must remove at least this share of the noise variance from the held-out MSE.
constexpr double kMinGainOfNoiseVariance = 0.02;
// The white-noise estimate differences the gap at lag 2: as free of slow bias as lag 1, and
// unbiased also when neighbouring samples share noise (a channel interpolated between samples
// by a skew), which lag 1 under-reads.
constexpr std::size_t kNoiseLag = 2;

std::vector<double> minus(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
  return d;
}

// Block-bootstrap index sets: blocks of consecutive samples, drawn with replacement.
std::vector<std::vector<std::size_t>> block_resamples(std::size_t n, int rounds,
                                                      std::uint64_t seed) {
  const std::size_t block = std::max<std::size_t>(32, n / 20);
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<std::size_t> start(0, n > block ? n - block : 0);
  std::vector<std::vector<std::size_t>> sets(static_cast<std::size_t>(rounds));
  for (auto& set : sets) {
    while (set.size() < n) {
      const std::size_t s = start(random);
      for (std::size_t i = s; i < std::min(n, s + block) && set.size() < n; ++i) set.push_back(i);
    }
  }
  return sets;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(pos);
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

double mean_square_on(const std::vector<double>& e, const std::vector<std::size_t>& idx) {
  double s = 0.0;
  for (std::size_t i : idx) s += e[i] * e[i];
  return idx.empty() ? 0.0 : s / static_cast<double>(idx.size());
}

// The thesis's measurement filter (eq. 4.15: Butterworth order 5, 0.574 Hz at 6 Hz), at the
// same cut-off relative to the recording's rate, in double precision.
std::vector<double> measurement_filter(const std::vector<double>& x, double fs_hz) {
  const coeffs::FloatDesign design =
      coeffs::design_butterworth(5, 0.574 / 6.0 * fs_hz, fs_hz, std::nullopt);
  const std::vector<double>& b = design.b;
  const std::vector<double>& a = design.a;
  std::vector<double> y(x.size(), 0.0);
  // Start from rest at the first input (a DC-settled state), so the start-up is not a gap.
  for (std::size_t n = 0; n < x.size(); ++n) {
    double acc = 0.0;
    for (std::size_t k = 0; k < b.size(); ++k) acc += b[k] * (n >= k ? x[n - k] : x.front());
    for (std::size_t k = 1; k < a.size(); ++k) acc -= a[k] * (n >= k ? y[n - k] : x.front());
    y[n] = acc;
  }
  return y;
}

struct AlarmChange {
  double t_s;
  AlarmLevel level;
};

std::vector<AlarmChange> alarm_changes(const std::vector<double>& t,
                                       const std::vector<double>& clearance) {
  ThresholdStage stage{ThresholdConfig{}};
  std::vector<AlarmChange> changes;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const ThresholdOutput out = stage.step(t[i], clearance[i]);
    if (out.level_changed) changes.push_back({t[i], out.level});
  }
  return changes;
}

// Largest time between a change in `a` and the nearest change to the same level in `b`, both
// ways; a change with no partner counts as the record's length.
double alarm_timing_gap(const std::vector<AlarmChange>& a, const std::vector<AlarmChange>& b,
                        double record_s) {
  double worst = 0.0;
  const auto one_way = [&](const auto& from, const auto& to) {
    for (const AlarmChange& c : from) {
      double nearest = record_s;
      for (const AlarmChange& d : to) {
        if (d.level == c.level) nearest = std::min(nearest, std::abs(d.t_s - c.t_s));
      }
      worst = std::max(worst, nearest);
    }
  };
  one_way(a, b);
  one_way(b, a);
  return worst;
}

std::vector<double> clearance_of(const sim::PolynomialSensorModel& model,
                                 const std::vector<double>& v, const std::vector<double>& t) {
  std::vector<double> d(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) d[i] = model.clearance_mm(v[i], t[i]);
  return d;
}

std::vector<StageGap> stage_gaps(const RecordingSeries& real, const std::vector<double>& sim_v,
                                 double noise_std_v, const sim::PolynomialSensorModel& model,
                                 double fs_hz, std::uint64_t seed) {
  // The noisy twin: the noise floor every stage's gap is compared with.
  sim::GaussianSource noise(sim::derive_seed(seed, 77));
  std::vector<double> noisy_v(sim_v.size());
  for (std::size_t i = 0; i < sim_v.size(); ++i) {
    noisy_v[i] = sim_v[i] + noise_std_v * noise.standard_normal();
  }
  std::vector<StageGap> stages;
  const std::vector<double> gap_v = minus(real.voltage_v, sim_v);
  stages.push_back({"voltage", "V", rms_of(gap_v), rms_of(minus(noisy_v, sim_v)), 0, 0, false,
                    "recorded voltage minus the twin's"});

  const std::vector<double> d_real = clearance_of(model, real.voltage_v, real.temp_c);
  const std::vector<double> d_sim = clearance_of(model, sim_v, real.temp_c);
  const std::vector<double> d_noisy = clearance_of(model, noisy_v, real.temp_c);
  stages.push_back({"clearance", "mm", rms_of(minus(d_real, d_sim)), rms_of(minus(d_noisy, d_sim)),
                    rms_of(minus(d_real, real.clearance_mm)),
                    rms_of(minus(d_sim, real.clearance_mm)), false,
                    "compensated clearance (the twin's nominal polynomial applied to V, T)"});

  const std::vector<double> f_real = measurement_filter(d_real, fs_hz);
  const std::vector<double> f_sim = measurement_filter(d_sim, fs_hz);
  const std::vector<double> f_noisy = measurement_filter(d_noisy, fs_hz);
  stages.push_back({"filtered_clearance", "mm", rms_of(minus(f_real, f_sim)),
                    rms_of(minus(f_noisy, f_sim)), rms_of(minus(f_real, real.clearance_mm)),
                    rms_of(minus(f_sim, real.clearance_mm)), false,
                    "after the thesis measurement filter (Butterworth 5, fc = 0.0957 fs, double)"});

  const double record_s = real.t_s.back() - real.t_s.front();
  const auto a_real = alarm_changes(real.t_s, f_real);
  const auto a_sim = alarm_changes(real.t_s, f_sim);
  const auto a_noisy = alarm_changes(real.t_s, f_noisy);
  stages.push_back({"alarm_timing", "s", alarm_timing_gap(a_real, a_sim, record_s),
                    alarm_timing_gap(a_noisy, a_sim, record_s), 0, 0, false,
                    fmt::format("largest onset difference of {} real vs {} sim alarm changes",
                                a_real.size(), a_sim.size())});
  for (StageGap& stage : stages) {
    stage.significant = stage.name == "alarm_timing" ? stage.gap_rms > stage.noise_floor + 1.0
                                                     : stage.gap_rms > 1.5 * stage.noise_floor;
  }
  return stages;
}

constexpr int kClearanceCells = 5, kTempCells = 4;

struct Grid {
  double c_lo, c_step, t_lo, t_step;
  int cell(double c, double t) const {
    const int ci = std::clamp(static_cast<int>((c - c_lo) / c_step), 0, kClearanceCells - 1);
    const int ti = std::clamp(static_cast<int>((t - t_lo) / t_step), 0, kTempCells - 1);
    return ti * kClearanceCells + ci;
  }
};

Grid grid_for(const RecordingSeries& s) {
  const auto [c_min, c_max] = std::minmax_element(s.clearance_mm.begin(), s.clearance_mm.end());
  const auto [t_min, t_max] = std::minmax_element(s.temp_c.begin(), s.temp_c.end());
  return {*c_min, std::max(*c_max - *c_min, 1e-9) / kClearanceCells, *t_min,
          std::max(*t_max - *t_min, 1e-9) / kTempCells};
}

std::vector<RegionCell> region_cells(const RecordingSeries& s, const std::vector<double>& gap,
                                     const Grid& grid, int rounds, std::uint64_t seed) {
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
      for (const auto& set :
           block_resamples(values.size(), rounds, seed + static_cast<unsigned>(k))) {
        std::vector<double> drawn;
        for (std::size_t i : set) drawn.push_back(values[i]);
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

std::vector<double> rate_of(const std::vector<double>& t, const std::vector<double>& x) {
  std::vector<double> r(x.size(), 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::size_t lo = i == 0 ? 0 : i - 1, hi = i + 1 == x.size() ? i : i + 1;
    if (hi > lo) r[i] = (x[hi] - x[lo]) / (t[hi] - t[lo]);
  }
  return r;
}

double band_rms(const Spectrum& psd, std::pair<double, double> band) {
  if (psd.frequency_hz.size() < 2) return 0.0;
  const double df = psd.frequency_hz[1] - psd.frequency_hz[0];
  double power = 0.0;
  for (std::size_t k = 0; k < psd.value.size(); ++k) {
    if (psd.frequency_hz[k] >= band.first - 1e-12 && psd.frequency_hz[k] <= band.second + 1e-12) {
      power += psd.value[k] * df;
    }
  }
  return std::sqrt(power);
}

void locate(const RecordingSeries& cal, const std::vector<double>& sim_v, double fs_hz,
            const DiagnoseOptions& options, DiagnosisDetail& detail) {
  const double sigma = detail.noise_std_v;
  const std::vector<double> gap = minus(cal.voltage_v, sim_v);
  detail.t_s = cal.t_s;
  detail.gap_v = gap;
  detail.stages = stage_gaps(cal, sim_v, sigma, options.twin.nominal, fs_hz, options.seed);
  detail.regions = region_cells(cal, gap, grid_for(cal), options.bootstrap_rounds, options.seed);
  // The cell where the gap stands out most above the noise, among cells with enough samples.
  double worst = 0.0;
  for (std::size_t k = 0; k < detail.regions.size(); ++k) {
    const RegionCell& c = detail.regions[k];
    const double excess = c.rms_v * c.rms_v - sigma * sigma;
    if (c.n >= 30 && excess > worst) {
      worst = excess;
      detail.where_region = k;
    }
  }
  const std::size_t segment = spectrum_segment(gap.size());
  detail.gap_psd = welch_psd(gap, fs_hz, segment);
  detail.noise_psd = 2.0 * sigma * sigma / fs_hz;
  // The band: from the bin of largest excess over the noise, widened while the PSD stays above
  // twice the noise level. DC is left out (each segment's mean is removed).
  const std::vector<double>& p = detail.gap_psd.value;
  std::size_t peak = 0;
  double peak_excess = 0.0;
  for (std::size_t k = 1; k < p.size(); ++k) {
    if (p[k] - detail.noise_psd > peak_excess) {
      peak_excess = p[k] - detail.noise_psd;
      peak = k;
    }
  }
  if (peak > 0 && p[peak] > 2.0 * detail.noise_psd) {
    std::size_t lo = peak, hi = peak;
    while (lo > 1 && p[lo - 1] > 2.0 * detail.noise_psd) --lo;
    while (hi + 1 < p.size() && p[hi + 1] > 2.0 * detail.noise_psd) ++hi;
    detail.band_hz =
        std::make_pair(detail.gap_psd.frequency_hz[lo], detail.gap_psd.frequency_hz[hi]);
  }
  const std::vector<double> temp_rate = rate_of(cal.t_s, cal.temp_c);
  const std::vector<std::pair<std::string, const std::vector<double>*>> inputs = {
      {"temperature", &cal.temp_c},
      {"temperature_rate", &temp_rate},
      {"clearance", &cal.clearance_mm}};
  for (const auto& [name, input] : inputs) {
    const Spectrum msc = coherence(gap, *input, fs_hz, segment);
    InputCoherence c{name, 0.0, 0.0, 0.0};
    int count = 0;
    for (std::size_t k = 1; k < msc.value.size(); ++k) {
      const double f = msc.frequency_hz[k];
      if (!detail.band_hz || (f >= detail.band_hz->first && f <= detail.band_hz->second)) {
        c.in_band += msc.value[k];
        ++count;
      }
      if (msc.value[k] > c.peak) {
        c.peak = msc.value[k];
        c.peak_hz = f;
      }
    }
    if (count > 0) c.in_band /= count;
    detail.coherences.push_back(c);
  }
  const std::size_t min_length = std::max<std::size_t>(30, gap.size() / 50);
  for (const MeanSegment& s : mean_change_points(gap, sigma, 0.5 * sigma, min_length, 8)) {
    detail.segments.push_back({cal.t_s[s.begin], cal.t_s[s.end - 1], s.mean});
  }
  detail.whiteness = whiteness_test(gap, kMaxLag);
  detail.vs_temperature = independence_test(gap, cal.temp_c, kMaxLag);
  detail.vs_temperature_rate = independence_test(gap, temp_rate, kMaxLag);
  detail.vs_clearance = independence_test(gap, cal.clearance_mm, kMaxLag);
}

void check_series(const RecordingSeries& s, const std::string& role) {
  const std::string name = s.path.empty() ? role : s.path;
  if (s.size() < kMinSamples) {
    throw InputError(fmt::format("{}: {} rows in the {} part; at least {} are needed", name,
                                 s.size(), role, kMinSamples));
  }
  if (s.clearance_mm.size() != s.size() || s.temp_c.size() != s.size() ||
      s.voltage_v.size() != s.size()) {
    throw InputError(fmt::format("{}: columns of unequal length", name));
  }
}

// Refits every selected effect (from `first` on) once, with the others held. A greedy pick is
// fitted before the effects found after it, so it soaks up part of them (an offset drift takes
// some of an ageing offset); the refit hands that part back. A refit is kept only where it
// lowers the calibration RMS, since fit_effect searches afresh rather than from the last fit.
void backfit(std::vector<sim::EffectSettings>& modelled, std::size_t first,
             const TwinReplay& replay, const std::vector<double>& real_v) {
  double rms_now = rms_of(minus(real_v, replay.voltage(modelled)));
  for (std::size_t j = first; j < modelled.size(); ++j) {
    std::vector<sim::EffectSettings> others = modelled;
    others.erase(others.begin() + static_cast<long>(j));
    const EffectFit refit = fit_effect(modelled[j].name, replay, real_v, others);
    if (refit.rms_v < rms_now) {
      modelled[j] = refit.settings;
      rms_now = refit.rms_v;
    }
  }
}

}  // namespace

double sample_rate_hz(const RecordingSeries& series) {
  if (series.size() < 2) {
    throw InputError(fmt::format("{}: fewer than 2 rows: no sample rate", series.path));
  }
  std::vector<double> steps;
  for (std::size_t i = 1; i < series.size(); ++i) {
    const double step = series.t_s[i] - series.t_s[i - 1];
    if (!(step > 0.0)) {
      throw InputError(fmt::format("{}: row {}: t_s = {} does not increase (previous {})",
                                   series.path, i + 1, series.t_s[i], series.t_s[i - 1]));
    }
    steps.push_back(step);
  }
  return 1.0 / quantile(steps, 0.5);
}

DiagnosisResult diagnose_in_detail(const RecordingSeries& calibration,
                                   const RecordingSeries& heldout, const DiagnoseOptions& options) {
  check_series(calibration, "calibration");
  check_series(heldout, "held-out");
  const double fs_hz = sample_rate_hz(calibration);
  const double fs_heldout = sample_rate_hz(heldout);
  if (std::abs(fs_heldout - fs_hz) > 0.01 * fs_hz) {
    throw InputError(fmt::format(
        "{}: sample rate {:.6g} Hz differs from {}'s {:.6g} Hz; the held-out recording must be "
        "sampled at the same rate (within 1 %)",
        heldout.path.empty() ? "held-out" : heldout.path, fs_heldout,
        calibration.path.empty() ? "the calibration part" : calibration.path, fs_hz));
  }
  sim::check_twin_config(options.twin);

  DiagnosisResult result;
  Diagnosis& diagnosis = result.diagnosis;
  DiagnosisDetail& detail = result.detail;
  detail.fs_hz = fs_hz;
  const TwinReplay cal_replay(calibration, options.twin.nominal);
  const TwinReplay ho_replay(heldout, options.twin.nominal);
  std::vector<sim::EffectSettings> modelled = options.twin.effects;
  const std::vector<double> cal_base = cal_replay.voltage(modelled);
  const std::vector<double> ho_base = ho_replay.voltage(modelled);
  const std::vector<double> cal_gap = minus(calibration.voltage_v, cal_base);
  const std::vector<double> ho_gap = minus(heldout.voltage_v, ho_base);

  if (options.estimate_noise) {
    detail.noise_std_v = white_noise_std(cal_gap, kNoiseLag);
    detail.noise_source =
        "estimated from the calibration gap: 1.4826 MAD(differences at lag 2) / sqrt(2)";
  } else {
    detail.noise_std_v = options.twin.noise.voltage_std_v;
    detail.noise_source = "given by the twin (noise.voltage_std_v)";
  }
  double sigma = std::max(detail.noise_std_v, 1e-9);
  diagnosis.noise_std_v = sigma;
  locate(calibration, cal_base, fs_hz, options, detail);
  for (const StageGap& stage : detail.stages) {
    if (stage.significant) {
      diagnosis.stage = stage.name;
      break;
    }
  }

  // Greedy selection of bias-type effects, each scored on the held-out part.
  struct Step {
    std::vector<std::string> names;
    std::vector<std::vector<double>> heldout_error;  // per candidate, after adding it
    std::size_t chosen = 0;
  };
  std::vector<Step> steps;
  std::vector<EffectFinding> findings;
  std::vector<double> current_error = ho_gap;
  const auto resamples = block_resamples(heldout.size(), options.bootstrap_rounds, options.seed);
  const std::size_t first_selected = options.twin.effects.size();
  for (int round = 0; round < kMaxSelected; ++round) {
    Step step;
    std::vector<EffectFit> fits;
    std::vector<std::vector<sim::EffectSettings>> candidate_sets;  // modelled + each candidate
    // Candidates are independent of each other: each is fitted in its own thread (the replays
    // are read-only), and the results are taken in catalogue order, so the outcome does not
    // depend on the threads.
    struct Candidate {
      EffectFit fit;
      std::vector<sim::EffectSettings> with;  // modelled + the candidate, refitted
      std::vector<double> heldout_error;
    };
    std::vector<std::string> names;
    for (const sim::EffectSpec& spec : sim::effect_catalogue()) {
      const bool taken = std::any_of(modelled.begin(), modelled.end(),
                                     [&](const auto& m) { return m.name == spec.name; });
      if (fitted_by_bias(spec.name) && !taken) names.push_back(spec.name);
    }
    std::vector<std::future<Candidate>> pending;
    for (const std::string& name : names) {
      pending.push_back(std::async(std::launch::async, [&, name] {
        Candidate c;
        c.fit = fit_effect(name, cal_replay, calibration.voltage_v, modelled);
        c.with = modelled;
        c.with.push_back(c.fit.settings);
        // Each candidate is scored with the effects chosen before it refitted around it.
        if (c.with.size() > first_selected + 1) {
          backfit(c.with, first_selected, cal_replay, calibration.voltage_v);
        }
        c.heldout_error = minus(heldout.voltage_v, ho_replay.voltage(c.with));
        return c;
      }));
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
      Candidate c = pending[i].get();
      fits.push_back(std::move(c.fit));
      candidate_sets.push_back(std::move(c.with));
      step.names.push_back(names[i]);
      step.heldout_error.push_back(std::move(c.heldout_error));
    }
    if (fits.empty()) break;
    const double mse_now = rms_of(current_error) * rms_of(current_error);
    std::size_t best = 0;
    double best_gain = -std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < fits.size(); ++c) {
      const double r = rms_of(step.heldout_error[c]);
      if (mse_now - r * r > best_gain) {
        best_gain = mse_now - r * r;
        best = c;
      }
    }
    // Significant: the gain is a real share of the noise variance and its block-bootstrap 95 %
    // lower bound is above zero.
    std::vector<double> gains;
    for (const auto& set : resamples) {
      gains.push_back(mean_square_on(current_error, set) -
                      mean_square_on(step.heldout_error[best], set));
    }
    const double lower = quantile(gains, 0.05);
    if (best_gain < kMinGainOfNoiseVariance * sigma * sigma || lower <= 0.0) break;
    step.chosen = best;
    EffectFinding finding;
    finding.name = fits[best].settings.name;
    finding.params = fits[best].settings.params;
    finding.heldout_rms_before = rms_of(current_error);
    finding.heldout_rms_after = rms_of(step.heldout_error[best]);
    finding.shrink_pct = 100.0 * (finding.heldout_rms_before - finding.heldout_rms_after) /
                         finding.heldout_rms_before;
    finding.evidence = fmt::format(
        "fitted on the calibration part (RMS {:.4g} V); on held-out data it lowers the gap's mean "
        "square by {:.3g} V^2 (bootstrap 95 % lower bound {:.3g})",
        fits[best].rms_v, best_gain, lower);
    if (finding.name == "mains_pickup") {
      finding.noise_type = true;
      finding.evidence += "; a tone: the mains line aliased by the sampling";
    }
    modelled = candidate_sets[best];
    current_error = step.heldout_error[best];
    findings.push_back(finding);
    // The earlier findings carry their parameters as refitted with this one.
    for (std::size_t j = 0; j < findings.size(); ++j) {
      findings[j].params = modelled[first_selected + j].params;
    }
    steps.push_back(std::move(step));
    // A deterministic effect in the gap (a mains tone, a lag on the clearance steps) inflates
    // the difference-based noise estimate; estimate it again from what the effects leave.
    if (options.estimate_noise) {
      const double left =
          white_noise_std(minus(calibration.voltage_v, cal_replay.voltage(modelled)), kNoiseLag);
      if (left < sigma) {
        sigma = std::max(left, 1e-9);
        detail.noise_std_v = sigma;
        diagnosis.noise_std_v = sigma;
        detail.noise_source =
            "estimated from the calibration gap left by the selected effects: 1.4826 "
            "MAD(differences at lag 2) / sqrt(2)";
      }
    }
  }
  // Inclusion: the share of held-out resamples on which each step's choice still wins and
  // gains (the fits are not redone per round: it is the scoring that is resampled).
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const std::vector<double>& before =
        s == 0 ? ho_gap : steps[s - 1].heldout_error[steps[s - 1].chosen];
    int wins = 0;
    for (const auto& set : resamples) {
      const double base = mean_square_on(before, set);
      std::size_t arg = 0;
      double best = -std::numeric_limits<double>::infinity();
      for (std::size_t c = 0; c < steps[s].names.size(); ++c) {
        const double gain = base - mean_square_on(steps[s].heldout_error[c], set);
        if (gain > best) {
          best = gain;
          arg = c;
        }
      }
      if (arg == steps[s].chosen && best > 0.0) ++wins;
    }
    findings[s].inclusion = static_cast<double>(wins) / static_cast<double>(resamples.size());
  }

  // Noise-type effects, recognised from their signatures in both parts.
  const auto cal_grid = find_lsb_grid(calibration.voltage_v);
  const auto ho_grid = find_lsb_grid(heldout.voltage_v);
  if (cal_grid && ho_grid && *cal_grid == *ho_grid) {
    EffectFinding finding;
    finding.name = "adc_quantization";
    finding.params = cal_grid->params;
    finding.noise_type = true;
    finding.inclusion = 1.0;
    finding.evidence = fmt::format(
        "every recorded voltage of both parts lies on a {}-bit grid over [{}, {}] V (LSB {:.4g} "
        "mV)",
        cal_grid->params.at("bits"), cal_grid->params.at("v_min"), cal_grid->params.at("v_max"),
        1e3 * (cal_grid->params.at("v_max") - cal_grid->params.at("v_min")) /
            std::ldexp(1.0, static_cast<int>(cal_grid->params.at("bits"))));
    std::vector<sim::EffectSettings> with = modelled;
    with.push_back(*cal_grid);
    finding.heldout_rms_before = rms_of(current_error);
    current_error = minus(heldout.voltage_v, ho_replay.voltage(with));
    finding.heldout_rms_after = rms_of(current_error);
    finding.shrink_pct = 100.0 * (finding.heldout_rms_before - finding.heldout_rms_after) /
                         std::max(finding.heldout_rms_before, 1e-30);
    modelled = with;
    findings.push_back(finding);
  }
  const std::vector<double> cal_after = minus(calibration.voltage_v, cal_replay.voltage(modelled));
  const VibrationSignature cal_vibration =
      vibration_signature(cal_after, cal_replay.sensitivity_v_per_mm());
  const VibrationSignature ho_vibration =
      vibration_signature(current_error, ho_replay.sensitivity_v_per_mm());
  // The noise the verdict compares what is left with: the white voltage noise, or, with mount
  // motion found, that plus the motion's share, whose variance follows the sensitivity and so
  // escapes the median-based estimate: the held-out gap's mean squared difference / 2.
  double verdict_noise = sigma;
  if (cal_vibration.present && ho_vibration.present) {
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < current_error.size(); ++i) {
      sum += std::pow(current_error[i + 1] - current_error[i], 2);
    }
    verdict_noise =
        std::max(sigma, std::sqrt(0.5 * sum / static_cast<double>(current_error.size() - 1)));
    EffectFinding finding;
    finding.name = "vibration";
    finding.params = {{"rms_mm", cal_vibration.rms_mm}};
    finding.noise_type = true;
    finding.heldout_rms_before = finding.heldout_rms_after = rms_of(current_error);
    // Inclusion: resamples of the held-out gap on which the signature still shows.
    int shows = 0;
    for (const auto& set : resamples) {
      std::vector<double> gap_drawn, sens_drawn;
      for (std::size_t i : set) {
        gap_drawn.push_back(current_error[i]);
        sens_drawn.push_back(ho_replay.sensitivity_v_per_mm()[i]);
      }
      if (vibration_signature(gap_drawn, sens_drawn).present) ++shows;
    }
    finding.inclusion = static_cast<double>(shows) / static_cast<double>(resamples.size());
    finding.evidence = fmt::format(
        "the gap's sample-to-sample variance grows with the sensor's sensitivity squared "
        "(t = {:.1f} calibration, {:.1f} held-out): clearance motion, not voltage noise; "
        "random phases cannot be fitted, so it adds no shrink (held-out rms_mm {:.3g})",
        cal_vibration.slope_t, ho_vibration.slope_t, ho_vibration.rms_mm);
    findings.push_back(finding);
  }

  diagnosis.heldout_rms_before = rms_of(ho_gap);
  diagnosis.heldout_rms_after = rms_of(current_error);
  const bool has_noise_type =
      std::any_of(findings.begin(), findings.end(),
                  [](const EffectFinding& f) { return f.noise_type && f.name != "mains_pickup"; });
  const bool gap_exists = diagnosis.heldout_rms_before > kGapRatio * sigma ||
                          !diagnosis.stage.empty() || has_noise_type || !findings.empty();
  const bool left_within_noise = diagnosis.heldout_rms_after <= kExplainedRatio * verdict_noise;
  auto& reasons = detail.reasons;
  reasons.push_back(fmt::format(
      "held-out gap RMS {:.4g} V before, {:.4g} V after the selected effects; white noise {:.4g} V",
      diagnosis.heldout_rms_before, diagnosis.heldout_rms_after, sigma));
  if (verdict_noise > sigma) {
    reasons.push_back(fmt::format(
        "with the mount motion, the noise what is left is compared with is {:.4g} V (the held-out "
        "gap's mean squared difference / 2), not the white {:.4g} V",
        verdict_noise, sigma));
  }
  if (!findings.empty() && left_within_noise) {
    diagnosis.status = "explained";
    diagnosis.effects = findings;
    reasons.push_back(fmt::format("what is left is within {:.0f} % of the noise",
                                  100.0 * (kExplainedRatio - 1.0)));
  } else if (gap_exists) {
    diagnosis.status = "unexplained";
    detail.partial = findings;
    reasons.push_back(findings.empty()
                          ? "no library effect shrinks the held-out gap significantly"
                          : "the effects that help leave more than the noise: something outside "
                            "the library remains");
  } else {
    diagnosis.status = "none";
    reasons.push_back(fmt::format(
        "the held-out gap is within {:.0f} % of the twin's noise and no stage exceeds its noise "
        "floor",
        100.0 * (kGapRatio - 1.0)));
  }
  if (diagnosis.stage.empty()) diagnosis.stage = "none";

  // How far, on held-out data: overall, in the where-cell and in the where-band.
  HowFar& how = detail.how_far;
  how.rms_before = diagnosis.heldout_rms_before;
  how.rms_after = diagnosis.heldout_rms_after;
  how.max_before = max_abs_of(ho_gap);
  how.max_after = max_abs_of(current_error);
  if (detail.where_region) {
    const RegionCell& cell = detail.regions[*detail.where_region];
    std::vector<double> before, after;
    for (std::size_t i = 0; i < heldout.size(); ++i) {
      if (heldout.clearance_mm[i] >= cell.clearance_lo &&
          heldout.clearance_mm[i] <= cell.clearance_hi && heldout.temp_c[i] >= cell.temp_lo &&
          heldout.temp_c[i] <= cell.temp_hi) {
        before.push_back(ho_gap[i]);
        after.push_back(current_error[i]);
      }
    }
    how.region_rms_before = rms_of(before);
    how.region_rms_after = rms_of(after);
  }
  if (detail.band_hz) {
    const std::size_t segment = spectrum_segment(heldout.size());
    how.band_rms_before = band_rms(welch_psd(ho_gap, fs_hz, segment), *detail.band_hz);
    how.band_rms_after = band_rms(welch_psd(current_error, fs_hz, segment), *detail.band_hz);
  }
  detail.heldout_t_s = heldout.t_s;
  detail.heldout_gap_before_v = ho_gap;
  detail.heldout_gap_after_v = current_error;
  return result;
}

Diagnosis diagnose(const RecordingSeries& calibration, const RecordingSeries& heldout,
                   const DiagnoseOptions& options) {
  return diagnose_in_detail(calibration, heldout, options).diagnosis;
}

}  // namespace flange::diagnose

// SPDX-License-Identifier: MIT
// The diagnosis (docs/diagnose.md): noise estimate, where the gap lies, greedy selection of
// library effects scored on held-out data, noise-type signatures, bootstrap inclusion, verdict.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <numeric>
#include <optional>
#include <span>
#include <string>

#include "adc_grid.h"
#include "block_resamples.h"
#include "diagnosis_detail.h"
#include "effect_fit.h"
#include "float_design.h"
#include "free_shape_fit.h"
#include "gaussian_source.h"
#include "input_error.h"
#include "quantised_noise.h"
#include "residual_tests.h"
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
// The fewest samples a clearance x temperature cell needs to be the where-region, and the held-out
// part to say anything about that cell.
constexpr std::size_t kMinCellSamples = 30;
// A gap exists when the held-out RMS exceeds the noise by 5 %, and is explained when what is
// left after the selected effects is within 10 % of the noise.
constexpr double kGapRatio = 1.05;
constexpr double kExplainedRatio = 1.10;
// Significant picks that leave more than that are still the diagnosis ("partly explained") when
// they take at least this share of the held-out gap's RMS above the noise. Not 0.80, the shrink
// issue 11 asks of a bias-type class: on the twin's own self-test (seed 3) three classes together
// took 78-86 % of a gain step that no class models, and would have been claimed.
constexpr double kPartlyExplainedShare = 0.90;
// "Explained" also asks the noise level of what is left in every window of the held-out samples
// that lie within the calibration's clearance and temperature ranges (a 64th of them, at least 100
// samples; worst_window): twice the noise in one of them is something the picks miss there. A gain
// step at 0.66 of a session, taken for a temperature gain because the session is below 38 C almost
// only after it, left 1.10 times the noise over the session and 2.26 times it in one 64th (the
// twin's seed 4, case 49). On the twin's seed 3 and the twelve alternative development seeds it
// turns no verdict.
constexpr std::size_t kLocalWindows = 64;
constexpr std::size_t kLeastLocalWindowSamples = 100;
constexpr double kLocalExplainedRatio = 2.0;
// A held-out session that goes beyond the calibration's clearance or temperature is explained
// when what is left within the calibration's ranges is (verdict, explained_within_reach), if at
// least this share of its samples lies within them ...
constexpr double kLeastShareWithinReach = 0.25;
// ... and if the picks' continued curves take at least this share of the gap above the noise
// beyond the calibration's ranges, and at least the share of the samples that lie there: a curve
// that leaves most of the gap there explains only what it was fitted on (fresh alternative pair
// 425/19: a static nonlinearity on a hysteresis, seen from one side, took 42 % where the held-out
// session went to closer clearances; the range compression of 101/24 took 72 % beyond its
// calibration's temperatures), and the less of the session the calibration reaches, the more
// the continued curves must carry. (Until stop 28 half the samples had to lie within, whatever
// the curves took beyond: development pair 430/23, a quadratic temperature gain, was 0.98 times
// the noise on the 45 % within and took 89 % beyond, where the held-out session heated 23 C
// further, and was "unexplained".)
constexpr double kLeastShareTakenBeyondReach = 0.5;
// A candidate must remove at least this share of the noise variance from the held-out MSE ...
constexpr double kMinGainOfNoiseVariance = 0.02;
// ... the first pick at least this share, unless a noise-type class shows before any pick. On pairs
// with no effect the best first candidate gains at most 0.05 % (the twin's seed 11 and
// alternative seed 433, 13 null pairs): 0.5 % is ten times that. Later picks keep 2 %: what they
// take is mostly the misfit of an earlier pick's shape (alternative pair 433/23, a channel skew
// taking 0.4 % after a log-time ageing; the twin's seed 11 case 32, an ageing taking 0.65 % after
// a temperature gain). So does a first pick where mount motion or a converter grid shows: motion
// moves the mean voltage where the sensor's curve bends and where it is one-sided (impacts), and a
// converter's rounding is a function of the voltage, by amounts their signatures do not fix; a
// bias class took that at 0.6-1 % (the twin's seed 11, cases 1 and 13; alternative pairs 432/32,
// 432/12 and 434/7). At 2 % for every pick, a 133 s thermal lag at 0.07 V of noise, which takes
// 0.9 %, was "none" (the twin's seed 11, cases 22 and 23).
constexpr double kMinFirstGainOfNoiseVariance = 0.005;
// Since stop 30 that 0.5 % is the most a first pick is asked: where what the candidates gain by
// chance on the data at hand (first_pick_least_gain) is less, the least gain is that chance gain,
// but not below 0.2 % (four times the largest best first gain of the 13 null pairs above). The
// twin's reading lags of -62 s at 0.07 V of noise (seed 14 case 23, seed 15 case 25) take 0.2-0.5 %
// and were "none".
constexpr double kLeastFirstGainOfNoiseVariance = 0.002;
// Lags of the held-out gap the chance gains are measured at.
constexpr std::size_t kChanceShifts = 64;

std::vector<double> minus(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
  return d;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(pos);
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
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

// Null replicas behind the stage floors: the noisy twin drawn this many times at the estimated
// noise (issue 11 item 3). The RMS stages take the replicas' median (their spread is a few per
// cent). Alarm timing, a largest onset difference that jumps to the time to the next alarm change
// when noise makes or misses one, takes their largest, which a noise-made gap passes with odds of
// 1 in 33: so it must show on the held-out part too (against that part's own replicas) to count,
// and a null pair passes both about 1 time in 1,000.
constexpr int kNullReplicas = 32;
constexpr double kAlarmMarginS = 1.0;  // an alarm gap must exceed its floor by this much

double median_of(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// Calls each(replica, noisy_v, d_noisy, f_noisy) for kNullReplicas draws of the noisy twin (on
// the recording's converter grid, if it has one) of `sim_v`, with its compensated and filtered
// clearance. The draws come from one stream in replica order, so the floors do not depend on the
// threads; what each draw then costs (inversion, filter, alarms: most of it) runs two replicas at
// a time, so `each` must only write to its replica's own place.
template <class Each>
void for_each_null_replica(const RecordingSeries& real, const std::vector<double>& sim_v,
                           const WhiteNoise& white, const sim::PolynomialSensorModel& model,
                           double fs_hz, std::uint64_t seed, Each each) {
  constexpr std::size_t kInFlight = 2;
  sim::GaussianSource noise(seed);
  std::vector<std::future<void>> running;
  for (int replica = 0; replica < kNullReplicas; ++replica) {
    std::vector<double> noisy_v(sim_v.size());
    for (std::size_t i = 0; i < sim_v.size(); ++i) {
      noisy_v[i] = white.noisy(sim_v[i], noise.standard_normal());
    }
    if (running.size() == kInFlight) {
      running.front().get();
      running.erase(running.begin());
    }
    running.push_back(std::async(std::launch::async, [&, replica, noisy_v = std::move(noisy_v)] {
      const std::vector<double> d_noisy = clearance_of(model, noisy_v, real.temp_c);
      each(static_cast<std::size_t>(replica), noisy_v, d_noisy, measurement_filter(d_noisy, fs_hz));
    }));
  }
  for (std::future<void>& r : running) r.get();
}

struct AlarmTiming {
  double gap_s = 0.0, floor_s = 0.0;
  std::size_t real_changes = 0, sim_changes = 0;
  bool exceeds() const { return gap_s > floor_s + kAlarmMarginS; }
};

// The alarm-timing gap of `real` (its filtered clearance `f_real`) against the twin's alarm
// changes `a_sim`, and its floor, the largest of the null replicas' (`alarm_floor`).
AlarmTiming alarm_timing(const RecordingSeries& real, const std::vector<double>& f_real,
                         const std::vector<AlarmChange>& a_sim,
                         const std::vector<double>& alarm_floor) {
  const double record_s = real.t_s.back() - real.t_s.front();
  const auto a_real = alarm_changes(real.t_s, f_real);
  return {alarm_timing_gap(a_real, a_sim, record_s),
          *std::max_element(alarm_floor.begin(), alarm_floor.end()), a_real.size(), a_sim.size()};
}

std::vector<StageGap> stage_gaps(const RecordingSeries& real, const std::vector<double>& sim_v,
                                 const WhiteNoise& white, const sim::PolynomialSensorModel& model,
                                 double fs_hz, std::uint64_t seed) {
  const std::vector<double> d_real = clearance_of(model, real.voltage_v, real.temp_c);
  const std::vector<double> d_sim = clearance_of(model, sim_v, real.temp_c);
  const std::vector<double> f_real = measurement_filter(d_real, fs_hz);
  const std::vector<double> f_sim = measurement_filter(d_sim, fs_hz);
  const double record_s = real.t_s.back() - real.t_s.front();
  const auto a_sim = alarm_changes(real.t_s, f_sim);

  // The noisy twin against the noiseless one: the floors every stage's gap is compared with.
  std::vector<double> voltage_floor(kNullReplicas), clearance_floor(kNullReplicas),
      filtered_floor(kNullReplicas), alarm_floor(kNullReplicas);
  for_each_null_replica(
      real, sim_v, white, model, fs_hz, sim::derive_seed(seed, 77),
      [&](std::size_t replica, const std::vector<double>& noisy_v,
          const std::vector<double>& d_noisy, const std::vector<double>& f_noisy) {
        voltage_floor[replica] = rms_of(minus(noisy_v, sim_v));
        clearance_floor[replica] = rms_of(minus(d_noisy, d_sim));
        filtered_floor[replica] = rms_of(minus(f_noisy, f_sim));
        alarm_floor[replica] = alarm_timing_gap(alarm_changes(real.t_s, f_noisy), a_sim, record_s);
      });
  const AlarmTiming alarm = alarm_timing(real, f_real, a_sim, alarm_floor);

  std::vector<StageGap> stages;
  stages.push_back({"voltage", "V", rms_of(minus(real.voltage_v, sim_v)), median_of(voltage_floor),
                    0, 0, false, "recorded voltage minus the twin's"});
  stages.push_back({"clearance", "mm", rms_of(minus(d_real, d_sim)), median_of(clearance_floor),
                    rms_of(minus(d_real, real.clearance_mm)),
                    rms_of(minus(d_sim, real.clearance_mm)), false,
                    "compensated clearance (the twin's nominal polynomial applied to V, T)"});
  stages.push_back({"filtered_clearance", "mm", rms_of(minus(f_real, f_sim)),
                    median_of(filtered_floor), rms_of(minus(f_real, real.clearance_mm)),
                    rms_of(minus(f_sim, real.clearance_mm)), false,
                    "after the thesis measurement filter (Butterworth 5, fc = 0.0957 fs, double)"});
  stages.push_back(
      {"alarm_timing", "s", alarm.gap_s, alarm.floor_s, 0, 0, false,
       fmt::format("largest onset difference of {} real vs {} sim alarm changes; the floor is the "
                   "largest of {} null replicas at the estimated noise",
                   alarm.real_changes, alarm.sim_changes, kNullReplicas)});
  for (StageGap& stage : stages) {
    stage.significant =
        stage.name == "alarm_timing" ? alarm.exceeds() : stage.gap_rms > 1.5 * stage.noise_floor;
  }
  return stages;
}

// The alarm-timing gap of the held-out part against the twin replayed on it, with its own floor.
AlarmTiming heldout_alarm_timing(const RecordingSeries& heldout, const std::vector<double>& sim_v,
                                 const WhiteNoise& white, const sim::PolynomialSensorModel& model,
                                 double fs_hz, std::uint64_t seed) {
  const std::vector<double> f_real =
      measurement_filter(clearance_of(model, heldout.voltage_v, heldout.temp_c), fs_hz);
  const std::vector<double> f_sim =
      measurement_filter(clearance_of(model, sim_v, heldout.temp_c), fs_hz);
  const double record_s = heldout.t_s.back() - heldout.t_s.front();
  const auto a_sim = alarm_changes(heldout.t_s, f_sim);
  std::vector<double> alarm_floor(kNullReplicas);
  for_each_null_replica(heldout, sim_v, white, model, fs_hz, sim::derive_seed(seed, 78),
                        [&](std::size_t replica, const std::vector<double>&,
                            const std::vector<double>&, const std::vector<double>& f_noisy) {
                          alarm_floor[replica] = alarm_timing_gap(
                              alarm_changes(heldout.t_s, f_noisy), a_sim, record_s);
                        });
  return alarm_timing(heldout, f_real, a_sim, alarm_floor);
}

// The alarm-timing stage counts only when the held-out part shows it too: a stage that the
// calibration part alone exceeds is kept, not significant, with the held-out figures in its note.
void confirm_alarm_timing_on_heldout(const RecordingSeries& heldout,
                                     const std::vector<double>& ho_sim_v,
                                     const DiagnoseOptions& options, DiagnosisDetail& detail) {
  for (StageGap& stage : detail.stages) {
    if (stage.name != "alarm_timing" || !stage.significant) continue;
    const AlarmTiming held_out = heldout_alarm_timing(
        heldout, ho_sim_v, detail.white_noise, options.twin.nominal, detail.fs_hz, options.seed);
    if (held_out.exceeds()) {
      stage.note += fmt::format("; the held-out part shows it too ({:.3g} s against {:.3g} s)",
                                held_out.gap_s, held_out.floor_s);
    } else {
      stage.significant = false;
      stage.note += fmt::format(
          "; not counted: the held-out part does not show it ({:.3g} s against a floor of {:.3g} "
          "s, {} real vs {} sim alarm changes), and the calibration part's largest alone is "
          "passed by noise about 1 time in {}",
          held_out.gap_s, held_out.floor_s, held_out.real_changes, held_out.sim_changes,
          kNullReplicas + 1);
    }
  }
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
      const BlockResamples resamples(values.size(), rounds, seed + static_cast<unsigned>(k));
      for (std::size_t r = 0; r < resamples.size(); ++r) {
        std::vector<double> drawn;
        for (std::size_t i : resamples.indices(r)) drawn.push_back(values[i]);
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
  detail.stages =
      stage_gaps(cal, sim_v, detail.white_noise, options.twin.nominal, fs_hz, options.seed);
  detail.regions = region_cells(cal, gap, grid_for(cal), options.bootstrap_rounds, options.seed);
  // The cell where the gap stands out most above the noise, among cells with enough samples.
  double worst = 0.0;
  for (std::size_t k = 0; k < detail.regions.size(); ++k) {
    const RegionCell& c = detail.regions[k];
    const double excess = c.rms_v * c.rms_v - sigma * sigma;
    if (c.n >= kMinCellSamples && excess > worst) {
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

// The sample rate the two parts share. Throws InputError for a part that is too short or has
// unequal columns, and for parts sampled at different rates.
double shared_sample_rate_hz(const RecordingSeries& calibration, const RecordingSeries& heldout) {
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
  return fs_hz;
}

// How much later the held-out session's t_s = 0 is than the calibration's, and how that is known.
struct SessionClock {
  std::string kind;           // Diagnosis::clock
  double age_offset_s = 0.0;  // 0 unless the start times say otherwise
};

SessionClock session_clock(const RecordingSeries& calibration, const RecordingSeries& heldout) {
  if (calibration.start_utc_s && heldout.start_utc_s) {
    return {"start times", *heldout.start_utc_s - *calibration.start_utc_s};
  }
  if (heldout.t_s.front() > calibration.t_s.back()) return {"one clock", 0.0};
  return {"unknown", 0.0};
}

// The reason line on the clocks, when it bears on the verdict: the start times were used, or they
// were missing and an age effect was weighed.
std::optional<std::string> clock_reason(const Diagnosis& diagnosis,
                                        const std::vector<EffectFinding>& partial) {
  if (diagnosis.clock == "start times") {
    return fmt::format(
        "the held-out session starts {:.4g} days after the calibration session (the start times "
        "given): effects of the sensor's age are replayed that much older",
        *diagnosis.heldout_starts_after_s / 86400.0);
  }
  const auto ageing = [](const EffectFinding& f) { return f.name == "ageing_drift"; };
  const bool weighed = std::any_of(diagnosis.effects.begin(), diagnosis.effects.end(), ageing) ||
                       std::any_of(partial.begin(), partial.end(), ageing) ||
                       (diagnosis.nearest && ageing(*diagnosis.nearest));
  if (diagnosis.clock != "unknown" || !weighed) return std::nullopt;
  return "the held-out clock restarts at 0 and the sessions' start times are unknown: ageing is "
         "a trend within each session, and each session is taken to start at the same age, so a "
         "drift that ran on between the sessions is left as an offset on the held-out part, "
         "unless a free ageing curve placed the held-out session at an age of its own (give "
         "--real-start and --holdout-start)";
}

// Whether, in `s`, the direction of the last clearance move is set by the clearance itself: in
// every band of a twentieth of the range holding 30 or more samples at rest after the first move,
// at least 95 % of them were last reached by a move the same way, and both ways occur (a
// staircase that climbs in steps and drops back in one move). Then an output that depends on the
// direction of the last move is a function of clearance. A sweep says no: it reaches each
// clearance from both sides. It slows to under 1e-4 mm a sample only at its turning points, and
// there each band is reached one way (alternative pair 442/7, a motorised sweep, was said to be
// one-sided): a micrometer that rests for less than a quarter of the session is not asked.
bool last_move_set_by_clearance(const RecordingSeries& s) {
  constexpr int kBands = 20;
  constexpr std::size_t kLeastSamples = 30;
  constexpr double kOneWayShare = 0.95;
  const std::vector<bool> rest = pairs_at_rest(s.clearance_mm);
  if (rest.empty()) return false;
  const auto [lo, hi] = std::minmax_element(s.clearance_mm.begin(), s.clearance_mm.end());
  const double width = (*hi - *lo) / kBands;
  if (!(width > 0.0)) return false;
  std::vector<std::size_t> opening(kBands, 0), closing(kBands, 0);
  int last = 0;  // +1 after an opening move, -1 after a closing one, 0 before the first
  for (std::size_t i = 1; i < s.size(); ++i) {
    if (!rest[i - 1]) {
      last = s.clearance_mm[i] > s.clearance_mm[i - 1] ? 1 : -1;
      continue;
    }
    if (last == 0) continue;
    const auto band = std::min(kBands - 1, static_cast<int>((s.clearance_mm[i] - *lo) / width));
    ++(last > 0 ? opening : closing)[static_cast<std::size_t>(band)];
  }
  bool any_opening = false, any_closing = false;
  for (int b = 0; b < kBands; ++b) {
    const std::size_t up = opening[static_cast<std::size_t>(b)];
    const std::size_t down = closing[static_cast<std::size_t>(b)];
    if (up + down < kLeastSamples) continue;
    if (static_cast<double>(std::max(up, down)) < kOneWayShare * static_cast<double>(up + down)) {
      return false;
    }
    any_opening = any_opening || up > down;
    any_closing = any_closing || down > up;
  }
  return any_opening && any_closing;
}

// A static nonlinearity named on sessions whose every clearance is reached from one side only
// cannot be told from a hysteresis (an output that depends on the direction of the last move,
// outside the library): there that is a function of clearance too.
std::optional<std::string> one_sided_protocol_reason(const Diagnosis& diagnosis,
                                                     const RecordingSeries& calibration,
                                                     const RecordingSeries& heldout) {
  const bool named = std::any_of(diagnosis.effects.begin(), diagnosis.effects.end(),
                                 [](const EffectFinding& f) { return f.name == "nonlinearity"; });
  if (!named || !last_move_set_by_clearance(calibration) || !last_move_set_by_clearance(heldout)) {
    return std::nullopt;
  }
  return "in both sessions each clearance is reached from one side only (the micrometer's last "
         "move before a clearance went the same way at least 95 % of the time there), so the "
         "static nonlinearity cannot be told from a hysteresis, an output that depends on the "
         "direction of the last move (outside the library); a session that reaches each "
         "clearance from both sides would tell them apart";
}

// The two parts of the data, each with the twin replayed on its inputs.
class LibraryRounds;

struct Parts {
  const RecordingSeries& calibration;
  const RecordingSeries& heldout;
  TwinReplay cal_replay;
  TwinReplay ho_replay;
  bool heldout_age_unknown;     // the sessions' clocks are unknown (session_clock's "unknown")
  std::optional<AdcGrid> grid;  // the converter grid both parts lie on (shared_grid), if one
  std::shared_ptr<LibraryRounds> library_rounds;  // the library candidates both passes weigh
};

// A candidate effect fitted on the calibration part and scored on the held-out part.
struct Candidate {
  EffectFit fit;
  std::vector<sim::EffectSettings> with;  // modelled + the candidate, refitted
  std::vector<double> heldout_error;      // the held-out gap `with` leaves
  // A free-shape candidate (free_shape_fit.h): its curve, added to the voltage beside `with`
  // (then the modelled effects as they were).
  std::optional<FreeShapeFit> free_shape;
};

// The library's candidates of the rounds weighed so far, for the other pass: the free-shape pass's
// first round weighs the same library candidates, on the same targets, as the library pass's first
// round did, and so do its later rounds while it picks as the library pass did. They are fitted
// once (their fits are a third of a 100 Hz diagnosis). A round is found again only when everything
// its fits depend on is the same.
class LibraryRounds {
 public:
  struct Key {
    std::vector<std::string> names;  // the candidates' effects
    std::vector<sim::EffectSettings> modelled;
    std::size_t first_selected = 0;
    std::vector<double> cal_v, ho_v;  // the calibration and held-out targets
    bool operator==(const Key&) const = default;
  };

  std::optional<std::vector<Candidate>> find(const Key& key) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [k, candidates] : rounds_) {
      if (k == key) return candidates;
    }
    return std::nullopt;
  }
  void keep(Key key, const std::vector<Candidate>& candidates) {
    const std::lock_guard<std::mutex> lock(mutex_);
    rounds_.emplace_back(std::move(key), candidates);
  }

 private:
  mutable std::mutex mutex_;
  std::vector<std::pair<Key, std::vector<Candidate>>> rounds_;
};

// One round of the greedy selection that picked an effect: every candidate it weighed (their
// held-out gaps are scored again on resamples for the inclusion) and the one it picked.
struct Step {
  std::vector<Candidate> candidates;
  std::size_t chosen = 0;
};

// What the diagnosis's steps hand on to each other once the nominal twin is replayed.
struct Selection {
  std::vector<sim::EffectSettings> modelled;  // the twin's own effects, then the picks
  std::size_t first_selected = 0;             // where the picks start in `modelled`
  std::vector<double> ho_gap;                 // held-out gap the picks start from
  // The held-out gap of the twin as given: ho_gap unless the converter's boundaries were placed
  // first (their offset is then in ho_gap, not here). What "before" means in the report.
  std::vector<double> raw_ho_gap;
  std::vector<double> current_error;    // held-out gap `modelled` leaves
  double sigma = 0.0;                   // the twin's white noise, V (>= 1e-9)
  BlockResamples resamples;             // of the held-out part
  std::vector<Step> steps;              // one per bias-type pick
  std::vector<EffectFinding> findings;  // in selection order
  std::optional<AdcGrid> quantised_on;  // the converter grid, once recognised
  // The converter's code boundaries, when placed before the picks (place_converter_boundaries),
  // and the constant offset they give the twin's voltage (held in cal_free_v and ho_free_v).
  std::optional<double> converter_threshold_lsb;
  double converter_offset_v = 0.0;
  // The DAQ's gain calibration, when placed with them: the recorded voltage is the gain times
  // the twin's plus converter_gain_offset_v (held in cal_free_v and ho_free_v as well).
  std::optional<double> converter_gain;
  double converter_gain_offset_v = 0.0;
  bool quantisation_as_noise = false;  // its codes not reproduced: taken as noise
  // Mount motion shows in both parts' first gaps, or both parts lie on one converter grid: a
  // first pick then needs kMinGainOfNoiseVariance, like the later ones.
  bool noise_type_before_picks = false;
  // The least held-out gain a first pick must make on this data (V^2): set in the first round
  // from the candidates' chance gains against the held-out gap shifted in time.
  double first_pick_least_gain = 0.0;
  std::optional<EffectFinding> nearest_unpicked;  // the best candidate when none was significant
  // What the free-shape picks add to the twin's voltage, per part (zeros without any), and for
  // each bias-type pick the index of its effect in `modelled` (-1: a free shape, which has none).
  std::vector<double> cal_free_v, ho_free_v;
  std::vector<int> modelled_index;
  bool free_shapes = false;  // whether the free-shape families compete (the second pass)
  // Whether a library pick was given a free shape after the rounds (give_pick_a_free_shape).
  bool shapes_refined = false;
  // One sentence per pick that another class explained as well (issue 11 item 2).
  std::vector<std::string> confounded;
  // One sentence per pick that the backward steps took out (drop_unneeded_picks).
  std::vector<std::string> dropped;
};

// The recorded voltage less what the free-shape picks add: what the replayed effects must meet.
std::vector<double> cal_target(const Parts& parts, const Selection& selection) {
  return minus(parts.calibration.voltage_v, selection.cal_free_v);
}
std::vector<double> ho_target(const Parts& parts, const Selection& selection) {
  return minus(parts.heldout.voltage_v, selection.ho_free_v);
}

// Whether `name`'s class is already modelled: by the library effect or by its free shape.
bool class_taken(const std::string& name, const Selection& selection) {
  return std::any_of(selection.modelled.begin(), selection.modelled.end(),
                     [&](const auto& m) { return m.name == name; }) ||
         std::any_of(selection.findings.begin(), selection.findings.end(),
                     [&](const EffectFinding& f) { return f.name == name; });
}

// What the held-out gap that is left is compared with, and why when it is not the white noise.
struct VerdictNoise {
  double rms_v = 0.0;
  std::string why;
};

// The twin's white voltage noise: estimated from the calibration part (on its converter grid,
// if it has one), or the twin's own.
void estimate_noise(const RecordingSeries& calibration, const std::vector<double>& cal_base,
                    const DiagnoseOptions& options, DiagnosisDetail& detail) {
  detail.adc_grid = estimate_adc_grid(calibration.voltage_v);
  detail.white_noise = options.estimate_noise
                           ? estimate_white_noise(calibration.voltage_v, cal_base, detail.adc_grid)
                           : given_white_noise(options.twin.noise.voltage_std_v, detail.adc_grid);
  detail.noise_std_v = detail.white_noise.effective_std_v;
  detail.noise_source = detail.white_noise.source;
}

// The first stage whose gap stands above its noise floor; empty when none does.
std::string first_significant_stage(const std::vector<StageGap>& stages) {
  for (const StageGap& stage : stages) {
    if (stage.significant) return stage.name;
  }
  return "";
}

// Two parts' grids are one converter's: the same LSB, codes on one lattice.
bool same_grid(const AdcGrid& a, const AdcGrid& b) {
  const double codes_apart = (b.lowest_v - a.lowest_v) / a.lsb_v;
  return std::abs(a.lsb_v - b.lsb_v) <= 1e-3 * a.lsb_v &&
         std::abs(codes_apart - std::round(codes_apart)) < 0.05;
}

// The converter grid both parts lie on, if they lie on one.
std::optional<AdcGrid> shared_grid(const RecordingSeries& calibration,
                                   const RecordingSeries& heldout) {
  const auto cal_grid = estimate_adc_grid(calibration.voltage_v);
  const auto ho_grid = estimate_adc_grid(heldout.voltage_v);
  if (!cal_grid || !ho_grid || !same_grid(*cal_grid, *ho_grid)) return std::nullopt;
  std::vector<double> both = calibration.voltage_v;
  both.insert(both.end(), heldout.voltage_v.begin(), heldout.voltage_v.end());
  return estimate_adc_grid(both);
}

bool has_effect(const std::vector<sim::EffectSettings>& effects, const std::string& name) {
  return std::any_of(effects.begin(), effects.end(),
                     [&](const sim::EffectSettings& e) { return e.name == name; });
}

// A converter's code boundaries need not sit where rounding puts them: a truncating one puts
// them a whole LSB up, which offsets every code by -LSB/2 against the twin's rounding. On a
// coarse grid that offset is as large as an effect, and a bias class took it before the
// quantisation was recognised. So when both parts lie on one grid, the twin's converter on it is
// replayed with its boundaries at 21 places over [-0.5, 0.5] LSB (threshold_lsb), the place that
// fits the calibration part best is kept, and the mean offset it gives the twin's voltage there
// joins the twin as a constant before any effect is fitted (a constant, not the converter itself,
// so that the effects' fits stay smooth), if it lowers the calibration gap's mean square by the
// least gain a pick must make. With them, a DAQ gain calibration the grid shows. `grid`: the
// parts' shared grid (shared_grid), if any.
void place_converter_boundaries(const Parts& parts, const std::optional<AdcGrid>& grid,
                                Selection& selection) {
  if (has_effect(selection.modelled, "adc_quantization")) return;
  if (!grid) return;
  const std::vector<double>& cal_v = parts.calibration.voltage_v;
  const std::vector<double> twin_v = parts.cal_replay.voltage(selection.modelled);
  double best_rms = std::numeric_limits<double>::infinity(), best_threshold = 0.0;
  std::vector<double> best_v;
  for (int step = -10; step <= 10; ++step) {
    sim::EffectSettings converter = grid->as_effect();
    converter.params["threshold_lsb"] = 0.05 * step;
    std::vector<sim::EffectSettings> with = selection.modelled;
    with.push_back(converter);
    std::vector<double> v = parts.cal_replay.voltage(with);
    const double rms = rms_of(minus(cal_v, v));
    if (rms < best_rms) {
      best_rms = rms;
      best_threshold = converter.params["threshold_lsb"];
      best_v = std::move(v);
    }
  }
  const std::vector<double> offset_by_sample = minus(best_v, twin_v);
  const double offset_v = std::accumulate(offset_by_sample.begin(), offset_by_sample.end(), 0.0) /
                          static_cast<double>(offset_by_sample.size());
  const std::vector<double> raw_gap = minus(cal_v, twin_v);
  std::vector<double> gap = raw_gap;
  for (double& g : gap) g -= offset_v;
  const double sigma = selection.sigma;
  const double least = kMinGainOfNoiseVariance * sigma * sigma;
  // A grid a little off a usual range's is a DAQ gain calibration (AdcGrid::calibration_gain):
  // the recorded voltage is then the gain times the twin's, plus a constant. The gain is the
  // grid's, so only the constant is fitted; kept when it lowers the calibration gap by the least
  // gain a pick must make.
  const double slope = grid->calibration_gain - 1.0;
  double line_offset_v = 0.0;
  bool calibrated = false;
  if (slope != 0.0) {
    std::vector<double> line_gap = gap;
    for (std::size_t i = 0; i < line_gap.size(); ++i) line_gap[i] -= slope * twin_v[i];
    line_offset_v = std::accumulate(line_gap.begin(), line_gap.end(), 0.0) /
                    static_cast<double>(line_gap.size());
    for (double& g : line_gap) g -= line_offset_v;
    const double before = rms_of(gap), after = rms_of(line_gap);
    calibrated = before * before - after * after >= least;
    if (calibrated) gap = std::move(line_gap);
  }
  const double without = rms_of(raw_gap), after = rms_of(gap);
  if (without * without - after * after < least) return;
  for (double& v : selection.cal_free_v) v += offset_v;
  for (double& v : selection.ho_free_v) v += offset_v;
  if (calibrated) {
    const std::vector<double> ho_twin_v = parts.ho_replay.voltage(selection.modelled);
    for (std::size_t i = 0; i < twin_v.size(); ++i) {
      selection.cal_free_v[i] += slope * twin_v[i] + line_offset_v;
    }
    for (std::size_t i = 0; i < ho_twin_v.size(); ++i) {
      selection.ho_free_v[i] += slope * ho_twin_v[i] + line_offset_v;
    }
    selection.converter_gain = grid->calibration_gain;
    selection.converter_gain_offset_v = line_offset_v;
  }
  selection.converter_threshold_lsb = best_threshold;
  selection.converter_offset_v = offset_v;
}

// The twin as given (options.twin) replayed on both parts: the noise estimate, where the gap
// lies on the calibration part, and the held-out gap the selection starts from (with the
// converter's boundaries placed first, when the data lie on a grid: place_converter_boundaries).
Selection replay_nominal_twin(const Parts& parts, const DiagnoseOptions& options,
                              DiagnosisResult& result) {
  Diagnosis& diagnosis = result.diagnosis;
  DiagnosisDetail& detail = result.detail;
  Selection selection;
  selection.modelled = options.twin.effects;
  const std::vector<double> cal_base = parts.cal_replay.voltage(selection.modelled);
  selection.cal_free_v.assign(parts.calibration.size(), 0.0);
  selection.ho_free_v.assign(parts.heldout.size(), 0.0);

  estimate_noise(parts.calibration, cal_base, options, detail);
  selection.sigma = std::max(detail.noise_std_v, 1e-9);
  diagnosis.noise_std_v = selection.sigma;
  locate(parts.calibration, cal_base, detail.fs_hz, options, detail);
  const std::vector<double> ho_base = parts.ho_replay.voltage(selection.modelled);
  confirm_alarm_timing_on_heldout(parts.heldout, ho_base, options, detail);
  diagnosis.stage = first_significant_stage(detail.stages);
  selection.raw_ho_gap = minus(parts.heldout.voltage_v, ho_base);
  const std::optional<AdcGrid>& grid = parts.grid;
  place_converter_boundaries(parts, grid, selection);
  selection.ho_gap = minus(ho_target(parts, selection), ho_base);
  const bool motion =
      vibration_signature(minus(cal_target(parts, selection), cal_base),
                          parts.cal_replay.sensitivity_v_per_mm(), parts.calibration.clearance_mm)
          .present &&
      vibration_signature(selection.ho_gap, parts.ho_replay.sensitivity_v_per_mm(),
                          parts.heldout.clearance_mm)
          .present;
  selection.noise_type_before_picks = motion || grid.has_value();
  return selection;
}

// The two parts with the temperature the coil sees in place of the recorded one, for the free
// shapes: with a late temperature channel modelled (a reading lag, a skew), a class of the
// temperature follows the coil's, which leads the reading; the library's effects see it in the
// replay already (ambient_from_recorded). A range compression's knee behind a sheathed
// thermocouple falls with the coil's temperature, not with what the thermocouple shows yet.
// With a late voltage channel modelled (a skew), the clearance and temperature are those the
// voltage was made at: a free curve is added to the skewed voltage, after the chain, so a curve
// of the recorded clearance would smear a ripple wherever the micrometer moves (alternative pair
// 450/27, a 3.9 mm clearance ripple behind a 4.8 s delay on a motorised sweep: the curve left the
// calibration part at 1.3 times the noise).
struct CoilParts {
  RecordingSeries calibration, heldout;
  std::unique_ptr<TwinReplay> cal_replay, ho_replay;
};

// How late a modelled skew makes the voltage channel (s, <= 0: the voltage at t was made at
// t + skew_s), or 0.
double voltage_channel_skew_s(const std::vector<sim::EffectSettings>& modelled) {
  for (const sim::EffectSettings& effect : modelled) {
    if (effect.name == "channel_skew" && effect.params.at("skew_s") < 0.0) {
      return effect.params.at("skew_s");
    }
  }
  return 0.0;
}

// `series` with its clearance and temperature taken `skew_s` later (held at the first row before
// the record began, as the twin's skew holds it).
void shift_inputs(RecordingSeries& series, double skew_s) {
  const RecordingSeries recorded = series;
  for (std::size_t i = 0; i < series.size(); ++i) {
    series.clearance_mm[i] =
        interpolate_at(recorded.t_s, recorded.clearance_mm, recorded.t_s[i] + skew_s);
    series.temp_c[i] = interpolate_at(recorded.t_s, recorded.temp_c, recorded.t_s[i] + skew_s);
  }
}

std::unique_ptr<const CoilParts> coil_parts(const Parts& parts,
                                            const std::vector<sim::EffectSettings>& modelled) {
  const double voltage_skew_s = voltage_channel_skew_s(modelled);
  if (std::none_of(modelled.begin(), modelled.end(), delays_temperature_channel) &&
      voltage_skew_s == 0.0) {
    return nullptr;
  }
  auto coil = std::make_unique<CoilParts>();
  coil->calibration = parts.calibration;
  coil->calibration.temp_c = ambient_from_recorded(parts.calibration, modelled);
  coil->heldout = parts.heldout;
  coil->heldout.temp_c = ambient_from_recorded(parts.heldout, modelled);
  if (voltage_skew_s != 0.0) {
    shift_inputs(coil->calibration, voltage_skew_s);
    shift_inputs(coil->heldout, voltage_skew_s);
  }
  coil->cal_replay = std::make_unique<TwinReplay>(coil->calibration, parts.cal_replay.nominal(),
                                                  parts.cal_replay.age_offset_s());
  coil->ho_replay = std::make_unique<TwinReplay>(coil->heldout, parts.ho_replay.nominal(),
                                                 parts.ho_replay.age_offset_s());
  return coil;
}

// What the free shapes are fitted on: the parts as recorded, or `coil`'s copies of them.
struct FreeShapeParts {
  const RecordingSeries& calibration;
  const TwinReplay& cal_replay;
  const RecordingSeries& heldout;
  const TwinReplay& ho_replay;
};

FreeShapeParts free_shape_parts(const Parts& parts, const CoilParts* coil) {
  if (!coil) return {parts.calibration, parts.cal_replay, parts.heldout, parts.ho_replay};
  return {coil->calibration, *coil->cal_replay, coil->heldout, *coil->ho_replay};
}

// Whether `family` is weighed on these parts (FreeShapeFamily::weighed_on_a_converter_grid; test
// Diagnose.ACoarseConverterIsListedBeforeASmallerBiasEffect).
bool weighed_on(const FreeShapeFamily& family, const Parts& parts) {
  return !parts.grid || family.weighed_on_a_converter_grid;
}

// The library's candidates of a round (`round`: their names, the effects modelled and the
// targets), each fitted on the calibration part, refitted with the picks before it and scored on
// the held-out part. They are independent of each other: each is fitted in its own thread (the
// replays are read-only), and the results are taken in catalogue order, so the outcome does not
// depend on the threads.
std::vector<Candidate> fit_library_candidates(const Parts& parts, const LibraryRounds::Key& round) {
  std::vector<std::future<Candidate>> pending;
  for (const std::string& name : round.names) {
    pending.push_back(std::async(std::launch::async, [&, name] {
      Candidate c;
      c.fit = fit_effect(name, parts.cal_replay, round.cal_v, round.modelled);
      c.with = round.modelled;
      c.with.push_back(c.fit.settings);
      // Each candidate is scored with the effects chosen before it refitted around it.
      if (c.with.size() > round.first_selected + 1) {
        backfit(c.with, round.first_selected, parts.cal_replay, round.cal_v);
      }
      c.heldout_error = minus(round.ho_v, parts.ho_replay.voltage(c.with));
      return c;
    }));
  }
  std::vector<Candidate> candidates;
  for (std::future<Candidate>& c : pending) candidates.push_back(c.get());
  return candidates;
}

// Every bias-type effect of the catalogue not yet modelled, fitted on top of `modelled` and
// scored on the held-out part, in catalogue order.
std::vector<Candidate> score_candidates(const Parts& parts, const Selection& selection) {
  const std::vector<sim::EffectSettings>& modelled = selection.modelled;
  const std::vector<double> cal_v = cal_target(parts, selection);
  std::vector<std::string> names;
  for (const sim::EffectSpec& spec : sim::effect_catalogue()) {
    if (fitted_by_bias(spec.name) && !class_taken(spec.name, selection)) {
      names.push_back(spec.name);
    }
  }
  LibraryRounds::Key key{names, modelled, selection.first_selected, cal_v,
                         ho_target(parts, selection)};
  std::vector<Candidate> candidates;
  if (auto weighed = parts.library_rounds->find(key)) {
    candidates = std::move(*weighed);
  } else {
    candidates = fit_library_candidates(parts, key);
    parts.library_rounds->keep(std::move(key), candidates);
  }
  // The free shapes of the classes not yet modelled: least squares on the gap left, no refit;
  // in parallel too, taken in catalogue order.
  const std::vector<double> cal_gap = minus(cal_v, parts.cal_replay.voltage(modelled));
  const std::unique_ptr<const CoilParts> coil =
      selection.free_shapes ? coil_parts(parts, modelled) : nullptr;
  const FreeShapeParts free_parts = free_shape_parts(parts, coil.get());
  std::vector<std::future<Candidate>> pending_free;
  for (const FreeShapeFamily& family : free_shape_families()) {
    if (!selection.free_shapes || class_taken(family.effect, selection) ||
        !weighed_on(family, parts)) {
      continue;
    }
    pending_free.push_back(std::async(std::launch::async, [&, family] {
      Candidate c;
      c.free_shape = fit_free_shape(family, {{free_parts.calibration, free_parts.cal_replay},
                                             {free_parts.heldout, free_parts.ho_replay},
                                             cal_gap,
                                             selection.current_error,
                                             parts.heldout_age_unknown});
      // The class the fitted shape names (a compression whose knee does not move is a static
      // nonlinearity).
      c.fit.settings =
          sim::make_effect_settings(c.free_shape->family.effect, {}, "diagnose free shape");
      c.fit.rms_v = rms_of(minus(cal_gap, c.free_shape->cal_voltage_v));
      c.with = modelled;
      c.heldout_error = minus(selection.current_error, c.free_shape->heldout_voltage_v);
      return c;
    }));
  }
  for (std::future<Candidate>& c : pending_free) candidates.push_back(c.get());
  return candidates;
}

struct Pick {
  std::size_t best = 0;  // index into the round's candidates
  double gain = 0.0;     // the held-out mean-square gain, V^2
  double lower = 0.0;    // its block-bootstrap 5 % quantile, V^2
};

// What fitting a candidate's held-out values (the mains' windows) would take from white noise
// alone: heldout_values / n of its variance, charged against every gain it makes.
double chance_gain(const Candidate& c, const Selection& selection) {
  if (!c.free_shape || c.free_shape->heldout_values == 0) return 0.0;
  return selection.sigma * selection.sigma * c.free_shape->heldout_values /
         static_cast<double>(std::max<std::size_t>(c.heldout_error.size(), 1));
}

// The held-out mean-square gain of candidate `c` over what the selection leaves now.
double gain_of(const Candidate& c, const Selection& selection) {
  const double now = rms_of(selection.current_error), after = rms_of(c.heldout_error);
  return now * now - after * after - chance_gain(c, selection);
}

// Candidate `index` as a pick: its gain and the gain's block-bootstrap 5 % quantile.
Pick pick_of(const std::vector<Candidate>& candidates, std::size_t index,
             const Selection& selection) {
  Pick pick;
  pick.best = index;
  pick.gain = gain_of(candidates[index], selection);
  const std::vector<double> now = selection.resamples.mean_squares(selection.current_error);
  const std::vector<double> after =
      selection.resamples.mean_squares(candidates[index].heldout_error);
  std::vector<double> gains;
  for (std::size_t r = 0; r < now.size(); ++r) {
    gains.push_back(now[r] - after[r] - chance_gain(candidates[index], selection));
  }
  pick.lower = quantile(gains, 0.05);
  return pick;
}

// How many values a candidate's calibration fit chose.
int free_values_of(const Candidate& c) {
  return c.free_shape ? c.free_shape->free_values
                      : static_cast<int>(fitted_keys(c.fit.settings.name).size());
}

// The candidate that lowers the held-out mean square most, with its gain and the gain's
// block-bootstrap 5 % quantile. When the free shapes compete (the second pass), the fewest values
// win among those within the least gain a pick must make of the best (kMinGainOfNoiseVariance of
// sigma^2): a family with more freedom must earn it on held-out data (issue 11 item 2).
Pick best_candidate(const std::vector<Candidate>& candidates, const Selection& selection) {
  std::size_t best = 0;
  double best_gain = -std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (gain_of(candidates[c], selection) > best_gain) {
      best_gain = gain_of(candidates[c], selection);
      best = c;
    }
  }
  if (selection.free_shapes) {
    const double margin = kMinGainOfNoiseVariance * selection.sigma * selection.sigma;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      if (gain_of(candidates[c], selection) >= best_gain - margin &&
          free_values_of(candidates[c]) < free_values_of(candidates[best])) {
        best = c;
      }
    }
  }
  return pick_of(candidates, best, selection);
}

// When the best candidate is a free shape whose library formula fits as well, the library one.
// "As well": what the free curve gains over the library's formula on held-out data is below the
// least gain a pick must make (kMinGainOfNoiseVariance of sigma^2), so the shape's departure is
// not significant by the selection's own measure.
Pick prefer_library_formula(const std::vector<Candidate>& candidates, Pick pick,
                            const Selection& selection) {
  const Candidate& best = candidates[pick.best];
  if (!best.free_shape) return pick;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (candidates[c].free_shape || candidates[c].fit.settings.name != best.fit.settings.name) {
      continue;
    }
    const double sigma = selection.sigma;
    if (pick.gain - gain_of(candidates[c], selection) < kMinGainOfNoiseVariance * sigma * sigma) {
      return pick_of(candidates, c, selection);
    }
  }
  return pick;
}

// A gain is significant when it is a real share of the noise variance (for a first pick where no
// noise-type class shows, first_pick_least_gain; else kMinGainOfNoiseVariance) and its
// block-bootstrap 95 % lower bound is above zero.
bool significant(const Pick& pick, const Selection& selection) {
  const double sigma = selection.sigma;
  const double least = selection.steps.empty() && !selection.noise_type_before_picks
                           ? selection.first_pick_least_gain
                           : kMinGainOfNoiseVariance * sigma * sigma;
  return pick.gain >= least && pick.lower > 0.0;
}

// The least gain a first pick must make, from the data at hand (issue 11 item 3): each
// candidate's held-out prediction (what it takes off the gap) scored against the held-out gap
// circularly shifted by kChanceShifts lags spread over its middle 80 %. Shifted, the gap keeps its
// own level, spectrum and slow structure, but no longer lines up with what the candidates
// predict; the best candidate's gain at a lag is what the best of them gains by chance, and the
// largest over the lags is the least gain, kept between kLeastFirstGainOfNoiseVariance and
// kMinFirstGainOfNoiseVariance of sigma^2. A gap too short to shift keeps the larger.
double first_pick_least_gain(const std::vector<Candidate>& candidates, const Selection& selection) {
  const double variance = selection.sigma * selection.sigma;
  const std::vector<double>& gap = selection.current_error;
  const std::size_t n = gap.size();
  if (n < 10 * kChanceShifts) return kMinFirstGainOfNoiseVariance * variance;
  std::vector<double> best_at_lag(kChanceShifts, -std::numeric_limits<double>::infinity());
  for (const Candidate& c : candidates) {
    double own = 0.0;  // the prediction's own sum of squares, the same at every lag
    for (std::size_t i = 0; i < n; ++i) own += std::pow(gap[i] - c.heldout_error[i], 2);
    for (std::size_t k = 0; k < kChanceShifts; ++k) {
      const std::size_t lag = n / 10 + k * (8 * n / 10) / (kChanceShifts - 1);
      double dot = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = i + lag < n ? i + lag : i + lag - n;
        dot += gap[j] * (gap[i] - c.heldout_error[i]);
      }
      best_at_lag[k] = std::max(
          best_at_lag[k], (2.0 * dot - own) / static_cast<double>(n) - chance_gain(c, selection));
    }
  }
  const double chance = *std::max_element(best_at_lag.begin(), best_at_lag.end());
  return std::clamp(chance, kLeastFirstGainOfNoiseVariance * variance,
                    kMinFirstGainOfNoiseVariance * variance);
}

// The finding for a picked candidate: its fit and how far it shrinks the held-out gap.
EffectFinding finding_for_pick(const Candidate& chosen, const Pick& pick,
                               const std::vector<double>& current_error) {
  EffectFinding finding;
  finding.name = chosen.fit.settings.name;
  finding.params = chosen.free_shape ? chosen.free_shape->params : chosen.fit.settings.params;
  finding.heldout_rms_before = rms_of(current_error);
  finding.heldout_rms_after = rms_of(chosen.heldout_error);
  finding.shrink_pct =
      100.0 * (finding.heldout_rms_before - finding.heldout_rms_after) / finding.heldout_rms_before;
  finding.evidence = fmt::format(
      "fitted on the calibration part (RMS {:.4g} V); on held-out data it lowers the gap's mean "
      "square by {:.3g} V^2 (bootstrap 95 % lower bound {:.3g})",
      chosen.fit.rms_v, pick.gain, pick.lower);
  if (finding.name == "mains_pickup") {
    finding.noise_type = true;
    finding.evidence += "; a tone: the mains line aliased by the sampling";
  }
  if (chosen.free_shape) {
    finding.evidence += "; not the library's formula: " + chosen.free_shape->description;
  }
  return finding;
}

// For a free-shape pick: how far the library's own formula of the class went in the same round,
// so the report says how the shape departs from it.
void compare_with_library(const std::vector<Candidate>& candidates, const Pick& pick,
                          const Selection& selection, EffectFinding& finding) {
  const Candidate& chosen = candidates[pick.best];
  if (!chosen.free_shape) return;
  for (const Candidate& c : candidates) {
    if (c.free_shape || c.fit.settings.name != chosen.fit.settings.name) continue;
    std::string params;
    for (const auto& [key, value] : c.fit.settings.params) {
      params += fmt::format("{}{}={:.4g}", params.empty() ? "" : ", ", key, value);
    }
    finding.evidence += fmt::format(
        " (the library's formula, best at {}, lowers the held-out mean square by {:.3g} V^2 "
        "only, {:.0f} % of the free curve's)",
        params, gain_of(c, selection), 100.0 * gain_of(c, selection) / std::max(pick.gain, 1e-30));
  }
}

// Adds `sign` times what a free shape adds to the twin's voltage to both parts' free voltages.
void add_free_shape(Selection& selection, const FreeShapeFit& shape, double sign) {
  for (std::size_t i = 0; i < selection.cal_free_v.size(); ++i) {
    selection.cal_free_v[i] += sign * shape.cal_voltage_v[i];
  }
  for (std::size_t i = 0; i < selection.ho_free_v.size(); ++i) {
    selection.ho_free_v[i] += sign * shape.heldout_voltage_v[i];
  }
}

// Takes the library effect at `index` out of `modelled`; the picks' indices into it follow.
void erase_library_effect(Selection& selection, int index) {
  selection.modelled.erase(selection.modelled.begin() + index);
  for (int& other : selection.modelled_index) other -= other > index ? 1 : 0;
}

// Each library pick's finding carries its effect's parameters as last refitted.
void refresh_library_params(Selection& selection) {
  for (std::size_t j = 0; j < selection.findings.size(); ++j) {
    const int index = selection.modelled_index[j];
    if (index >= 0) {
      selection.findings[j].params = selection.modelled[static_cast<std::size_t>(index)].params;
    }
  }
}

// Adds the pick to the model. The earlier findings carry their parameters as refitted with it.
void take_pick(std::vector<Candidate> candidates, const Pick& pick, Selection& selection) {
  const Candidate& chosen = candidates[pick.best];
  EffectFinding finding = finding_for_pick(chosen, pick, selection.current_error);
  compare_with_library(candidates, pick, selection, finding);
  selection.modelled = chosen.with;
  selection.current_error = chosen.heldout_error;
  selection.findings.push_back(finding);
  if (chosen.free_shape) {
    add_free_shape(selection, *chosen.free_shape, 1.0);
    selection.modelled_index.push_back(-1);
  } else {
    selection.modelled_index.push_back(static_cast<int>(selection.modelled.size()) - 1);
  }
  refresh_library_params(selection);
  selection.steps.push_back({std::move(candidates), pick.best});
}

// A deterministic effect in the gap (a mains tone, a lag on the clearance steps) inflates the
// difference-based noise estimate; estimate it again from what the picks leave, kept if lower.
void reestimate_noise(const Parts& parts, Selection& selection, DiagnosisResult& result) {
  DiagnosisDetail& detail = result.detail;
  WhiteNoise left = estimate_white_noise(
      cal_target(parts, selection), parts.cal_replay.voltage(selection.modelled), detail.adc_grid);
  if (left.effective_std_v < selection.sigma) {
    left.source = "re-estimated on the calibration gap the selected effects leave: " + left.source;
    selection.sigma = std::max(left.effective_std_v, 1e-9);
    detail.white_noise = left;
    detail.noise_std_v = selection.sigma;
    detail.noise_source = left.source;
    result.diagnosis.noise_std_v = selection.sigma;
  }
}

// What a class's effect follows, for saying which data would tell two classes apart.
std::string variable_of(const std::string& effect) {
  if (effect == "temp_offset_drift" || effect == "temp_gain_drift") return "the temperature";
  if (effect == "thermal_lag") return "the temperature's rate of change";
  if (effect == "ageing_drift") return "the time";
  if (effect == "channel_skew") return "the clearance's moves";
  if (effect == "mains_pickup") return "the spectrum";
  return "the voltage (clearance)";
}

// When a candidate of another class gains within the least gain a pick must make of the pick's,
// the two are confounded on this protocol: the pick stands, and a sentence says so and which data
// would separate them.
void note_confounding(const std::vector<Candidate>& candidates, const Pick& pick,
                      Selection& selection) {
  const Candidate& chosen = candidates[pick.best];
  const double margin = kMinGainOfNoiseVariance * selection.sigma * selection.sigma;
  std::vector<std::string> alike;
  for (const Candidate& c : candidates) {
    const std::string& name = c.fit.settings.name;
    if (name == chosen.fit.settings.name ||
        std::find(alike.begin(), alike.end(), name) != alike.end()) {
      continue;
    }
    if (gain_of(c, selection) >= pick.gain - margin) alike.push_back(name);
  }
  for (const std::string& other : alike) {
    const std::string a = variable_of(chosen.fit.settings.name), b = variable_of(other);
    selection.confounded.push_back(fmt::format(
        "{} and {} explain the held-out gap alike (within {:.0f} % of the noise variance): "
        "confounded on this protocol; {} is reported, and a session in which {} and {} do not "
        "move together would tell them apart",
        chosen.fit.settings.name, other, 100.0 * kMinGainOfNoiseVariance, chosen.fit.settings.name,
        a, a == b ? "the other's shape" : b));
  }
}

// Greedy selection of bias-type effects, each scored on the held-out part: at most
// kMaxSelected, stopping at the first round whose best candidate is not significant.
void select_bias_effects(const Parts& parts, const DiagnoseOptions& options, Selection& selection,
                         DiagnosisResult& result) {
  selection.current_error = selection.ho_gap;
  selection.resamples =
      BlockResamples(parts.heldout.size(), options.bootstrap_rounds, options.seed);
  selection.first_selected = selection.modelled.size();
  for (int round = 0; round < kMaxSelected; ++round) {
    std::vector<Candidate> candidates = score_candidates(parts, selection);
    if (candidates.empty()) break;
    if (selection.steps.empty() && !selection.noise_type_before_picks) {  // else unused
      selection.first_pick_least_gain = first_pick_least_gain(candidates, selection);
    }
    const Pick pick =
        prefer_library_formula(candidates, best_candidate(candidates, selection), selection);
    if (!significant(pick, selection)) {
      // Nothing significant at all: what came nearest is kept for an "unexplained" verdict.
      if (selection.findings.empty()) {
        selection.nearest_unpicked =
            finding_for_pick(candidates[pick.best], pick, selection.current_error);
      }
      break;
    }
    note_confounding(candidates, pick, selection);
    take_pick(std::move(candidates), pick, selection);
    if (options.estimate_noise) reestimate_noise(parts, selection, result);
  }
}

// Library pick `j` of `selection` given the free shape of its own class that fits best what the
// other picks leave, when that lowers the held-out mean square by the least gain a pick must make
// (after what fitting its held-out values would take from white noise); the library picks are then
// refitted around it.
void give_pick_a_free_shape(const Parts& parts, Selection& selection, std::size_t j) {
  const int index = selection.modelled_index[j];
  if (index < 0) return;
  const std::string name = selection.modelled[static_cast<std::size_t>(index)].name;
  std::vector<sim::EffectSettings> others = selection.modelled;
  others.erase(others.begin() + index);
  const std::vector<double> cal_gap =
      minus(cal_target(parts, selection), parts.cal_replay.voltage(others));
  const std::vector<double> ho_gap =
      minus(ho_target(parts, selection), parts.ho_replay.voltage(others));
  const std::unique_ptr<const CoilParts> coil = coil_parts(parts, others);
  const FreeShapeParts free_parts = free_shape_parts(parts, coil.get());
  const double variance = selection.sigma * selection.sigma;
  const double now = rms_of(selection.current_error);
  // The class's families are fitted in parallel and taken in catalogue order.
  std::vector<std::future<Candidate>> pending;
  for (const FreeShapeFamily& family : free_shape_families()) {
    if (family.effect != name || !weighed_on(family, parts)) continue;
    pending.push_back(std::async(std::launch::async, [&, family] {
      Candidate c;
      c.free_shape = fit_free_shape(family, {{free_parts.calibration, free_parts.cal_replay},
                                             {free_parts.heldout, free_parts.ho_replay},
                                             cal_gap,
                                             ho_gap,
                                             parts.heldout_age_unknown});
      c.heldout_error = minus(ho_gap, c.free_shape->heldout_voltage_v);
      return c;
    }));
  }
  std::optional<Candidate> best;
  double best_ms = now * now - kMinGainOfNoiseVariance * variance;
  for (std::future<Candidate>& fitted : pending) {
    Candidate c = fitted.get();
    if (c.free_shape->family.effect != name) continue;  // it names another class
    const double after = rms_of(c.heldout_error);
    const double ms = after * after + variance * c.free_shape->heldout_values /
                                          static_cast<double>(c.heldout_error.size());
    if (ms < best_ms) {
      best_ms = ms;
      c.fit.settings = sim::make_effect_settings(name, {}, "diagnose free shape");
      c.fit.rms_v = rms_of(minus(cal_gap, c.free_shape->cal_voltage_v));
      best = std::move(c);
    }
  }
  if (!best) return;
  const FreeShapeFit& shape = *best->free_shape;
  erase_library_effect(selection, index);
  selection.modelled_index[j] = -1;
  add_free_shape(selection, shape, 1.0);
  backfit(selection.modelled, selection.first_selected, parts.cal_replay,
          cal_target(parts, selection));
  selection.current_error =
      minus(ho_target(parts, selection), parts.ho_replay.voltage(selection.modelled));
  EffectFinding& finding = selection.findings[j];
  finding.params = shape.params;
  finding.evidence += fmt::format(
      "; given a free shape of its class once the other picks were in (the library's formula "
      "left {:.4g} V of held-out RMS, the free shape {:.4g} V): {}",
      now, rms_of(selection.current_error), shape.description);
  refresh_library_params(selection);
  // Its round now chooses the free shape (the later rounds' scores were made beside the library's
  // formula: measure_inclusion reads the final fit instead for such a selection).
  Step& step = selection.steps[j];
  step.candidates.push_back(std::move(*best));
  step.chosen = step.candidates.size() - 1;
  selection.shapes_refined = true;
}

// The library's classes with free shapes: after the library's pass, each of its picks in turn is
// given the free shape of its own class where that fits what the others leave better
// (give_pick_a_free_shape). The classes stay; their shapes and the library picks' values change.
// A free pass picks its classes greedily, with each free curve fitted before the picks after it
// and never refitted; a class whose shape departs from the library's alongside a second class
// that the library's formula explains was lost there (alternative pair 449/27: a sheathed
// thermocouple, which the library's lag explains, beside a range compression with a linear law
// above its knee, whose free shape the first free round gave to a curve of clearance).
Selection with_free_shapes_of_its_classes(const Parts& parts, const Selection& library) {
  Selection refined = library;
  for (std::size_t j = 0; j < refined.findings.size(); ++j) {
    give_pick_a_free_shape(parts, refined, j);
  }
  return refined;
}

// The library's formulas first; only when what they leave is above the noise, a second pass
// with the free-shape families competing too, kept when it leaves significantly less on held-out
// data. A free curve fitted early is not refitted around later picks, so letting it compete
// from the start would let it take part of an effect the library explains exactly (an offset
// curve of T takes the hysteresis of a thermal lag).
Selection select_in_two_passes(const Parts& parts, const DiagnoseOptions& options,
                               const Selection& start, DiagnosisResult& result) {
  Selection library = start;
  DiagnosisResult library_result = result;
  select_bias_effects(parts, options, library, library_result);
  // The library's classes with shapes of their own, when they leave less: whether or not the
  // library's formulas explained the pair, a shape that departs from them is reported.
  const auto with_shapes_of_its_classes = [&parts](Selection selection) {
    if (selection.findings.empty()) return selection;
    Selection refined = with_free_shapes_of_its_classes(parts, selection);
    const double before = rms_of(selection.current_error), after = rms_of(refined.current_error);
    const double margin = kMinGainOfNoiseVariance * selection.sigma * selection.sigma;
    return before * before - after * after >= margin ? refined : selection;
  };
  const bool several_classes = library.findings.size() > 1;
  const auto explained_by_one_class = [&](const Selection& selection) {
    return rms_of(selection.current_error) <= kExplainedRatio * selection.sigma && !several_classes;
  };
  if (explained_by_one_class(library)) {
    result = std::move(library_result);
    return with_shapes_of_its_classes(std::move(library));
  }
  // The refinement and the free pass do not depend on each other: they run at once, and the
  // refined selection is taken alone when it explains with one class (the free pass then unused).
  std::future<Selection> refining =
      std::async(std::launch::async, with_shapes_of_its_classes, library);
  Selection free = start;
  free.free_shapes = true;
  DiagnosisResult free_result = result;
  select_bias_effects(parts, options, free, free_result);
  library = refining.get();
  if (explained_by_one_class(library)) {
    result = std::move(library_result);
    return library;
  }
  const double left = rms_of(library.current_error);
  const double free_left = rms_of(free.current_error);
  const double sigma = std::min(library.sigma, free.sigma);
  const double margin = kMinGainOfNoiseVariance * sigma * sigma;
  const bool leaves_less = left * left - free_left * free_left >= margin;
  // Fewer classes that leave as little, or that leave the noise too: the library's formulas split
  // between two classes what one class of another shape explains alone (alternative pair 447/13,
  // a temperature gain about a mid-range pivot, which the library's nonlinearity and temperature
  // gain shared, the nonlinearity first). Given free shapes of their own, the library's classes
  // can share it more closely still (449/11, the same effect: a curve of clearance, a gain about a
  // pivot and an offset line left 1.02 sigma, one free gain and a reading lag 1.09 sigma); where
  // both leave the noise, the fewer classes are the explanation.
  const bool both_leave_the_noise =
      left <= kExplainedRatio * sigma && free_left <= kExplainedRatio * sigma;
  const bool fewer_classes = !free.findings.empty() &&
                             free.findings.size() < library.findings.size() &&
                             (free_left * free_left - left * left < margin || both_leave_the_noise);
  if (leaves_less || (several_classes && fewer_classes)) {
    result = std::move(free_result);
    return free;
  }
  result = std::move(library_result);
  return library;
}

// The share of `resamples` on which `step`'s choice still wins and gains over `before`.
double share_of_wins(const Step& step, const std::vector<double>& before,
                     const BlockResamples& resamples) {
  const std::vector<double> base = resamples.mean_squares(before);
  std::vector<std::vector<double>> after;
  for (const Candidate& c : step.candidates)
    after.push_back(resamples.mean_squares(c.heldout_error));
  int wins = 0;
  for (std::size_t r = 0; r < resamples.size(); ++r) {
    std::size_t arg = 0;
    double best = -std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < step.candidates.size(); ++c) {
      const double gain = base[r] - after[c][r];
      if (gain > best) {
        best = gain;
        arg = c;
      }
    }
    if (arg == step.chosen && best > 0.0) ++wins;
  }
  return static_cast<double>(wins) / static_cast<double>(resamples.size());
}

// The held-out gap that the picks marked in `kept` leave (the twin's own effects and the
// converter's placed boundaries always in), each with its parameters from the final fit.
std::vector<double> heldout_error_with(const Parts& parts, const Selection& selection,
                                       const std::vector<bool>& kept) {
  std::vector<double> target = ho_target(parts, selection);
  std::vector<bool> in_library(selection.modelled.size(), true);
  for (std::size_t j = 0; j < kept.size(); ++j) {
    if (kept[j]) continue;
    const int index = selection.modelled_index[j];
    if (index >= 0) {
      in_library[static_cast<std::size_t>(index)] = false;
      continue;
    }
    // A free shape: what it added comes back into the target.
    const Step& step = selection.steps[j];
    const std::vector<double>& added = step.candidates[step.chosen].free_shape->heldout_voltage_v;
    for (std::size_t i = 0; i < target.size(); ++i) target[i] += added[i];
  }
  // The library's effects stay in the order they were fitted in.
  std::vector<sim::EffectSettings> library;
  for (std::size_t m = 0; m < selection.modelled.size(); ++m) {
    if (in_library[m]) library.push_back(selection.modelled[m]);
  }
  return minus(target, parts.ho_replay.voltage(library));
}

// Inclusion: the share of held-out resamples on which each step's choice still wins and gains
// (the fits are not redone per round: it is the scoring that is resampled). Where a pick was given
// a free shape after the rounds, the rounds' scores no longer add up to the final fit: there it is
// the share of resamples on which the final fit without the pick leaves more.
void measure_inclusion(const Parts& parts, Selection& selection) {
  const std::vector<Step>& steps = selection.steps;
  if (selection.shapes_refined) {
    const std::vector<bool> all(selection.findings.size(), true);
    const std::vector<double> with_all =
        selection.resamples.mean_squares(heldout_error_with(parts, selection, all));
    // Each pick's replay and resamples in its own thread (as each round's below).
    std::vector<std::future<double>> shares;
    for (std::size_t j = 0; j < selection.findings.size(); ++j) {
      shares.push_back(std::async(std::launch::async, [&, j] {
        std::vector<bool> kept = all;
        kept[j] = false;
        const std::vector<double> without =
            selection.resamples.mean_squares(heldout_error_with(parts, selection, kept));
        int needed = 0;
        for (std::size_t r = 0; r < without.size(); ++r) needed += without[r] > with_all[r] ? 1 : 0;
        return static_cast<double>(needed) / static_cast<double>(selection.resamples.size());
      }));
    }
    for (std::size_t j = 0; j < shares.size(); ++j)
      selection.findings[j].inclusion = shares[j].get();
    return;
  }
  std::vector<std::future<double>> shares;
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const std::vector<double>& before =
        s == 0 ? selection.ho_gap : steps[s - 1].candidates[steps[s - 1].chosen].heldout_error;
    shares.push_back(std::async(std::launch::async, [&, s] {
      return share_of_wins(steps[s], before, selection.resamples);
    }));
  }
  for (std::size_t s = 0; s < shares.size(); ++s) selection.findings[s].inclusion = shares[s].get();
}

// The held-out gap's RMS with every pick but pick `j`.
double heldout_rms_without(const Parts& parts, const Selection& selection, std::size_t j) {
  std::vector<bool> kept(selection.findings.size(), true);
  kept[j] = false;
  return rms_of(heldout_error_with(parts, selection, kept));
}

// Takes pick `j` out of the selection: its effect or free shape, its finding and its round.
void remove_pick(Selection& selection, std::size_t j) {
  const int index = selection.modelled_index[j];
  if (index >= 0) {
    erase_library_effect(selection, index);
  } else {
    add_free_shape(selection, *selection.steps[j].candidates[selection.steps[j].chosen].free_shape,
                   -1.0);
  }
  const auto at = [j](auto& v) { v.erase(v.begin() + static_cast<long>(j)); };
  at(selection.findings);
  at(selection.steps);
  at(selection.modelled_index);
}

// Backward steps after the greedy forward ones: a pick that the final model does not need (taking
// it out raises the held-out mean square by less than the least gain a pick must make) is taken
// out, the least needed first, until every pick left is needed. A pick taken first for what it
// explained alone can be made redundant by a later one (a static nonlinearity that took the
// calibration part's offset of a log-time ageing, which the refit handed back to the ageing).
// Each one taken out leaves a reason line.
void drop_unneeded_picks(const Parts& parts, Selection& selection) {
  const double margin = kMinGainOfNoiseVariance * selection.sigma * selection.sigma;
  const auto refresh_error = [&] {
    selection.current_error =
        heldout_error_with(parts, selection, std::vector<bool>(selection.findings.size(), true));
  };
  refresh_error();
  while (selection.findings.size() > 1) {
    const double now = rms_of(selection.current_error);
    std::size_t least = 0;
    double least_cost = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < selection.findings.size(); ++j) {
      const double without = heldout_rms_without(parts, selection, j);
      const double cost = without * without - now * now;
      if (cost < least_cost) {
        least_cost = cost;
        least = j;
      }
    }
    if (least_cost >= margin) break;
    selection.dropped.push_back(fmt::format(
        "{} was selected, but the effects selected after it make it unneeded: without it the "
        "held-out gap's mean square changes by {:.3g} V^2, less than the {:.3g} V^2 a pick must "
        "take; not named",
        selection.findings[least].name, least_cost, margin));
    // Its confounding sentences said it was the one reported.
    const std::string lead = selection.findings[least].name + " and ";
    std::erase_if(selection.confounded,
                  [&](const std::string& line) { return line.starts_with(lead); });
    remove_pick(selection, least);
    refresh_error();
  }
}

// Each pick as the final fit has it, in the order the rounds took them: the held-out gap's RMS
// with every pick but this one (what the final model needs it for), and its before and after with
// the picks listed before it (what the refits and the backward steps left of each round's own
// figures). The order stays the greedy one: ranking by that need was tried and named the wrong
// class first as often as the right one, since a constant offset is shared between classes as the
// fits happen to split it (an ageing's offset against a nonlinearity curve's level), and the
// need of each follows that split.
void measure_picks_in_final_fit(const Parts& parts, Selection& selection) {
  const std::size_t picks = selection.findings.size();
  std::vector<bool> kept(picks, false);
  double before = rms_of(selection.ho_gap);
  for (std::size_t k = 0; k < picks; ++k) {
    EffectFinding& f = selection.findings[k];
    f.heldout_rms_without = heldout_rms_without(parts, selection, k);
    kept[k] = true;
    f.heldout_rms_before = before;
    f.heldout_rms_after = rms_of(heldout_error_with(parts, selection, kept));
    f.shrink_pct = 100.0 * (f.heldout_rms_before - f.heldout_rms_after) /
                   std::max(f.heldout_rms_before, 1e-30);
    before = f.heldout_rms_after;
  }
}

std::string grid_evidence(const AdcGrid& grid) {
  return fmt::format(
      "the recorded voltages of both parts lie on one converter grid (estimated from their "
      "spacing): LSB {:.4g} mV, codes {:.6g} to {:.6g} V ({} of {} used, {:.1f} % of samples on "
      "it); {}",
      1e3 * grid.lsb_v, grid.lowest_v, grid.highest_v, grid.codes_used, grid.codes_spanned,
      100.0 * grid.share_on_grid,
      grid.usual_range
          ? fmt::format("the {}-bit grid of the [{}, {}] V range", grid.bits, grid.v_min,
                        grid.v_max)
          : fmt::format("modelled as a {}-bit converter from {:.6g} V", grid.bits, grid.v_min));
}

// adc_quantization, recognised when the voltages of both parts lie on one converter grid. The
// twin's converter on that grid is kept when it reproduces the recorded codes (what it leaves
// is within what the noise alone would leave); when it does not (the thresholds sit elsewhere:
// a truncating converter, a gain or offset calibration in the DAQ software), the quantisation is
// taken as noise of LSB / sqrt(12), which the effective white noise already holds.
void recognise_quantization(const Parts& parts, const WhiteNoise& white, Selection& selection) {
  const std::optional<AdcGrid>& grid = parts.grid;
  if (!grid) return;
  EffectFinding finding;
  finding.name = "adc_quantization";
  finding.params = grid->as_effect().params;
  finding.params["lsb_v"] = grid->lsb_v;
  finding.noise_type = true;
  finding.inclusion = 1.0;
  finding.evidence = grid_evidence(*grid);
  sim::EffectSettings converter = grid->as_effect();
  finding.heldout_rms_before = rms_of(selection.current_error);
  // With the boundaries placed first, their offset is in the targets; the converter replayed
  // here carries it instead, so it comes out of them.
  std::vector<double> target = ho_target(parts, selection);
  if (selection.converter_threshold_lsb) {
    const double threshold = *selection.converter_threshold_lsb;
    converter.params["threshold_lsb"] = threshold;
    finding.params["threshold_lsb"] = threshold;
    finding.heldout_rms_before = rms_of(selection.raw_ho_gap);
    finding.evidence += fmt::format(
        "; its code boundaries sit {:.2f} LSB from rounding's ({}), which offsets the twin's "
        "voltage by {:.4g} V: placed on the calibration part before any effect was fitted (the "
        "held-out gap RMS {:.4g} -> {:.4g} V by that offset alone)",
        threshold, std::abs(threshold) >= 0.4 ? "a truncating converter" : "not rounding's",
        selection.converter_offset_v, rms_of(selection.raw_ho_gap), rms_of(selection.ho_gap));
    if (selection.converter_gain) {
      finding.params["calibration_gain"] = *selection.converter_gain;
      finding.params["calibration_offset_v"] = selection.converter_gain_offset_v;
      finding.evidence += fmt::format(
          "; with it, the DAQ software's gain calibration that the grid's spacing shows ({:.5g} "
          "times a usual range's LSB): the recorded voltage is {:.5g} times the twin's {:+.4g} V "
          "(in that held-out figure too)",
          *selection.converter_gain, *selection.converter_gain, selection.converter_gain_offset_v);
    }
    for (double& v : target) v += selection.converter_offset_v;
  }
  std::vector<sim::EffectSettings> with = selection.modelled;
  with.push_back(converter);
  std::vector<double> replayed = minus(target, parts.ho_replay.voltage(with));
  const double null_rms = quantised_null_rms(white.analog_std_v, grid->lsb_v);
  if (rms_of(replayed) <= kExplainedRatio * null_rms) {
    selection.current_error = std::move(replayed);
    selection.modelled = with;
    for (double& v : selection.cal_free_v) v -= selection.converter_offset_v;
    for (double& v : selection.ho_free_v) v -= selection.converter_offset_v;
    selection.converter_offset_v = 0.0;
  } else {
    selection.quantisation_as_noise = true;
    finding.evidence += fmt::format(
        "; the twin's converter on it does not reproduce the recorded codes ({:.4g} V left where "
        "the noise alone leaves {:.4g} V: the thresholds sit elsewhere), so the quantisation is "
        "taken as noise of LSB / sqrt(12) = {:.4g} V",
        rms_of(replayed), null_rms, grid->lsb_v / std::sqrt(12.0));
  }
  // Its own shrink: with the boundaries placed first, what placing them took off the held-out gap
  // (the picks after them are theirs); else what the converter's replay takes.
  finding.heldout_rms_after = selection.converter_threshold_lsb ? rms_of(selection.ho_gap)
                                                                : rms_of(selection.current_error);
  finding.shrink_pct = 100.0 * (finding.heldout_rms_before - finding.heldout_rms_after) /
                       std::max(finding.heldout_rms_before, 1e-30);
  // Findings are listed largest first. The picks are in the order the rounds took them, each
  // taking sqrt(before^2 - after^2) of the held-out gap's RMS; the converter's size
  // is what its rounding puts in the gap, LSB / sqrt(12), which the grid itself shows whether or
  // not the twin's converter reproduces the codes.
  const double rounding_rms = grid->lsb_v / std::sqrt(12.0);
  const auto smaller = std::find_if(
      selection.findings.begin(), selection.findings.end(), [&](const EffectFinding& f) {
        return rms_above_noise(f.heldout_rms_before, f.heldout_rms_after) < rounding_rms;
      });
  selection.findings.insert(smaller, finding);
  selection.quantised_on = grid;
}

// The share of `resamples` of the held-out gap on which the vibration signature still shows.
double vibration_inclusion(const std::vector<double>& gap, const TwinReplay& replay,
                           const RecordingSeries& series, const BlockResamples& resamples) {
  int shows = 0;
  for (std::size_t r = 0; r < resamples.size(); ++r) {
    std::vector<double> gap_drawn, sens_drawn, clearance_drawn;
    for (std::size_t i : resamples.indices(r)) {
      gap_drawn.push_back(gap[i]);
      sens_drawn.push_back(replay.sensitivity_v_per_mm()[i]);
      clearance_drawn.push_back(series.clearance_mm[i]);
    }
    if (vibration_signature(gap_drawn, sens_drawn, clearance_drawn).present) ++shows;
  }
  return static_cast<double>(shows) / static_cast<double>(resamples.size());
}

// The motion's mean square in mm^2 on a part, from what is left there, regressed over the whole
// part: the squared departures from its mean against the sensitivity squared, E = a + b (dV/dd)^2,
// b. The signature's levels are taken about a moving mean of 49 samples, which takes with it the
// part of the motion that the sampling aliases below about 0.1 Hz (a narrow resonance near a
// multiple of fs: alternative pair 440/1, 26.6 Hz at 9 Hz, whose motion the levels put at 60 % of
// its variance). Over the part a slow bias left by the picks would count as motion too, so this
// counts only when the regression splits what is left into the noise and the motion: a, the part
// not following the sensitivity, between half the noise variance and `white_allowed` squared
// (440/1: 0.76 and 0.99 times sigma^2 on its two parts). A hysteresis that the picks left, whose
// size grows faster than (dV/dd)^2, gave a < 0 (alternative outside pair 436/39). 0 otherwise.
double motion_mean_square_over_part(const std::vector<double>& left,
                                    const std::vector<double>& sensitivity_v_per_mm, double sigma,
                                    double white_allowed) {
  const double mean = mean_of(left);
  std::vector<double> departure_sq(left.size()), s2(left.size());
  for (std::size_t i = 0; i < left.size(); ++i) {
    departure_sq[i] = std::pow(left[i] - mean, 2);
    s2[i] = std::pow(sensitivity_v_per_mm[i], 2);
  }
  const LineFit fit = line_fit(s2, departure_sq);
  const bool noise_beside =
      fit.intercept >= 0.5 * sigma * sigma && fit.intercept <= white_allowed * white_allowed;
  return fit.fitted && fit.slope > 0.0 && noise_beside ? fit.slope : 0.0;
}

// vibration, recognised from its signature in both parts. Returns the noise the verdict
// compares what is left with: the white voltage noise, or, with mount motion found, that plus
// the motion's share, whose variance follows the sensitivity and so escapes the median-based
// estimate: the held-out gap's mean squared difference / 2.
VerdictNoise recognise_vibration(const Parts& parts, Selection& selection) {
  const std::vector<double>& current_error = selection.current_error;
  const std::vector<double> cal_after =
      minus(cal_target(parts, selection), parts.cal_replay.voltage(selection.modelled));
  const VibrationSignature cal_vibration = vibration_signature(
      cal_after, parts.cal_replay.sensitivity_v_per_mm(), parts.calibration.clearance_mm);
  const VibrationSignature ho_vibration = vibration_signature(
      current_error, parts.ho_replay.sensitivity_v_per_mm(), parts.heldout.clearance_mm);
  const double sigma = selection.sigma;
  if (!cal_vibration.present || !ho_vibration.present) return {sigma, ""};
  // The mean squared difference over the pairs the signature took (at rest, where it rests).
  const std::vector<bool> rest = pairs_at_rest(parts.heldout.clearance_mm);
  double sum = 0.0;
  std::size_t pairs = 0;
  for (std::size_t i = 0; i + 1 < current_error.size(); ++i) {
    if (!rest.empty() && !rest[i]) continue;
    sum += std::pow(current_error[i + 1] - current_error[i], 2);
    ++pairs;
  }
  // The motion's own variance on the held-out part, (rms_mm dV/dd)^2 on average, beside the white
  // noise: motion whose aliases fall low escapes the differences. rms_mm^2 is the signature's or,
  // where larger, the mean square over the whole parts; the same mount shakes both, so the smaller
  // of those two counts, and what a pick's shape misses on one part alone does not pass for motion.
  const double session_mean_square_mm2 =
      std::min(motion_mean_square_over_part(cal_after, parts.cal_replay.sensitivity_v_per_mm(),
                                            sigma, kExplainedRatio * sigma),
               motion_mean_square_over_part(current_error, parts.ho_replay.sensitivity_v_per_mm(),
                                            sigma, kExplainedRatio * sigma));
  const double motion_mean_square_mm2 =
      std::max(ho_vibration.rms_mm * ho_vibration.rms_mm, session_mean_square_mm2);
  double mean_sensitivity_sq = 0.0;
  for (const double s : parts.ho_replay.sensitivity_v_per_mm()) mean_sensitivity_sq += s * s;
  mean_sensitivity_sq /= static_cast<double>(std::max<std::size_t>(current_error.size(), 1));
  const double motion_variance = motion_mean_square_mm2 * mean_sensitivity_sq;
  const double verdict_noise =
      std::max({sigma, std::sqrt(0.5 * sum / static_cast<double>(std::max<std::size_t>(pairs, 1))),
                std::sqrt(sigma * sigma + motion_variance)});
  EffectFinding finding;
  finding.name = "vibration";
  finding.params = {{"rms_mm", cal_vibration.rms_mm}};
  finding.noise_type = true;
  finding.heldout_rms_before = finding.heldout_rms_after = rms_of(current_error);
  finding.inclusion =
      vibration_inclusion(current_error, parts.ho_replay, parts.heldout, selection.resamples);
  finding.evidence = fmt::format(
      "the gap's sample-to-sample variance grows with the sensor's sensitivity squared "
      "(t = {:.1f} calibration, {:.1f} held-out): clearance motion, not voltage noise; "
      "random phases cannot be fitted, so it adds no shrink (held-out rms_mm {:.3g})",
      cal_vibration.slope_t, ho_vibration.slope_t, ho_vibration.rms_mm);
  selection.findings.push_back(finding);
  if (verdict_noise <= sigma) return {sigma, ""};
  return {verdict_noise,
          fmt::format("with the mount motion, the noise what is left is compared with is {:.4g} V "
                      "(the larger of the held-out gap's mean squared difference / 2 and the white "
                      "noise plus the motion's variance through dV/dd), not the white {:.4g} V",
                      verdict_noise, sigma)};
}

// With the converter's grid modelled, what is left is compared with what the noisy twin leaves
// once quantised on that grid (quantised_noise.h): less than the white noise when the noise is
// below the LSB, sqrt(sigma^2 + LSB^2 / 6) when it is far above.
VerdictNoise with_converter_grid(const Selection& selection, const WhiteNoise& white,
                                 VerdictNoise noise) {
  if (!selection.quantised_on) return noise;
  if (selection.quantisation_as_noise) {
    const std::string why = fmt::format(
        "the quantisation taken as noise: what is left is compared with the white noise with the "
        "grid's LSB^2/12 in it ({:.4g} V)",
        white.effective_std_v);
    return {noise.rms_v, noise.why.empty() ? why : noise.why + "; " + why};
  }
  const double null_rms = quantised_null_rms(white.analog_std_v, selection.quantised_on->lsb_v);
  const std::string why = fmt::format(
      "with the converter grid modelled, what is left is compared with {:.4g} V: what quantising "
      "the twin with {:.4g} V of analog noise on the {:.4g} mV grid leaves",
      null_rms, white.analog_std_v, 1e3 * selection.quantised_on->lsb_v);
  if (noise.why.empty()) return {null_rms, why};
  return null_rms > noise.rms_v ? VerdictNoise{null_rms, noise.why + "; " + why} : noise;
}

// What may be left in any one window of the held-out session (worst_window): twice the noise; with
// the converter's grid modelled, at least LSB / sqrt(2). Below the LSB the noise does not spread
// evenly over the code boundaries: a signal that dwells on a boundary for a window flips between
// two codes at random, half the time off the twin's one code, whatever the noise (alternative pair
// 452/14, a 6-bit converter with 0.013 V of noise on a staircase: 0.12 V left over one 64th of
// the session, where twice the 0.054 V the grid leaves on average allowed 0.109 V).
double local_allowance(const Selection& selection, double verdict_noise) {
  const double allowance = kLocalExplainedRatio * verdict_noise;
  if (!selection.quantised_on || selection.quantisation_as_noise) return allowance;
  return std::max(allowance, selection.quantised_on->lsb_v / std::numbers::sqrt2);
}

// What the selected effects leave, against what the noise allows: over the held-out session, or,
// when that is within it, in the window where the most is left.
std::string what_is_left(const Selection& selection, double verdict_noise,
                         const HeldoutWindow& worst) {
  const double left_v = rms_of(selection.current_error);
  if (left_v > kExplainedRatio * verdict_noise) {
    return fmt::format("{:.4g} V is left where the noise allows {:.4g} V", left_v,
                       kExplainedRatio * verdict_noise);
  }
  return fmt::format(
      "{:.4g} V is left over the session, within the {:.4g} V the noise allows, but {:.4g} V "
      "from {:.1f} to {:.1f} s, where it allows {:.4g} V",
      left_v, kExplainedRatio * verdict_noise, worst.rms_v, worst.from_s, worst.to_s,
      local_allowance(selection, verdict_noise));
}

// The library effect an "unexplained" verdict came nearest to: the first it selected, or, when
// none was significant, the candidate that lowered the held-out gap most; with how far it went.
std::optional<EffectFinding> nearest_effect(const Selection& selection, double verdict_noise,
                                            const HeldoutWindow& worst) {
  const bool picked = !selection.findings.empty();
  if (!picked && !selection.nearest_unpicked) return std::nullopt;
  EffectFinding nearest = picked ? selection.findings.front() : *selection.nearest_unpicked;
  const std::string how_much_is_left = what_is_left(selection, verdict_noise, worst);
  nearest.evidence =
      fmt::format("{}: it takes the held-out gap RMS from {:.4g} to {:.4g} V ({:.1f} %){}; {}",
                  picked ? "selected, but the effects selected leave too much"
                         : "the nearest candidate, not significant",
                  nearest.heldout_rms_before, nearest.heldout_rms_after, nearest.shrink_pct,
                  picked && selection.findings.size() > 1 ? " on its own" : "", how_much_is_left);
  return nearest;
}

// The share of a gap's RMS above `noise` that the selected effects take: from `rms_before` to
// `rms_after`.
double above_noise_share_taken(double rms_before, double rms_after, double noise) {
  const double before = rms_above_noise(rms_before, noise);
  if (before <= 0.0) return 0.0;
  return 1.0 - rms_above_noise(rms_after, noise) / before;
}

// The held-out samples whose clearance and temperature lie within the calibration part's ranges,
// in time order: where the fitted curves are interpolated, not continued or held.
struct CalibrationReach {
  double temp_lo_c = 0.0, temp_hi_c = 0.0, clearance_lo_mm = 0.0, clearance_hi_mm = 0.0;
  std::vector<std::size_t> heldout_within;
  std::vector<std::size_t> heldout_beyond;  // the others
};

CalibrationReach calibration_reach(const RecordingSeries& calibration,
                                   const RecordingSeries& heldout) {
  CalibrationReach reach;
  const auto [t_lo, t_hi] =
      std::minmax_element(calibration.temp_c.begin(), calibration.temp_c.end());
  const auto [x_lo, x_hi] =
      std::minmax_element(calibration.clearance_mm.begin(), calibration.clearance_mm.end());
  reach = {*t_lo, *t_hi, *x_lo, *x_hi, {}, {}};
  for (std::size_t i = 0; i < heldout.size(); ++i) {
    const bool within = heldout.temp_c[i] >= reach.temp_lo_c &&
                        heldout.temp_c[i] <= reach.temp_hi_c &&
                        heldout.clearance_mm[i] >= reach.clearance_lo_mm &&
                        heldout.clearance_mm[i] <= reach.clearance_hi_mm;
    (within ? reach.heldout_within : reach.heldout_beyond).push_back(i);
  }
  return reach;
}

double rms_at(const std::vector<double>& values, std::span<const std::size_t> at) {
  double sum_sq = 0.0;
  for (std::size_t i : at) sum_sq += values[i] * values[i];
  return at.empty() ? 0.0 : std::sqrt(sum_sq / static_cast<double>(at.size()));
}

// The held-out window where what is left has the largest RMS. The windows split the held-out
// samples within the calibration's reach (a 64th of them, at least 100): beyond those ranges a
// curve is continued or held, and what it leaves there says how well it guessed, not that
// something else is there (alternative pair 409/5: a range compression fitted up to 78 C left 2.2
// times the noise where the held-out session heated to 87 C, and the class was right).
HeldoutWindow worst_window(const RecordingSeries& heldout, const CalibrationReach& reach,
                           const std::vector<double>& error) {
  const std::vector<std::size_t>& within = reach.heldout_within;
  const std::size_t n = within.size();
  const std::size_t length = std::max(n / kLocalWindows, kLeastLocalWindowSamples);
  HeldoutWindow worst;
  for (std::size_t begin = 0; begin + length <= n; begin += length) {
    const auto window = std::span(within).subspan(begin, length);
    const double rms = rms_at(error, window);
    if (rms > worst.rms_v) worst = {heldout.t_s[window.front()], heldout.t_s[window.back()], rms};
  }
  return worst;
}

// The share of the gap's RMS above `noise` on the held-out samples `at` that the selected effects
// take.
double above_noise_share_taken_at(const Selection& selection, std::span<const std::size_t> at,
                                  double noise) {
  return above_noise_share_taken(rms_at(selection.raw_ho_gap, at),
                                 rms_at(selection.current_error, at), noise);
}

// Why an "explained" holds where the calibration reaches and what is left beyond it, where the
// selected effects take `beyond_share` of the gap above the noise.
std::string beyond_reach_reason(const RecordingSeries& heldout, const CalibrationReach& reach,
                                const Selection& selection, double beyond_share) {
  const auto [t_lo, t_hi] = std::minmax_element(heldout.temp_c.begin(), heldout.temp_c.end());
  const auto [x_lo, x_hi] =
      std::minmax_element(heldout.clearance_mm.begin(), heldout.clearance_mm.end());
  return fmt::format(
      "what is left is within {:.0f} % of the noise on the {} held-out samples within the "
      "calibration's ranges ({:.1f}-{:.1f} C, {:.2f}-{:.2f} mm): {:.4g} V; the other {} lie "
      "beyond them (the held-out part spans {:.1f}-{:.1f} C, {:.2f}-{:.2f} mm), where the fitted "
      "curves are continued past what they were fitted on: they take {:.0f} % of the gap above "
      "the noise there and leave {:.4g} V; a calibration session that reaches there would tell "
      "their shape",
      100.0 * (kExplainedRatio - 1.0), reach.heldout_within.size(), reach.temp_lo_c,
      reach.temp_hi_c, reach.clearance_lo_mm, reach.clearance_hi_mm,
      rms_at(selection.current_error, reach.heldout_within), reach.heldout_beyond.size(), *t_lo,
      *t_hi, *x_lo, *x_hi, 100.0 * beyond_share,
      rms_at(selection.current_error, reach.heldout_beyond));
}

// The status ("explained", "partly explained", "unexplained" or "none") and the reasons for it.
void verdict(const Parts& parts, const Selection& selection, const VerdictNoise& noise,
             DiagnosisResult& result) {
  const double verdict_noise = noise.rms_v;
  Diagnosis& diagnosis = result.diagnosis;
  const std::vector<EffectFinding>& findings = selection.findings;
  const double sigma = selection.sigma;
  diagnosis.heldout_rms_before = rms_of(selection.raw_ho_gap);
  diagnosis.heldout_rms_after = rms_of(selection.current_error);
  const bool has_noise_type =
      std::any_of(findings.begin(), findings.end(),
                  [](const EffectFinding& f) { return f.noise_type && f.name != "mains_pickup"; });
  const bool gap_exists = diagnosis.heldout_rms_before > kGapRatio * sigma ||
                          !diagnosis.stage.empty() || has_noise_type || !findings.empty();
  const CalibrationReach reach = calibration_reach(parts.calibration, parts.heldout);
  const HeldoutWindow worst = worst_window(parts.heldout, reach, selection.current_error);
  HowFar& how = result.detail.how_far;
  how.worst_window = worst;
  how.within_calibration_samples = reach.heldout_within.size();
  how.within_calibration_rms_before = rms_at(selection.raw_ho_gap, reach.heldout_within);
  how.within_calibration_rms_after = rms_at(selection.current_error, reach.heldout_within);
  const bool left_within_noise_overall =
      diagnosis.heldout_rms_after <= kExplainedRatio * verdict_noise;
  const bool left_within_noise_locally = worst.rms_v <= local_allowance(selection, verdict_noise);
  const bool left_within_noise = left_within_noise_overall && left_within_noise_locally;
  // Explained where the calibration reaches: enough held-out samples lie within its ranges, the
  // gap stands above the noise there, and what is left there is within the noise, overall and in
  // every window; what is left beyond is a curve continued past what it was fitted on, which must
  // take the more of the gap there the more of the session lies there.
  const double beyond_share =
      above_noise_share_taken_at(selection, reach.heldout_beyond, verdict_noise);
  const double share_within = static_cast<double>(reach.heldout_within.size()) /
                              static_cast<double>(selection.current_error.size());
  const bool explained_within_reach =
      !left_within_noise_overall && left_within_noise_locally &&
      share_within >= kLeastShareWithinReach &&
      how.within_calibration_rms_before > kGapRatio * verdict_noise &&
      how.within_calibration_rms_after <= kExplainedRatio * verdict_noise &&
      beyond_share >= std::max(kLeastShareTakenBeyondReach, 1.0 - share_within);
  auto& reasons = result.detail.reasons;
  reasons.push_back(fmt::format(
      "held-out gap RMS {:.4g} V before, {:.4g} V after the selected effects; white noise {:.4g} V",
      diagnosis.heldout_rms_before, diagnosis.heldout_rms_after, sigma));
  if (!noise.why.empty()) reasons.push_back(noise.why);
  if (!findings.empty() && left_within_noise_overall && !left_within_noise) {
    reasons.push_back(fmt::format(
        "what is left is within {:.0f} % of the noise over the held-out session, but {:.2f} times "
        "the noise from {:.1f} to {:.1f} s (at most {:.2f} times is asked in every {}th of it): "
        "the selected effects miss something there",
        100.0 * (kExplainedRatio - 1.0), worst.rms_v / verdict_noise, worst.from_s, worst.to_s,
        local_allowance(selection, verdict_noise) / verdict_noise, kLocalWindows));
  }
  if (!findings.empty() && left_within_noise) {
    diagnosis.status = "explained";
    diagnosis.effects = findings;
    reasons.push_back(fmt::format("what is left is within {:.0f} % of the noise",
                                  100.0 * (kExplainedRatio - 1.0)));
  } else if (!findings.empty() && explained_within_reach) {
    diagnosis.status = "explained";
    diagnosis.effects = findings;
    reasons.push_back(beyond_reach_reason(parts.heldout, reach, selection, beyond_share));
  } else if (const double share = above_noise_share_taken(
                 diagnosis.heldout_rms_before, diagnosis.heldout_rms_after, verdict_noise);
             !findings.empty() && share >= kPartlyExplainedShare) {
    diagnosis.status = "partly explained";
    diagnosis.effects = findings;
    reasons.push_back(fmt::format(
        "the selected effects take {:.1f} % of the held-out gap above the noise (at least {:.0f} "
        "% is asked), but {}: the rest is outside the library or of a shape its families miss",
        100.0 * share, 100.0 * kPartlyExplainedShare,
        what_is_left(selection, verdict_noise, worst)));
  } else if (gap_exists) {
    diagnosis.status = "unexplained";
    result.detail.partial = findings;
    diagnosis.nearest = nearest_effect(selection, verdict_noise, worst);
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
  if (diagnosis.status != "none") {
    reasons.insert(reasons.end(), selection.confounded.begin(), selection.confounded.end());
    reasons.insert(reasons.end(), selection.dropped.begin(), selection.dropped.end());
  }
  if (diagnosis.stage.empty()) diagnosis.stage = "none";
}

// How far, on held-out data: overall, in the where-cell and in the where-band; and the
// held-out traces before and after.
void measure_how_far(const RecordingSeries& heldout, const Selection& selection,
                     DiagnosisResult& result) {
  DiagnosisDetail& detail = result.detail;
  const std::vector<double>& ho_gap = selection.raw_ho_gap;
  const std::vector<double>& current_error = selection.current_error;
  HowFar& how = detail.how_far;
  how.rms_before = result.diagnosis.heldout_rms_before;
  how.rms_after = result.diagnosis.heldout_rms_after;
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
    how.region_samples = before.size();
  }
  if (detail.band_hz) {
    const std::size_t segment = spectrum_segment(heldout.size());
    how.band_rms_before = band_rms(welch_psd(ho_gap, detail.fs_hz, segment), *detail.band_hz);
    how.band_rms_after = band_rms(welch_psd(current_error, detail.fs_hz, segment), *detail.band_hz);
  }
  detail.heldout_t_s = heldout.t_s;
  detail.heldout_gap_before_v = ho_gap;
  detail.heldout_gap_after_v = current_error;
}

// When the held-out part barely enters the cell where the calibration gap stands out most, it can
// neither confirm nor refute what lies there (a held-out session that does not heat as far): the
// reason says so, and which data would.
std::optional<std::string> coverage_reason(const DiagnosisResult& result) {
  const DiagnosisDetail& detail = result.detail;
  if (result.diagnosis.status == "none" || !detail.where_region ||
      detail.how_far.region_samples >= kMinCellSamples) {
    return std::nullopt;
  }
  const RegionCell& cell = detail.regions[*detail.where_region];
  return fmt::format(
      "the held-out part has {} samples in the cell where the calibration gap stands out most "
      "({:.2f}-{:.2f} mm x {:.1f}-{:.1f} C, bias {:.4g} V, {} calibration samples): it can neither "
      "confirm nor refute what lies there; a held-out session that reaches that clearance and "
      "temperature would",
      detail.how_far.region_samples, cell.clearance_lo, cell.clearance_hi, cell.temp_lo,
      cell.temp_hi, cell.bias_v, cell.n);
}

}  // namespace

double rms_above_noise(double rms, double noise) {
  return std::sqrt(std::max(0.0, rms * rms - noise * noise));
}

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
  const double fs_hz = shared_sample_rate_hz(calibration, heldout);
  sim::check_twin_config(options.twin);

  DiagnosisResult result;
  result.detail.fs_hz = fs_hz;
  const SessionClock clock = session_clock(calibration, heldout);
  result.diagnosis.clock = clock.kind;
  if (clock.kind != "unknown") result.diagnosis.heldout_starts_after_s = clock.age_offset_s;
  // The held-out replay and the grid search beside the calibration replay: each inverts or
  // scans a whole record.
  auto ho_replay = std::async(std::launch::async, [&] {
    return TwinReplay(heldout, options.twin.nominal, clock.age_offset_s);
  });
  auto grid = std::async(std::launch::async, [&] { return shared_grid(calibration, heldout); });
  const Parts parts{calibration,
                    heldout,
                    TwinReplay(calibration, options.twin.nominal),
                    ho_replay.get(),
                    clock.kind == "unknown",
                    grid.get(),
                    std::make_shared<LibraryRounds>()};
  Selection selection =
      select_in_two_passes(parts, options, replay_nominal_twin(parts, options, result), result);
  measure_inclusion(parts, selection);
  drop_unneeded_picks(parts, selection);
  measure_picks_in_final_fit(parts, selection);
  // Noise-type effects, recognised from their signatures in both parts.
  recognise_quantization(parts, result.detail.white_noise, selection);
  const VerdictNoise verdict_noise = with_converter_grid(selection, result.detail.white_noise,
                                                         recognise_vibration(parts, selection));
  verdict(parts, selection, verdict_noise, result);
  if (auto why = clock_reason(result.diagnosis, result.detail.partial)) {
    result.detail.reasons.push_back(*why);
  }
  if (auto why = one_sided_protocol_reason(result.diagnosis, calibration, heldout)) {
    result.detail.reasons.push_back(*why);
  }
  measure_how_far(heldout, selection, result);
  if (auto why = coverage_reason(result)) result.detail.reasons.push_back(*why);
  return result;
}

Diagnosis diagnose(const RecordingSeries& calibration, const RecordingSeries& heldout,
                   const DiagnoseOptions& options) {
  return diagnose_in_detail(calibration, heldout, options).diagnosis;
}

}  // namespace flange::diagnose

// SPDX-License-Identifier: MIT
// The twin driven by a recording's own inputs, without its white noise: the deterministic
// "sim" voltage the diagnosis compares with the recorded one. It runs the catalogue's effects
// in the same chain order as sim::SensorTwin::step (a test checks they agree sample for
// sample), but inverts the nominal model only once per sample and reuses that inversion while
// no mount or thermal effect changes what the coil sees, and starts Newton from it when one
// does: fitting an effect replays thousands of times.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "diagnosis.h"
#include "sensor_twin.h"

namespace flange::diagnose {

// Linear interpolation of `values` (sampled at the increasing times `t`) at time `t_s`, held
// constant beyond the ends.
double interpolate_at(const std::vector<double>& t, const std::vector<double>& values, double t_s);

// interpolate_at for a run of times that mostly move forward (every sample's time plus a lead or
// a skew): the bracketing rows are found by stepping from the last ones rather than by a binary
// search over the whole series, with the same rows and so the same value.
class SeriesInterpolator {
 public:
  SeriesInterpolator(const std::vector<double>& t, const std::vector<double>& values)
      : t_(t), values_(values) {}
  double at(double t_s);

 private:
  const std::vector<double>& t_;
  const std::vector<double>& values_;
  std::size_t upper_ = 1;  // the first row later than the last time asked for
};

// Whether `effect` delays the temperature channel behind the coil: channel_skew with skew_s > 0,
// thermal_lag with tau_s < 0 (what ambient_from_recorded undoes).
bool delays_temperature_channel(const sim::EffectSettings& effect);

// The twin's ambient temperature behind a recorded one: effects that delay the temperature
// channel (delays_temperature_channel) are undone, so that the twin driven by the result records
// what was recorded. Others leave it as recorded.
std::vector<double> ambient_from_recorded(const RecordingSeries& series,
                                          const std::vector<sim::EffectSettings>& effects);

class TwinReplay {
 public:
  // `series` must outlive the replay; `nominal` is the twin's nominal model. `age_offset_s`: how
  // much older the sensor is at the series' t_s = 0 than at the t_s = 0 of the session its
  // effects were fitted on; effects of the sensor's age (ageing_drift) are replayed that much
  // later. The other effects depend on the time only through its differences.
  TwinReplay(const RecordingSeries& series, const sim::PolynomialSensorModel& nominal,
             double age_offset_s = 0.0);

  // The voltage the twin with `effects` (noise off) records for every sample. `seed` seeds the
  // random effects (vibration's tone phases), as the twin's seed does.
  std::vector<double> voltage(const std::vector<sim::EffectSettings>& effects,
                              std::uint64_t seed = 0) const;
  // The same into `out` (resized to one value per sample): a search that replays thousands of
  // times reuses one buffer rather than allocating and clearing a fresh one at every step.
  void voltage_into(const std::vector<sim::EffectSettings>& effects, std::uint64_t seed,
                    std::vector<double>& out) const;

  // The nominal model's voltage for every sample (no effect, no noise).
  const std::vector<double>& nominal_voltage() const { return nominal_v_; }
  // dV/dd of the nominal model at every sample (V/mm): how clearance motion shows in volts.
  const std::vector<double>& sensitivity_v_per_mm() const { return sensitivity_; }
  // dV/dT of the nominal model at every sample's clearance (V/degC): how a temperature the coil
  // sees other than the recorded one shows in volts (the free lag family, free_shape_fit.h).
  const std::vector<double>& temperature_sensitivity_v_per_c() const {
    return temperature_sensitivity_;
  }
  const std::vector<double>& times() const { return series_.t_s; }
  const RecordingSeries& series() const { return series_; }
  std::size_t size() const { return series_.size(); }

  // The replay a parameter search runs on: this one up to kSearchRows rows; beyond that (a
  // 100 Hz log), a replay of one row from each block of ceil(n / kSearchRows) consecutive rows,
  // at a pseudo-random place in its block so that no tone aliases onto a constant the way a
  // fixed stride can make it. A search on it costs what a 6 Hz session costs; the fit it finds
  // is then scored on every row.
  static constexpr std::size_t kSearchRows = 40000;
  const TwinReplay& search_replay() const;
  // `full` (one value per row of this replay) at the rows of search_replay().
  std::vector<double> at_search_rows(const std::vector<double>& full) const;
  // The rows of a search replay (one of at most kSearchRows rows) a search's coarse lattice runs
  // on: up to kLatticeRows rows this one; beyond, one row from each block, as above. A lattice
  // only finds the basin that the search's refinement, on every search row, then descends: on a
  // quarter of the rows the lattice costs a quarter (it was a third of a 100 Hz diagnosis).
  static constexpr std::size_t kLatticeRows = 10000;
  const TwinReplay& lattice_replay() const;
  // `search` (one value per row of this search replay) at the rows of lattice_replay().
  std::vector<double> at_lattice_rows(const std::vector<double>& search) const;
  // sin(k w t) and cos(k w t) at every sample for k = 1..count (w = angular_hz, rad/s): a search
  // of mains pickup sums its tones of any amplitude and phase from them (by the angle sum). Made
  // once per replay and mains frequency: every fit of mains pickup against this replay (each
  // round's screen, each refit of a mains pick) asks for the same.
  struct Harmonics {
    std::vector<std::vector<double>> sin_kwt, cos_kwt;  // [k - 1][sample]
  };
  std::shared_ptr<const Harmonics> harmonics(double angular_hz, int count) const;
  double age_offset_s() const { return age_offset_s_; }
  double v_min_v() const { return nominal_.v_min_v(); }
  const sim::PolynomialSensorModel& nominal() const { return nominal_; }

 private:
  // Every sample as the coil sees it once the effects that move the coil or its temperature
  // (mount and thermal stages, and a late temperature channel, which changes the drive) have
  // acted, with the nominal model inverted there. A fit varies one effect while the others
  // stay, so the last few of these are kept: a candidate downstream of a fitted thermal lag
  // would otherwise invert every sample at every step of its search.
  using CoilSamples = std::vector<sim::ChainSample>;
  std::shared_ptr<const CoilSamples> coil_samples(
      const std::vector<sim::EffectSettings>& coil_effects, std::uint64_t seed) const;
  // The terms of an effect that adds voltages set by the time alone (sim::Effect::time_terms) at
  // every sample, term k of sample i at k * size() + i: kept once the same settings are replayed
  // a second time (a search holding mains pickup evaluates its tones at every step otherwise),
  // null the first time (the effect is applied as it is).
  using TimeTerms = std::vector<double>;
  std::shared_ptr<const TimeTerms> time_terms(const sim::EffectSettings& settings,
                                              std::uint64_t seed, const sim::Effect& effect) const;
  // One row from each block of consecutive rows, and the replay of those rows.
  struct Subset;
  static std::shared_ptr<const Subset> make_subset(const RecordingSeries& series,
                                                   const sim::PolynomialSensorModel& nominal,
                                                   double age_offset_s, std::size_t rows);
  std::shared_ptr<const Subset> search_;   // null while the series has <= kSearchRows
  std::shared_ptr<const Subset> lattice_;  // null unless kLatticeRows < rows <= kSearchRows
  struct CoilCache {
    struct Entry {
      std::vector<sim::EffectSettings> coil_effects;
      std::uint64_t seed = 0;
      std::shared_ptr<const CoilSamples> samples;
    };
    std::mutex mutex;
    std::vector<Entry> entries;  // most recently used last
  };

  struct TimeTermCache {
    struct Entry {
      sim::EffectSettings settings;
      std::uint64_t seed = 0;
      std::shared_ptr<const TimeTerms> terms;  // null: seen once, not kept yet
    };
    std::mutex mutex;
    std::vector<Entry> entries;  // most recently used last
  };

  struct HarmonicsCache {
    struct Entry {
      double angular_hz = 0.0;
      int count = 0;
      std::shared_ptr<const Harmonics> harmonics;
    };
    std::mutex mutex;
    std::vector<Entry> entries;  // most recently made last
  };

  const RecordingSeries& series_;
  sim::PolynomialSensorModel nominal_;
  double age_offset_s_;
  std::vector<double> nominal_v_;
  std::vector<sim::RailClip> nominal_clip_;
  std::vector<double> sensitivity_;
  std::vector<double> temperature_sensitivity_;
  std::shared_ptr<CoilCache> coil_cache_ = std::make_shared<CoilCache>();
  std::shared_ptr<TimeTermCache> time_term_cache_ = std::make_shared<TimeTermCache>();
  std::shared_ptr<HarmonicsCache> harmonics_cache_ = std::make_shared<HarmonicsCache>();
};

}  // namespace flange::diagnose

// SPDX-License-Identifier: MIT
#include "twin_replay.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "effect_catalogue.h"
#include "effect_classes.h"

namespace flange::diagnose {
namespace {

constexpr double kSecondsPerDay = 86400.0;
// Coil states kept per replay: at least the fitted effects, and the candidate being searched when
// it is itself a coil effect, with room for the parallel candidates' own; on a short replay (a
// search's or its lattice's rows) as many as kCoilCacheBytes hold, so that the lattice points of a
// lag or a skew, the same in every fit of it against the same coil, are inverted once, not again
// in each round and each refit (on a 100 Hz pair, three of every four inversions of the lattice).
constexpr std::size_t kCoilCacheEntries = 6;
constexpr std::size_t kCoilCacheBytes = 24u << 20;
// Settings of effects that add voltages set by the time alone (mains pickup) remembered per
// replay, and the most of them whose terms are kept: a search holds one such effect (or a few,
// across the threads' candidates) while it varies another, and a pick's settings come back in
// every candidate of the next round; kTimeTermBytes bounds what the terms hold (a 45-minute
// 100 Hz part's three mains tones are 6.5 MB).
constexpr std::size_t kTimeTermSettingsSeen = 16;
constexpr std::size_t kTimeTermBytes = 32u << 20;
// Harmonic tables kept per replay: one for each of the two mains standards.
constexpr std::size_t kHarmonicTablesKept = 2;
// The half-width of the window an inverted reading lag takes its slope over, as a share of the
// lag's time constant (local_slopes).
constexpr double kSlopeWindowOfTau = 0.125;

using sim::ChainStage;

// Which row of block `block` (of `stride` rows) the search subset takes: a fixed hash, so that
// runs agree, spread over the block.
std::size_t row_in_block(std::size_t block, std::size_t stride) {
  std::uint64_t z = static_cast<std::uint64_t>(block) + 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<std::size_t>(z % stride);
}

}  // namespace

struct TwinReplay::Subset {
  RecordingSeries series;
  std::vector<std::size_t> rows;
  std::unique_ptr<TwinReplay> replay;
};

std::shared_ptr<const TwinReplay::Subset> TwinReplay::make_subset(
    const RecordingSeries& series, const sim::PolynomialSensorModel& nominal, double age_offset_s,
    std::size_t rows) {
  auto subset = std::make_shared<Subset>();
  const std::size_t n = series.size();
  const std::size_t stride = (n + rows - 1) / rows;
  for (std::size_t block = 0; block * stride < n; ++block) {
    const std::size_t i = std::min(n - 1, block * stride + row_in_block(block, stride));
    subset->rows.push_back(i);
    subset->series.t_s.push_back(series.t_s[i]);
    subset->series.clearance_mm.push_back(series.clearance_mm[i]);
    subset->series.temp_c.push_back(series.temp_c[i]);
    subset->series.voltage_v.push_back(series.voltage_v[i]);
  }
  subset->series.path = series.path;
  subset->series.start_utc_s = series.start_utc_s;
  subset->replay = std::make_unique<TwinReplay>(subset->series, nominal, age_offset_s);
  return subset;
}

namespace {

std::vector<double> at_rows(const std::vector<double>& full, const std::vector<std::size_t>& rows) {
  std::vector<double> picked;
  picked.reserve(rows.size());
  for (const std::size_t i : rows) picked.push_back(full[i]);
  return picked;
}

}  // namespace

double interpolate_at(const std::vector<double>& t, const std::vector<double>& values, double t_s) {
  if (t_s <= t.front()) return values.front();
  if (t_s >= t.back()) return values.back();
  const auto upper = std::upper_bound(t.begin(), t.end(), t_s);
  const std::size_t j = static_cast<std::size_t>(upper - t.begin());
  const double w = (t_s - t[j - 1]) / (t[j] - t[j - 1]);
  return values[j - 1] + w * (values[j] - values[j - 1]);
}

double SeriesInterpolator::at(double t_s) {
  if (t_s <= t_.front()) return values_.front();
  if (t_s >= t_.back()) return values_.back();
  // The row std::upper_bound finds: the first with t > t_s (t_s lies inside, so 1 <= j < n).
  std::size_t j = std::clamp<std::size_t>(upper_, 1, t_.size() - 1);
  while (t_[j] <= t_s) ++j;
  while (t_[j - 1] > t_s) --j;
  upper_ = j;
  const double w = (t_s - t_[j - 1]) / (t_[j] - t_[j - 1]);
  return values_[j - 1] + w * (values_[j] - values_[j - 1]);
}

bool delays_temperature_channel(const sim::EffectSettings& effect) {
  const ChannelDelay delay = channel_delay_of(effect);
  return delay.temperature_late() || delay.temperature_lag_tau_s > 0.0;
}

namespace {

// The slope of `x` at each sample: least squares over the samples within `half_width_s` of it
// (the neighbours at least, where they are farther apart). The inverted lag multiplies the slope
// by tau, so a two-sample difference would multiply a thermocouple's reading noise by
// tau / dt (0.1 degC read at 9 Hz behind a 400 s lag: some 200 degC). Over a window of an eighth
// of tau either side, the slope adds sqrt(768 / (fs tau)) of the reading's noise to the lead
// (0.46 of it there), while a heating curve slower than the lag bends little over the window; a
// sharp turn of the oven is rounded off (from heating to a 4.6 degC/min fall: 2 degC at the turn).
std::vector<double> local_slopes(const std::vector<double>& t, const std::vector<double>& x,
                                 double half_width_s) {
  const std::size_t n = t.size();
  // Prefix sums of u = t - t[0], x, u x and u^2 (about the first sample, for precision).
  std::vector<double> su(n + 1, 0.0), sx(n + 1, 0.0), sux(n + 1, 0.0), suu(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = t[i] - t[0];
    su[i + 1] = su[i] + u;
    sx[i + 1] = sx[i] + x[i];
    sux[i + 1] = sux[i] + u * x[i];
    suu[i + 1] = suu[i] + u * u;
  }
  std::vector<double> slope(n, 0.0);
  std::size_t lo = 0, hi = 0;  // the window is [lo, hi)
  for (std::size_t i = 0; i < n; ++i) {
    while (lo < i && t[lo] < t[i] - half_width_s) ++lo;
    hi = std::max(hi, i + 1);
    while (hi < n && t[hi] <= t[i] + half_width_s) ++hi;
    const std::size_t a = std::min(lo, i == 0 ? 0 : i - 1), b = std::max(hi, std::min(n, i + 2));
    const double m = static_cast<double>(b - a);
    const double mean_u = (su[b] - su[a]) / m, mean_x = (sx[b] - sx[a]) / m;
    const double cov = (sux[b] - sux[a]) / m - mean_u * mean_x;
    const double var = (suu[b] - suu[a]) / m - mean_u * mean_u;
    slope[i] = var > 0.0 ? cov / var : 0.0;
  }
  return slope;
}

}  // namespace

std::vector<double> ambient_from_recorded(const RecordingSeries& series,
                                          const std::vector<sim::EffectSettings>& effects) {
  std::vector<double> ambient = series.temp_c;
  const std::size_t n = ambient.size();
  // Undo in reverse chain order: the skew acts after the lag.
  for (const sim::EffectSettings& effect : effects) {
    if (const ChannelDelay delay = channel_delay_of(effect); delay.temperature_late()) {
      std::vector<double> advanced(n);
      SeriesInterpolator late(series.t_s, ambient);
      for (std::size_t i = 0; i < n; ++i) {
        const double t = series.t_s[i];
        advanced[i] = late.at(t + std::max(0.0, delay.skew.at(t)));
      }
      ambient = std::move(advanced);
    }
  }
  for (const sim::EffectSettings& effect : effects) {
    const double tau_s = channel_delay_of(effect).temperature_lag_tau_s;
    if (tau_s > 0.0 && n >= 3) {
      // A first-order lag y' = (x - y) / tau inverts to x = y + tau y'.
      const std::vector<double> slope =
          local_slopes(series.t_s, ambient, kSlopeWindowOfTau * tau_s);
      for (std::size_t i = 0; i < n; ++i) ambient[i] += tau_s * slope[i];
    }
  }
  return ambient;
}

TwinReplay::TwinReplay(const RecordingSeries& series, const sim::PolynomialSensorModel& nominal,
                       double age_offset_s)
    : series_(series), nominal_(nominal), age_offset_s_(age_offset_s) {
  const std::size_t n = series.size();
  nominal_v_.resize(n);
  nominal_clip_.resize(n);
  sensitivity_.resize(n);
  temperature_sensitivity_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const sim::VoltageSolution v = nominal_.voltage_for(series.clearance_mm[i], series.temp_c[i]);
    nominal_v_[i] = v.volts;
    nominal_clip_[i] = v.clip;
    // dd/dV by a central difference; its inverse is the sensitivity.
    const double h = 1e-3;
    const double dd_dv = (nominal_.clearance_mm(v.volts + h, series.temp_c[i]) -
                          nominal_.clearance_mm(v.volts - h, series.temp_c[i])) /
                         (2.0 * h);
    sensitivity_[i] = dd_dv != 0.0 ? 1.0 / dd_dv : 0.0;
    // At a fixed clearance, dV/dT = -(dd/dT) / (dd/dV).
    const double dd_dt = (nominal_.clearance_mm(v.volts, series.temp_c[i] + h) -
                          nominal_.clearance_mm(v.volts, series.temp_c[i] - h)) /
                         (2.0 * h);
    temperature_sensitivity_[i] = v.clip == sim::RailClip::kNone ? -dd_dt * sensitivity_[i] : 0.0;
  }
  if (n > kSearchRows) {
    search_ = make_subset(series, nominal, age_offset_s, kSearchRows);
  } else if (n > kLatticeRows) {
    lattice_ = make_subset(series, nominal, age_offset_s, kLatticeRows);
  }
}

const TwinReplay& TwinReplay::search_replay() const { return search_ ? *search_->replay : *this; }

std::vector<double> TwinReplay::at_search_rows(const std::vector<double>& full) const {
  return search_ ? at_rows(full, search_->rows) : full;
}

const TwinReplay& TwinReplay::lattice_replay() const {
  return lattice_ ? *lattice_->replay : *this;
}

std::vector<double> TwinReplay::at_lattice_rows(const std::vector<double>& search) const {
  return lattice_ ? at_rows(search, lattice_->rows) : search;
}

std::shared_ptr<const TwinReplay::CoilSamples> TwinReplay::coil_samples(
    const std::vector<sim::EffectSettings>& coil_effects, std::uint64_t seed) const {
  {
    const std::lock_guard<std::mutex> lock(coil_cache_->mutex);
    auto& entries = coil_cache_->entries;
    for (std::size_t k = 0; k < entries.size(); ++k) {
      if (entries[k].seed == seed && entries[k].coil_effects == coil_effects) {
        std::rotate(entries.begin() + static_cast<std::ptrdiff_t>(k),
                    entries.begin() + static_cast<std::ptrdiff_t>(k) + 1, entries.end());
        return entries.back().samples;
      }
    }
  }
  std::vector<std::unique_ptr<sim::Effect>> chain;
  std::vector<ChainStage> stages;
  for (const sim::EffectSettings& effect : coil_effects) {
    chain.push_back(sim::make_effect(effect, nominal_.v_min_v(), nominal_.v_max_v(), seed));
    stages.push_back(sim::chain_stage_of(effect.name));
  }
  const std::vector<double> ambient = ambient_from_recorded(series_, coil_effects);
  // Reserved, not sized: each sample is written once, not zeroed first (at 100 Hz a replay's
  // 15 MB, on every search step that moves a coil effect).
  auto samples = std::make_shared<CoilSamples>();
  samples->reserve(series_.size());
  for (std::size_t i = 0; i < series_.size(); ++i) {
    sim::ChainSample& sample = samples->emplace_back();
    sample.t_s = series_.t_s[i];
    sample.clearance_mm = series_.clearance_mm[i];
    sample.ambient_c = sample.coil_c = sample.thermocouple_c = ambient[i];
    for (const ChainStage stage : {ChainStage::kMount, ChainStage::kThermal}) {
      for (std::size_t k = 0; k < chain.size(); ++k) {
        if (stages[k] == stage) chain[k]->apply(sample);
      }
    }
    const sim::VoltageSolution v =
        nominal_clip_[i] == sim::RailClip::kNone
            ? nominal_.voltage_near(sample.clearance_mm, sample.coil_c, nominal_v_[i])
            : nominal_.voltage_for(sample.clearance_mm, sample.coil_c);
    sample.voltage_v = v.volts;
    sample.clip = v.clip;
  }
  const std::lock_guard<std::mutex> lock(coil_cache_->mutex);
  auto& entries = coil_cache_->entries;
  const std::size_t bytes_per_entry = std::max<std::size_t>(1, series_.size()) * sizeof(sim::ChainSample);
  const std::size_t capacity = std::max(kCoilCacheEntries, kCoilCacheBytes / bytes_per_entry);
  if (entries.size() >= capacity) entries.erase(entries.begin());
  entries.push_back({coil_effects, seed, samples});
  return samples;
}

std::shared_ptr<const TwinReplay::TimeTerms> TwinReplay::time_terms(
    const sim::EffectSettings& settings, std::uint64_t seed, const sim::Effect& effect) const {
  {
    const std::lock_guard<std::mutex> lock(time_term_cache_->mutex);
    auto& entries = time_term_cache_->entries;
    const auto found = std::find_if(entries.begin(), entries.end(), [&](const auto& e) {
      return e.seed == seed && e.settings == settings;
    });
    if (found == entries.end()) {  // the first time: remembered, applied as it is
      if (entries.size() >= kTimeTermSettingsSeen) entries.erase(entries.begin());
      entries.push_back({settings, seed, nullptr});
      return nullptr;
    }
    std::rotate(found, found + 1, entries.end());
    if (entries.back().terms) return entries.back().terms;
  }
  const std::size_t n = series_.size();
  const int count = effect.time_terms();
  auto terms = std::make_shared<TimeTerms>(static_cast<std::size_t>(count) * n);
  for (int k = 0; k < count; ++k) {
    double* term = terms->data() + static_cast<std::size_t>(k) * n;
    for (std::size_t i = 0; i < n; ++i) term[i] = effect.time_term(k, series_.t_s[i]);
  }
  const std::lock_guard<std::mutex> lock(time_term_cache_->mutex);
  auto& entries = time_term_cache_->entries;
  const auto found = std::find_if(entries.begin(), entries.end(), [&](const auto& e) {
    return e.seed == seed && e.settings == settings;
  });
  if (found != entries.end()) {
    found->terms = terms;
  } else {
    if (entries.size() >= kTimeTermSettingsSeen) entries.erase(entries.begin());
    entries.push_back({settings, seed, terms});
  }
  // The least recently used terms go first while those kept exceed kTimeTermBytes.
  std::size_t bytes = 0;
  for (auto e = entries.rbegin(); e != entries.rend(); ++e) {
    if (!e->terms) continue;
    bytes += e->terms->size() * sizeof(double);
    if (bytes > kTimeTermBytes && e->terms != terms) e->terms.reset();
  }
  return terms;
}

std::shared_ptr<const TwinReplay::Harmonics> TwinReplay::harmonics(double angular_hz,
                                                                   int count) const {
  const auto same = [&](const HarmonicsCache::Entry& e) {
    return e.angular_hz == angular_hz && e.count == count;
  };
  {
    const std::lock_guard<std::mutex> lock(harmonics_cache_->mutex);
    const auto& entries = harmonics_cache_->entries;
    const auto found = std::find_if(entries.begin(), entries.end(), same);
    if (found != entries.end()) return found->harmonics;
  }
  auto made = std::make_shared<Harmonics>();
  const std::vector<double>& t = series_.t_s;
  for (int k = 1; k <= count; ++k) {
    std::vector<double> sin_kwt(t.size()), cos_kwt(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
      sin_kwt[i] = std::sin(k * angular_hz * t[i]);
      cos_kwt[i] = std::cos(k * angular_hz * t[i]);
    }
    made->sin_kwt.push_back(std::move(sin_kwt));
    made->cos_kwt.push_back(std::move(cos_kwt));
  }
  const std::lock_guard<std::mutex> lock(harmonics_cache_->mutex);
  auto& entries = harmonics_cache_->entries;
  const auto found = std::find_if(entries.begin(), entries.end(), same);
  if (found != entries.end()) return found->harmonics;  // made meanwhile by another thread
  if (entries.size() >= kHarmonicTablesKept) entries.erase(entries.begin());
  entries.push_back({angular_hz, count, made});
  return made;
}

std::vector<double> TwinReplay::voltage(const std::vector<sim::EffectSettings>& effects,
                                        std::uint64_t seed) const {
  std::vector<double> out;
  voltage_into(effects, seed, out);
  return out;
}

void TwinReplay::voltage_into(const std::vector<sim::EffectSettings>& effects, std::uint64_t seed,
                              std::vector<double>& out) const {
  // The sensor's age at this series' t_s = 0, for the effects fitted on another session.
  std::vector<sim::EffectSettings> aged = effects;
  for (sim::EffectSettings& effect : aged) {
    if (const std::string& age = effect_class(effect.name).age_param; !age.empty()) {
      effect.params[age] += age_offset_s_ / kSecondsPerDay;
    }
  }
  std::vector<const sim::EffectSettings*> ordered;
  for (const sim::EffectSettings& effect : aged) ordered.push_back(&effect);
  std::sort(ordered.begin(), ordered.end(),
            [](const sim::EffectSettings* a, const sim::EffectSettings* b) {
              return sim::catalogue_index(a->name) < sim::catalogue_index(b->name);
            });
  // The coil effects in chain order, and whether any is there: without one the coil sees the
  // recorded inputs and the inversion made once in the constructor serves.
  std::vector<sim::EffectSettings> coil_effects;
  for (const sim::EffectSettings* effect : ordered) {
    const bool moves_drive = channel_delay_of(*effect).temperature_late();
    if (sim::chain_stage_of(effect->name) <= ChainStage::kThermal || moves_drive) {
      coil_effects.push_back(*effect);
    }
  }
  // The effects after the coil, stage by stage and in catalogue order within a stage: those
  // before the rails' clamp (the sensor's) and those after it (wiring, then acquisition).
  // An effect of the time alone adds its kept terms where the replay has them (time_terms).
  struct Applied {
    std::unique_ptr<sim::Effect> effect;
    std::shared_ptr<const TimeTerms> terms;
  };
  std::vector<Applied> before_clamp, after_clamp;
  for (const ChainStage stage : {ChainStage::kSensor, ChainStage::kWiring, ChainStage::kAcquisition}) {
    for (const sim::EffectSettings* effect : ordered) {
      if (sim::chain_stage_of(effect->name) != stage) continue;
      Applied applied{sim::make_effect(*effect, nominal_.v_min_v(), nominal_.v_max_v(), seed),
                      nullptr};
      if (applied.effect->time_terms() > 0) {
        applied.terms = time_terms(*effect, seed, *applied.effect);
      }
      (stage == ChainStage::kSensor ? before_clamp : after_clamp).push_back(std::move(applied));
    }
  }
  const std::size_t n = series_.size();
  const auto apply = [n](const Applied& applied, std::size_t i, sim::ChainSample& sample) {
    if (!applied.terms) {
      applied.effect->apply(sample);
      return;
    }
    const std::size_t count = applied.terms->size() / n;
    for (std::size_t k = 0; k < count; ++k) sample.voltage_v += (*applied.terms)[k * n + i];
  };
  const std::shared_ptr<const CoilSamples> coil =
      coil_effects.empty() ? nullptr : coil_samples(coil_effects, seed);
  const double v_min = nominal_.v_min_v(), v_max = nominal_.v_max_v();
  out.resize(series_.size());
  for (std::size_t i = 0; i < series_.size(); ++i) {
    sim::ChainSample sample;
    if (coil) {
      sample = (*coil)[i];
    } else {
      sample.t_s = series_.t_s[i];
      sample.clearance_mm = series_.clearance_mm[i];
      sample.ambient_c = sample.coil_c = sample.thermocouple_c = series_.temp_c[i];
      sample.voltage_v = nominal_v_[i];
      sample.clip = nominal_clip_[i];
    }
    for (const Applied& applied : before_clamp) apply(applied, i, sample);
    sample.voltage_v = std::clamp(sample.voltage_v, v_min, v_max);
    for (const Applied& applied : after_clamp) apply(applied, i, sample);
    out[i] = sample.voltage_v;
  }
}

}  // namespace flange::diagnose

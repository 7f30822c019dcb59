// SPDX-License-Identifier: MIT
#include "effect_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <utility>

#include "class_fits.h"
#include "effect_classes.h"
#include "recording_series.h"
#include "series_arithmetic.h"
#include "series_statistics.h"

namespace flange::diagnose {
namespace {

// Lattice points per parameter for the starting search: finer in one dimension, where it is
// cheap and where lags and skews have narrow basins.
int lattice_points(std::size_t dims) { return dims == 1 ? 41 : dims == 2 ? 9 : 7; }

struct Objective {
  std::function<double(const std::vector<double>&)> value;  // of unit-cube coordinates
  int evaluations = 0;
};

// The objective at `x`, counted.
double evaluate(Objective& objective, const std::vector<double>& x) {
  ++objective.evaluations;
  return objective.value(x);
}

std::vector<double> clamp_to_unit_cube(std::vector<double> x) {
  for (double& v : x) v = std::clamp(v, 0.0, 1.0);
  return x;
}

// Nelder-Mead's n + 1 points in the unit cube and the objective at each.
struct Simplex {
  std::vector<std::vector<double>> points;
  std::vector<double> values;
};

// `start` and one point `step` away along each axis (backwards where forwards leaves the cube).
Simplex initial_simplex(Objective& objective, const std::vector<double>& start, double step) {
  Simplex simplex;
  simplex.points.push_back(clamp_to_unit_cube(start));
  for (std::size_t d = 0; d < start.size(); ++d) {
    std::vector<double> x = start;
    x[d] += x[d] + step <= 1.0 ? step : -step;
    simplex.points.push_back(clamp_to_unit_cube(x));
  }
  for (const auto& x : simplex.points) simplex.values.push_back(evaluate(objective, x));
  return simplex;
}

// Halves every point's distance to the best one. Returns the evaluations spent.
int shrink_towards(Objective& objective, Simplex& simplex, std::size_t best) {
  int used = 0;
  for (std::size_t i = 0; i < simplex.points.size(); ++i) {
    if (i == best) continue;
    std::vector<double>& x = simplex.points[i];
    for (std::size_t d = 0; d < x.size(); ++d) {
      x[d] = simplex.points[best][d] + 0.5 * (x[d] - simplex.points[best][d]);
    }
    simplex.values[i] = evaluate(objective, x);
    ++used;
  }
  return used;
}

// One Nelder-Mead move: the worst point is reflected through the centroid of the others, then
// the reflection is expanded or contracted, or else the simplex shrinks towards the best point.
// Returns the evaluations spent.
int move_worst_point(Objective& objective, Simplex& simplex, std::size_t best, std::size_t second,
                     std::size_t worst) {
  std::vector<std::vector<double>>& points = simplex.points;
  std::vector<double>& values = simplex.values;
  const std::size_t n = points.size() - 1;
  std::vector<double> centroid(n, 0.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i == worst) continue;
    for (std::size_t d = 0; d < n; ++d) centroid[d] += points[i][d] / static_cast<double>(n);
  }
  const auto along = [&](double t) {
    std::vector<double> x(n);
    for (std::size_t d = 0; d < n; ++d) x[d] = centroid[d] + t * (points[worst][d] - centroid[d]);
    return clamp_to_unit_cube(x);
  };
  const auto replace_worst = [&](const std::vector<double>& x, double value) {
    points[worst] = x;
    values[worst] = value;
  };
  const std::vector<double> reflected = along(-1.0);
  const double fr = evaluate(objective, reflected);
  if (fr < values[best]) {
    const std::vector<double> expanded = along(-2.0);
    const double fe = evaluate(objective, expanded);
    if (fe < fr) {
      replace_worst(expanded, fe);
    } else {
      replace_worst(reflected, fr);
    }
    return 2;
  }
  if (fr < values[second]) {
    replace_worst(reflected, fr);
    return 1;
  }
  const std::vector<double> contracted = along(fr < values[worst] ? -0.5 : 0.5);
  const double fc = evaluate(objective, contracted);
  if (fc < std::min(fr, values[worst])) {
    replace_worst(contracted, fc);
    return 2;
  }
  return 2 + shrink_towards(objective, simplex, best);
}

// Nelder-Mead on the unit cube (coordinates clamped), from `start`.
std::vector<double> nelder_mead(Objective& objective, std::vector<double> start, double step,
                                int max_evaluations) {
  const std::size_t n = start.size();
  Simplex simplex = initial_simplex(objective, start, step);
  const std::vector<double>& values = simplex.values;
  int used = static_cast<int>(simplex.points.size());
  while (used < max_evaluations) {
    std::vector<std::size_t> order(simplex.points.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return values[a] < values[b]; });
    const std::size_t best = order.front(), worst = order.back(), second = order[n - 1];
    if (std::abs(values[worst] - values[best]) <= 1e-10 * (std::abs(values[best]) + 1e-12)) {
      break;
    }
    used += move_worst_point(objective, simplex, best, second, worst);
  }
  const auto best = std::min_element(values.begin(), values.end()) - values.begin();
  return simplex.points[static_cast<std::size_t>(best)];
}

// The ageing drift's line over the record: offset a = r a0 at t = 0 and rate r, with the
// catalogue's limits: |r| <= 2 V/day, start age a0 = a / r in [0, 3650] days (so a and r share
// a sign). Least squares of `gap` on [1, t in days] within those limits: the free optimum if it
// is allowed, else the best point on the edges of the allowed region (a = 0, a0 = 3650,
// r = +-2), where a convex problem's constrained optimum lies.
struct AgeingLine {
  double offset_v = 0.0, rate_v_per_day = 0.0;
};
AgeingLine ageing_line(const std::vector<double>& gap, const std::vector<double>& t_s) {
  constexpr double kMaxRate = 2.0, kMaxAge = 3650.0, kDay = 86400.0;
  const double n = static_cast<double>(gap.size());
  double st = 0, sg = 0, stt = 0, stg = 0, sgg = 0;
  for (std::size_t i = 0; i < gap.size(); ++i) {
    const double t = t_s[i] / kDay;
    st += t;
    sg += gap[i];
    stt += t * t;
    stg += t * gap[i];
    sgg += gap[i] * gap[i];
  }
  // Sum of squares of gap - a - r t, from the sums.
  const auto sse = [&](double a, double r) {
    return sgg - 2 * a * sg - 2 * r * stg + n * a * a + 2 * a * r * st + r * r * stt;
  };
  const auto allowed = [&](double a, double r) {
    return std::abs(r) <= kMaxRate && a * r >= 0.0 && std::abs(a) <= kMaxAge * std::abs(r) + 1e-12;
  };
  const double denominator = n * stt - st * st;
  if (denominator > 0.0) {
    const double r = (n * stg - st * sg) / denominator;
    const double a = (sg - r * st) / n;
    if (allowed(a, r)) return {a, r};
  }
  std::vector<AgeingLine> edges;
  edges.push_back({0.0, std::clamp(stt > 0 ? stg / stt : 0.0, -kMaxRate, kMaxRate)});  // a = 0
  // a = kMaxAge r: gap = r (kMaxAge + t).
  const double suu = n * kMaxAge * kMaxAge + 2 * kMaxAge * st + stt;
  const double sug = kMaxAge * sg + stg;
  const double r_old = std::clamp(sug / suu, -kMaxRate, kMaxRate);
  edges.push_back({kMaxAge * r_old, r_old});
  for (const double r : {kMaxRate, -kMaxRate}) {  // r at a limit, a between 0 and kMaxAge r
    const double a = (sg - r * st) / n;
    edges.push_back({std::clamp(a, std::min(0.0, kMaxAge * r), std::max(0.0, kMaxAge * r)), r});
  }
  return *std::min_element(edges.begin(), edges.end(), [&](const auto& x, const auto& y) {
    return sse(x.offset_v, x.rate_v_per_day) < sse(y.offset_v, y.rate_v_per_day);
  });
}

// Subtracts the ageing drift's best line (ageing_line) from `gap`.
void remove_ageing_line(std::vector<double>& gap, const std::vector<double>& t_s) {
  const AgeingLine line = ageing_line(gap, t_s);
  for (std::size_t i = 0; i < gap.size(); ++i) {
    gap[i] -= line.offset_v + line.rate_v_per_day * t_s[i] / 86400.0;
  }
}

// Mains: the frequency aliases (any mains_hz gives a line at its alias), so it is chosen between
// the two mains standards rather than fitted continuously. A standard whose fundamental aliases
// to DC (60 Hz at 6 Hz) is an offset, not a tone, and is left to the offset effects.
std::vector<double> mains_standards_hz(const TwinReplay& replay) {
  const std::vector<double>& t = replay.times();
  const double fs_hz = rate_of_median_step(t);
  std::vector<double> standards;
  for (const double f : {50.0, 60.0}) {
    if (std::abs(f - fs_hz * std::round(f / fs_hz)) > 0.01 * fs_hz) standards.push_back(f);
  }
  return standards;
}

// The calibration voltage-gap RMS with one effect added to those modelled, as a function of the
// effect's free parameters in unit-cube coordinates.
class GapRms {
 public:
  // `fixed`: parameters held (mains_pickup's mains_hz); the others stay at their defaults.
  // `tones_on_the_cable`: the effect adds tones after every effect but the acquisition's (mains
  // pickup), which lets each step sum the tones onto one replay (prepare_mains_tail).
  GapRms(const std::string& name, const std::vector<SearchRange>& params, sim::ParamValues fixed,
         bool tones_on_the_cable, const TwinReplay& replay, const std::vector<double>& real_v,
         const std::vector<sim::EffectSettings>& modelled)
      : name_(name),
        params_(params),
        fixed_(std::move(fixed)),
        replay_(replay),
        real_v_(real_v),
        modelled_(modelled) {
    // An ageing drift already modelled (the class profiled in other fits) is linear in its
    // offset and rate: it is solved by least squares at every point of the search (profiled out)
    // rather than held, since a temperature effect and an ageing offset trade against each other
    // along a narrow valley that one-effect-at-a-time refits crawl along.
    for (const sim::EffectSettings& m : modelled) {
      if (!effect_class(m.name).profiled_in_other_fits) held_.push_back(m);
    }
    profile_ageing_ = held_.size() < modelled.size();
    if (tones_on_the_cable && !any_after_wiring(modelled)) prepare_mains_tail();
  }

  std::size_t dims() const { return params_.size(); }

  sim::EffectSettings settings_at(const std::vector<double>& unit) const {
    sim::ParamValues values = fixed_;
    for (std::size_t d = 0; d < params_.size(); ++d) {
      values[params_[d].key] = params_[d].lo + unit[d] * (params_[d].hi - params_[d].lo);
    }
    return sim::make_effect_settings(name_, values, "diagnose fit");
  }

  double operator()(const std::vector<double>& unit) const {
    std::vector<double>& gap = gap_;  // one buffer for every step of the search
    if (mains_tail_) {
      gap_with_mains_tail(settings_at(unit), gap);
    } else {
      std::vector<sim::EffectSettings> effects = profile_ageing_ ? held_ : modelled_;
      effects.push_back(settings_at(unit));
      replay_.voltage_into(effects, 0, gap);
      for (std::size_t i = 0; i < gap.size(); ++i) gap[i] = real_v_[i] - gap[i];
    }
    if (profile_ageing_) remove_ageing_line(gap, replay_.times());
    double sum = 0.0;
    for (const double g : gap) sum += g * g;
    return std::sqrt(sum / static_cast<double>(gap.size()));
  }

 private:
  // Mains pickup adds its tones on the cable, after every effect but the acquisition's: with no
  // acquisition effect modelled, the twin with it is the twin without it plus the tones, so
  // the replay is made once and each step of the search only sums the tones, from sin(k w t)
  // and cos(k w t) kept per sample (k w t + k phi by the angle sum).
  static bool any_after_wiring(const std::vector<sim::EffectSettings>& effects) {
    for (const sim::EffectSettings& e : effects) {
      if (sim::chain_stage_of(e.name) > sim::ChainStage::kWiring) return true;
    }
    return false;
  }

  void prepare_mains_tail() {
    const sim::EffectSettings any = settings_at(std::vector<double>(params_.size(), 0.0));
    const int harmonics = static_cast<int>(any.params.at("harmonics"));
    const double angular_hz = 2.0 * std::numbers::pi * any.params.at("mains_hz");
    mains_base_v_ = replay_.voltage(profile_ageing_ ? held_ : modelled_);
    mains_tail_ = replay_.harmonics(angular_hz, harmonics);
  }

  void gap_with_mains_tail(const sim::EffectSettings& mains, std::vector<double>& gap) const {
    const double phase_rad = mains.params.at("phase_deg") * std::numbers::pi / 180.0;
    gap.resize(real_v_.size());
    for (std::size_t i = 0; i < gap.size(); ++i) gap[i] = real_v_[i] - mains_base_v_[i];
    double amplitude_v = mains.params.at("amplitude_v");
    for (std::size_t k = 0; k < mains_tail_->sin_kwt.size(); ++k) {
      const double kphi = static_cast<double>(k + 1) * phase_rad;
      const double a_sin = amplitude_v * std::cos(kphi), a_cos = amplitude_v * std::sin(kphi);
      const std::vector<double>& sin_kwt = mains_tail_->sin_kwt[k];
      const std::vector<double>& cos_kwt = mains_tail_->cos_kwt[k];
      for (std::size_t i = 0; i < gap.size(); ++i) {
        gap[i] -= a_sin * sin_kwt[i] + a_cos * cos_kwt[i];
      }
      amplitude_v *= mains.params.at("harmonic_ratio");
    }
  }

  // sin(k w t) and cos(k w t) of the mains (the replay's, made once); null: every step replays
  std::shared_ptr<const TwinReplay::Harmonics> mains_tail_;
  std::vector<double> mains_base_v_;   // the twin without the tones, when mains_tail_ is used

  const std::string& name_;
  const std::vector<SearchRange>& params_;
  sim::ParamValues fixed_;
  const TwinReplay& replay_;
  const std::vector<double>& real_v_;
  const std::vector<sim::EffectSettings>& modelled_;
  std::vector<sim::EffectSettings> held_;  // modelled_ but an ageing drift
  bool profile_ageing_ = false;
  // The gap at the point being evaluated: a search runs on one thread, one step at a time.
  mutable std::vector<double> gap_;
};

// The best point of a lattice of `points` per dimension over the unit cube.
std::vector<double> best_lattice_point(Objective& objective, std::size_t dims, int points) {
  std::vector<double> start(dims, 0.5);
  double start_value = std::numeric_limits<double>::infinity();
  std::vector<int> index(dims, 0);
  while (true) {
    std::vector<double> unit(dims);
    for (std::size_t d = 0; d < dims; ++d) unit[d] = index[d] / static_cast<double>(points - 1);
    const double value = objective.value(unit);
    ++objective.evaluations;
    if (value < start_value) {
      start_value = value;
      start = unit;
    }
    std::size_t d = 0;
    while (d < dims && ++index[d] == points) index[d++] = 0;
    if (d == dims) break;
  }
  return start;
}

// Minimises `search` (a GapRms on the replay's search rows): a coarse lattice on `lattice` (the
// same on the lattice rows), then Nelder-Mead on `search` from its best point; the point found
// is scored by `score` (the same on every row).
EffectFit minimise_gap_rms(const GapRms& lattice, const GapRms& search, const GapRms& score) {
  const std::size_t dims = search.dims();
  Objective coarse;
  coarse.value = [&](const std::vector<double>& unit) { return lattice(unit); };
  const int points = lattice_points(dims);
  const std::vector<double> start = best_lattice_point(coarse, dims, points);
  Objective objective;
  objective.value = [&](const std::vector<double>& unit) { return search(unit); };
  objective.evaluations = coarse.evaluations;
  const std::vector<double> unit =
      nelder_mead(objective, start, 0.5 / (points - 1), 100 * static_cast<int>(dims));
  return {score.settings_at(unit), score(unit), objective.evaluations + 1};
}

// The best of the fits of `name` over its search ranges with each of `choices` held (a class
// whose parameter is chosen among a few values rather than searched: the mains standard).
EffectFit best_over_fixed_choices(const std::string& name,
                                  const std::vector<sim::ParamValues>& choices,
                                  bool tones_on_the_cable, const TwinReplay& replay,
                                  const std::vector<double>& real_v,
                                  const std::vector<sim::EffectSettings>& modelled) {
  const std::vector<SearchRange>& params = effect_class(name).search;
  const TwinReplay& search_replay = replay.search_replay();
  const std::vector<double> search_v = replay.at_search_rows(real_v);
  const TwinReplay& lattice_replay = search_replay.lattice_replay();
  const std::vector<double> lattice_v = search_replay.at_lattice_rows(search_v);
  EffectFit best;
  best.rms_v = std::numeric_limits<double>::infinity();
  for (const sim::ParamValues& fixed : choices) {
    const bool tones = tones_on_the_cable;
    const EffectFit fit = minimise_gap_rms(
        GapRms(name, params, fixed, tones, lattice_replay, lattice_v, modelled),
        GapRms(name, params, fixed, tones, search_replay, search_v, modelled),
        GapRms(name, params, fixed, tones, replay, real_v, modelled));
    if (fit.rms_v < best.rms_v) {
      best.settings = fit.settings;
      best.rms_v = fit.rms_v;
    }
    best.evaluations += fit.evaluations;
  }
  return best;
}

}  // namespace

bool fitted_by_bias(const std::string& name) {
  return effect_class(name).identification == Identification::kByBias;
}

std::vector<std::string> fitted_keys(const std::string& name) {
  std::vector<std::string> keys;
  for (const SearchRange& p : effect_class(name).search) keys.push_back(p.key);
  return keys;
}

EffectFit fit_by_search(const std::string& name, const TwinReplay& replay,
                        const std::vector<double>& real_v,
                        const std::vector<sim::EffectSettings>& modelled) {
  return best_over_fixed_choices(name, {sim::ParamValues{}}, false, replay, real_v, modelled);
}

EffectFit fit_mains(const std::string& name, const TwinReplay& replay,
                    const std::vector<double>& real_v,
                    const std::vector<sim::EffectSettings>& modelled) {
  std::vector<sim::ParamValues> choices;
  for (const double mains_hz : mains_standards_hz(replay)) choices.push_back({{"mains_hz", mains_hz}});
  if (choices.empty()) {
    return {sim::make_effect_settings(name, {}, "diagnose fit"),
            std::numeric_limits<double>::infinity(), 0};
  }
  return best_over_fixed_choices(name, choices, true, replay, real_v, modelled);
}

// ageing_drift is linear in time, gap = r (a0 + t / day): least squares of the gap on [1, t]
// gives r and r a0 directly (a search over r and a0 crawls along the curved valley r a0 = c).
// Over a record of hours r itself is poorly determined; their product, the offset, is not.
EffectFit fit_ageing(const std::string& name, const TwinReplay& replay,
                     const std::vector<double>& real_v,
                     const std::vector<sim::EffectSettings>& modelled) {
  const std::vector<double> sim_v = replay.voltage(modelled);
  std::vector<double> gap(sim_v.size());
  for (std::size_t i = 0; i < sim_v.size(); ++i) gap[i] = real_v[i] - sim_v[i];
  const AgeingLine line = ageing_line(gap, replay.times());
  const double rate = line.rate_v_per_day;
  const double start_days = rate != 0.0 ? std::clamp(line.offset_v / rate, 0.0, 3650.0) : 0.0;
  EffectFit fit;
  fit.settings = sim::make_effect_settings(
      name, {{"rate_v_per_day", rate}, {"start_age_days", start_days}}, "diagnose fit");
  std::vector<sim::EffectSettings> with = modelled;
  with.push_back(fit.settings);
  const std::vector<double> fitted = replay.voltage(with);
  double sum = 0.0;
  for (std::size_t i = 0; i < fitted.size(); ++i) sum += std::pow(real_v[i] - fitted[i], 2);
  fit.rms_v = std::sqrt(sum / static_cast<double>(fitted.size()));
  fit.evaluations = 2;
  return fit;
}


EffectFit fit_effect(const std::string& name, const TwinReplay& replay,
                     const std::vector<double>& real_v,
                     const std::vector<sim::EffectSettings>& modelled) {
  return class_fit(name).fit(name, replay, real_v, modelled);
}

}  // namespace flange::diagnose

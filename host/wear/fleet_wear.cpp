// SPDX-License-Identifier: MIT
#include "fleet_wear.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include "block_jackknife.h"
#include "daily_distance.h"
#include "locomotive_common_mode.h"
#include "moderated_spread.h"
#include "negative_rate.h"
#include "new_flange_rates.h"
#include "reprofiling_search.h"
#include "robust_location.h"
#include "season_to_come.h"
#include "weekly_wear_rate.h"

namespace flange::host {
namespace {

// The runs both wheels of an axle have, in time order, with the two clearances side by side.
struct AxleRuns {
  std::vector<WearObservation> left, right;
};

AxleRuns align_runs(const WheelHistory& left, const WheelHistory& right) {
  std::map<std::int64_t, const WearObservation*> right_by_run;
  for (const WearObservation& run : right.runs) right_by_run[run.run_id] = &run;
  AxleRuns axle;
  for (const WearObservation& run : left.runs) {
    const auto partner = right_by_run.find(run.run_id);
    if (partner == right_by_run.end()) continue;
    axle.left.push_back(run);
    axle.right.push_back(*partner->second);
  }
  return axle;
}

std::vector<double> clearances(const std::vector<WearObservation>& runs) {
  std::vector<double> values;
  for (const WearObservation& run : runs) values.push_back(run.clearance_mm);
  return values;
}

// The first run after each recorded reprofiling (none for a record before the first run).
std::map<std::size_t, std::string> recorded_boundaries(const std::vector<WearObservation>& runs,
                                                       const std::vector<MaintenanceMark>& marks) {
  std::map<std::size_t, std::string> boundaries;
  for (const MaintenanceMark& mark : marks) {
    if (mark.kind != "reprofile") continue;
    for (std::size_t k = 1; k < runs.size(); ++k) {
      if (runs[k - 1].day <= mark.day && runs[k].day > mark.day) boundaries[k] = mark.at;
    }
  }
  return boundaries;
}

// The first run after each recorded sensor replacement or wheelset move: a new segment (another
// unit's offset, another flange) that is neither wear nor a reprofiling. `moves_only`: the
// wheelset moves alone (another flange; a replaced sensor reads the same one).
std::set<std::size_t> recorded_changes(const std::vector<WearObservation>& runs,
                                       const std::vector<MaintenanceMark>& marks,
                                       bool moves_only = false) {
  std::set<std::size_t> changes;
  for (const MaintenanceMark& mark : marks) {
    const bool move = mark.kind == "wheelset_moved";
    if (!move && (moves_only || mark.kind != "sensor_replaced")) continue;
    for (std::size_t k = 1; k < runs.size(); ++k) {
      if (runs[k - 1].day <= mark.day && runs[k].day > mark.day) changes.insert(k);
    }
  }
  return changes;
}

// A jump at a recorded change is the change's, not a reprofiling.
std::vector<std::size_t> unexplained(std::vector<std::size_t> found,
                                     const std::set<std::size_t>& changes) {
  std::erase_if(found, [&](std::size_t k) { return changes.count(k) != 0; });
  return found;
}

// Segments and reprofiling events from what the data show and what the depot recorded.
void segment_runs(WheelWear& wheel, const std::vector<std::size_t>& found,
                  const std::map<std::size_t, std::string>& recorded,
                  const std::set<std::size_t>& changes = {}) {
  std::set<std::size_t> boundaries(found.begin(), found.end());
  for (const auto& [k, at] : recorded) boundaries.insert(k);
  for (const std::size_t k : boundaries) {
    ReprofilingEvent event;
    event.last_run_before = wheel.runs[k - 1].at;
    event.first_run_after = wheel.runs[k].at;
    event.odometer_km = wheel.runs[k].odometer_km;
    event.found = std::find(found.begin(), found.end(), k) != found.end();
    const auto record = recorded.find(k);
    event.recorded = record != recorded.end();
    if (event.recorded) event.recorded_at = record->second;
    wheel.reprofilings.push_back(event);
  }
  wheel.segment.clear();
  int segment = 0;
  for (std::size_t k = 0; k < wheel.runs.size(); ++k) {
    if (boundaries.count(k) != 0 || changes.count(k) != 0) ++segment;
    wheel.segment.push_back(segment);
  }
}

WearSeries series_of(const WheelWear& wheel, const std::vector<double>& y,
                     const SensitivityAt& sensitivity = {}) {
  WearSeries series;
  for (const WearObservation& run : wheel.runs) {
    series.km.push_back(run.odometer_km);
    series.day.push_back(run.day);
    if (sensitivity) series.drift_scale.push_back(sensitivity(run.clearance_mm));
  }
  series.y = y;
  series.segment = wheel.segment;
  return series;
}

// The fleet's b and gamma in a wheel's forecast (wear_acceleration.h): the clearance and rate
// moved to the line refitted to y - b q - gamma p (b as acceleration_in_dates weighs it), how
// they move with b and gamma, and their covariance.
void with_fleet_bend(ForecastInput& input, const AccelerationEvidence& bend,
                     const FleetAcceleration& acceleration) {
  const double b = acceleration_in_dates(acceleration), gamma = acceleration.trend;
  input.clearance_per_acceleration = -bend.clearance_gradient;
  input.rate_per_acceleration = -bend.rate_gradient;
  input.clearance_per_trend = -bend.clearance_trend_gradient;
  input.rate_per_trend = -bend.rate_trend_gradient;
  input.acceleration_dof = acceleration.dof;
  const double clearance_shift =
      b * bend.clearance_gradient + gamma * bend.clearance_trend_gradient;
  const double rate_shift = b * bend.rate_gradient + gamma * bend.rate_trend_gradient;
  input.clearance_now_mm -= clearance_shift;
  input.rate_mm_per_km -= rate_shift;
  input.rate_low_mm_per_km -= rate_shift;
  input.rate_high_mm_per_km -= rate_shift;
  input.acceleration_per_mm = b;
  input.acceleration_se = acceleration.se;
  input.trend_se = acceleration.trend_se;
  input.acceleration_trend_covariance = acceleration.covariance;
}

// What the forecast is made from: the line at the last run with its uncertainties (the
// least-squares covariance widened by the jackknife's inflation), the km per day and the rate to
// come: the season, carried forward and in the interval (season_to_come.h), and the locomotive's
// duties (weekly_wear_rate.h).
ForecastInput forecast_input(const WheelWear& wheel, const SerialSpread& spread,
                             const FleetAcceleration& acceleration, const WeeklyWearRate& duty) {
  const WearLineFit& fit = *wheel.fit;
  const std::vector<WearObservation>& runs = wheel.runs;
  const DailyDistance distance = daily_distance(runs);
  ForecastInput input;
  input.clearance_now_mm = wheel.clearance_now_mm;
  // The history's mean wear per km (history_mean_rate.h), where the line's slope weighs the
  // history's middle most; its uncertainty the line's, whose stretches move with the duties as
  // the months to come will.
  input.rate_mm_per_km =
      wheel.history_mean ? wheel.rate_mm_per_1000km / 1000.0 : fit.rate_mm_per_km;
  const double half_width = t95(spread.dof) * spread.rate_se;
  input.rate_low_mm_per_km = input.rate_mm_per_km - half_width;
  input.rate_high_mm_per_km = input.rate_mm_per_km + half_width;
  input.km_per_day = distance.km_per_day;
  input.last_day = runs.back().day;
  // The clearance now is a_current + r (km - km0): its variance and covariance with r.
  const auto& cov = fit.covariance;
  const auto a = static_cast<std::size_t>(wheel.segment.back());
  const std::size_t r = fit.intercepts_mm.size();
  const double lever = runs.back().odometer_km - fit.km0;
  const double variance = cov[a][a] + 2.0 * lever * cov[a][r] + lever * lever * cov[r][r];
  input.clearance_now_se_mm = std::sqrt(std::max(0.0, spread.inflation * variance));
  input.rate_se_mm_per_km = spread.rate_se;
  input.clearance_rate_covariance = spread.inflation * (cov[a][r] + lever * cov[r][r]);
  input.dof = spread.dof;
  input.km_per_day_se = distance.se;
  input.day_km_long_run_sd = distance.long_run_sd;
  input.km_per_day_dof = distance.dof;
  input.rate_long_run_variance = duty.long_run_variance;
  input.rate_long_run_dof = duty.dof;
  if (acceleration.dof == 0) return input;
  input.acceleration_dof = acceleration.dof;
  input.season_variance = season_to_come_variance(acceleration, runs);
  input.season_trend_per_day = acceleration.trend;
  input.season_departure_days = runs.back().day - km_weighted_mean_day(runs);
  // A drift fitted out keeps the straight line and no b or gamma: its terms in days take up a
  // bend of any cause (a quadratic drift is all but q on a wheel's own history), so the refit
  // would move its clearance by its drift's uncertainty, not by the wear's bend.
  if (!wheel.sensor_fault) with_fleet_bend(input, wheel.acceleration_evidence, acceleration);
  return input;
}

// The wheel's line and its own jackknife; "too few runs" when the line cannot be fitted. The
// interval and the forecasts wait for the fleet's prior (finish_wheel).
void fit_wheel(WheelWear& wheel, std::optional<double> drift_onset,
               const SensitivityAt& sensitivity) {
  const std::vector<WearObservation>& runs = wheel.runs;
  const WearSeries series = series_of(wheel, clearances(runs), sensitivity);
  try {
    wheel.fit = fit_wear_line(series, drift_onset, kDriftDegree);
  } catch (const std::invalid_argument&) {
    wheel.status = "too few runs";
    return;
  }
  wheel.own_spread = jackknife_rate(series, drift_onset, kDriftDegree, *wheel.fit,
                                    drift_onset ? kDriftBlockDays : kBlockDays);
  if (!drift_onset) wheel.history_mean = history_mean_fit(series);
  wheel.acceleration_evidence = acceleration_evidence(series, *wheel.fit, kDriftDegree);
}

// The rate and its interval from the history fit with `history_spread` (its jackknife,
// moderated), or from the line with `spread` (the line's, moderated) without one; the forecasts
// at that rate from the line's clearance now, with the line's uncertainty.
void finish_wheel(WheelWear& wheel, const FleetWear& fleet, const SerialSpread& spread,
                  const std::optional<SerialSpread>& history_spread, const WeeklyWearRate& duty) {
  const WearLineFit& fit = *wheel.fit;
  const std::vector<WearObservation>& runs = wheel.runs;
  const bool history = wheel.history_mean && history_spread;
  wheel.rate_mm_per_1000km =
      (history ? wheel.history_mean->rate_mm_per_km : fit.rate_mm_per_km) * 1000.0;
  wheel.rate_se = (history ? history_spread->rate_se : spread.rate_se) * 1000.0;
  wheel.rate_dof = history ? history_spread->dof : spread.dof;
  std::tie(wheel.rate_low, wheel.rate_high) = rate_interval(wheel, 0.95);
  const double line_half_width = t95(spread.dof) * spread.rate_se * 1000.0;
  wheel.line_rate_low = fit.rate_mm_per_km * 1000.0 - line_half_width;
  wheel.line_rate_high = fit.rate_mm_per_km * 1000.0 + line_half_width;
  wheel.clearance_now_mm = wear_line_at(fit, wheel.segment.back(), runs.back().odometer_km);
  wheel.wear_now_mm = wheel.clearance_now_mm - fleet.thresholds.sensor_gap_mm;
  wheel.forecast_input = forecast_input(wheel, spread, fleet.acceleration, duty);
  wheel.km_per_day = wheel.forecast_input.km_per_day;
  wheel.warning = forecast_limit(wheel.forecast_input, fleet.warning_clearance_mm);
  wheel.critical = forecast_limit(wheel.forecast_input, fleet.critical_clearance_mm);
}

// A rate wholly below zero is never "ok": wear only opens the clearance, so a missed reprofiling
// or a sensor fault hides the wear (negative_rate.h). Nor is a rate whose interval reaches zero
// while the fleet's wheels, at their median rate, wear more than its interval allows: the data
// cannot tell that flange's wear from none and do rule out the wear of a usual one. A sensor that
// starts drifting down as its flange is new reads so: the drift search, which fits each new
// flange a rate of its own, cannot tell it from a flange that does not wear. The fleet's median
// and kNoWearSeenDays keep a short history out, whose interval reaches zero because it is wide
// (a slow flange's, a few weeks in).
// Both on the line's interval (the wear model the forecast runs on) and, below zero, on the
// history's mean rate's as well.
void mark_negative_rate(WheelWear& wheel, double fleet_median_rate) {
  if (wheel.status != "ok" || !wheel.fit) return;
  const bool below_zero = wheel.line_rate_high < 0.0 || wheel.rate_high < 0.0;
  const double history_days = wheel.runs.back().day - wheel.runs.front().day;
  const bool no_wear_seen = wheel.line_rate_low <= 0.0 &&
                            wheel.line_rate_high < fleet_median_rate &&
                            history_days >= kNoWearSeenDays;
  if (!below_zero && !no_wear_seen) return;
  wheel.status = status_text(negative_rate_cause(series_of(wheel, clearances(wheel.runs))));
}

// The median of the wheels' rates (per 1000 km), over those with a line; 0 without one.
double median_rate(const std::vector<WheelWear>& wheels) {
  std::vector<double> rates;
  for (const WheelWear& wheel : wheels) {
    if (wheel.fit) rates.push_back(wheel.rate_mm_per_1000km);
  }
  return rates.empty() ? 0.0 : median(std::move(rates));
}

WheelWear wheel_with_runs(const WheelHistory& history, std::vector<WearObservation> runs) {
  WheelWear wheel;
  wheel.wheel = history.wheel;
  wheel.runs = std::move(runs);
  return wheel;
}

// Both wheels of an axle on the runs both have, with their shared segments.
struct AxlePair {
  WheelWear left, right;
  std::vector<double> yl, yr;  // the clearances
  std::vector<std::int64_t> run_id;
  std::set<std::size_t> new_flanges;  // the first run on each flange after the first
};

AxlePair segmented_axle(const FleetWear& fleet, const WheelHistory& left,
                        const WheelHistory& right) {
  AxleRuns axle = align_runs(left, right);
  AxlePair pair{wheel_with_runs(left, std::move(axle.left)),
                wheel_with_runs(right, std::move(axle.right)), {}, {}, {}, {}};
  pair.yl = clearances(pair.left.runs);
  pair.yr = clearances(pair.right.runs);
  for (const WearObservation& run : pair.left.runs) pair.run_id.push_back(run.run_id);
  std::vector<MaintenanceMark> marks = left.maintenance;
  marks.insert(marks.end(), right.maintenance.begin(), right.maintenance.end());
  const std::set<std::size_t> changes = recorded_changes(pair.left.runs, marks);
  const std::vector<std::size_t> found = unexplained(
      find_reprofilings(pair.yl, pair.yr, fleet.thresholds.max_step_mm), changes);
  const auto recorded = recorded_boundaries(pair.left.runs, marks);
  segment_runs(pair.left, found, recorded, changes);
  segment_runs(pair.right, found, recorded, changes);
  pair.new_flanges = recorded_changes(pair.left.runs, marks, true);
  pair.new_flanges.insert(found.begin(), found.end());
  for (const auto& [k, at] : recorded) pair.new_flanges.insert(k);
  return pair;
}

AxleSeries sum_and_difference(const AxlePair& pair) {
  std::vector<double> sum, difference;
  for (std::size_t k = 0; k < pair.yl.size(); ++k) {
    sum.push_back(pair.yl[k] + pair.yr[k]);
    difference.push_back(pair.yr[k] - pair.yl[k]);
  }
  return {pair.run_id, series_of(pair.left, sum), series_of(pair.left, difference)};
}

// The shared part of one wheel's own series: left = (sum - difference) / 2, right = (sum +
// difference) / 2, run by run where both are known.
std::map<std::int64_t, double> side_common_mode(const CommonMode& common, bool left) {
  std::map<std::int64_t, double> side;
  for (const auto& [run, sum] : common.sum_mm) {
    const auto difference = common.difference_mm.find(run);
    if (difference == common.difference_mm.end()) continue;
    side[run] = (sum + (left ? -1.0 : 1.0) * difference->second) / 2.0;
  }
  return side;
}

// The drift candidates of an axle, on what is left once the locomotive's shared part is taken
// away, at this axle's own scale (locomotive_common_mode.h), each new flange wearing at its own
// rate (new_flange_rates.h); none when the runs are too few to tell a drift from wear.
DriftCandidates axle_drift_candidates(const AxlePair& pair, const AxleSeries& both,
                                      const CommonMode& common, const SensitivityAt& sensitivity) {
  try {
    const auto shaped = [&](const WearSeries& series) {
      return with_new_flange_rates(with_shared_shapes(series, pair.run_id, common),
                                   pair.new_flanges);
    };
    return drift_candidates(
        shaped(without_common_mode(both.difference, pair.run_id, common.difference_mm)),
        shaped(without_common_mode(series_of(pair.left, pair.yl, sensitivity), pair.run_id,
                                   side_common_mode(common, true))),
        shaped(without_common_mode(series_of(pair.right, pair.yr, sensitivity), pair.run_id,
                                   side_common_mode(common, false))),
        pair.new_flanges);
  } catch (const std::invalid_argument&) {
    return {};
  }
}

// The axle's sensor fault (if any), then each wheel's own line.
void estimate_axle(FleetWear& fleet, AxlePair pair, const std::optional<DriftFinding>& drift,
                   const SensitivityAt& sensitivity) {
  WheelWear& l = pair.left;
  WheelWear& r = pair.right;
  WheelWear& faulty = drift && drift->left ? l : r;
  if (drift) {
    faulty.sensor_fault = drift;
    faulty.status = "sensor fault";
  }
  fit_wheel(l, l.sensor_fault ? std::optional(drift->onset_day) : std::nullopt, sensitivity);
  fit_wheel(r, r.sensor_fault ? std::optional(drift->onset_day) : std::nullopt, sensitivity);
  fleet.wheels.push_back(std::move(l));
  fleet.wheels.push_back(std::move(r));
}

// Every axle of one locomotive: each pair segmented, what the axles share, each axle's drift
// candidates, what a drift must reach on this locomotive (sensor_drift.h), then each axle.
void estimate_locomotive(FleetWear& fleet, const std::vector<const WheelHistory*>& lefts,
                         const std::vector<const WheelHistory*>& rights,
                         const SensitivityAt& sensitivity) {
  std::vector<AxlePair> pairs;
  std::vector<AxleSeries> series;
  for (std::size_t a = 0; a < lefts.size(); ++a) {
    pairs.push_back(segmented_axle(fleet, *lefts[a], *rights[a]));
    series.push_back(sum_and_difference(pairs.back()));
  }
  const CommonMode common = locomotive_common_mode(series);
  std::vector<DriftCandidates> candidates;
  for (std::size_t a = 0; a < pairs.size(); ++a) {
    candidates.push_back(axle_drift_candidates(pairs[a], series[a], common, sensitivity));
  }
  const LocomotiveBar bar = locomotive_bar(candidates);
  for (std::size_t a = 0; a < pairs.size(); ++a) {
    estimate_axle(fleet, std::move(pairs[a]), flagged_drift(candidates[a], bar), sensitivity);
  }
}

// A wheel without a partner: its own jumps back, no drift check (nothing to compare with).
void estimate_lone_wheel(FleetWear& fleet, const WheelHistory& history) {
  WheelWear wheel = wheel_with_runs(history, history.runs);
  const std::vector<double> y = clearances(wheel.runs);
  const std::set<std::size_t> changes = recorded_changes(wheel.runs, history.maintenance);
  segment_runs(wheel, unexplained(find_reprofilings(y, y, fleet.thresholds.max_step_mm), changes),
               recorded_boundaries(wheel.runs, history.maintenance), changes);
  fit_wheel(wheel, std::nullopt, {});
  fleet.wheels.push_back(std::move(wheel));
}

// How each locomotive's wear per km moves from week to week (weekly_wear_rate.h), from its fitted
// wheels.
std::map<std::string, WeeklyWearRate> locomotive_duties(const std::vector<WheelWear>& wheels) {
  std::map<std::string, std::vector<WeeklyWearWheel>> by_locomotive;
  for (const WheelWear& wheel : wheels) {
    auto& list = by_locomotive[wheel.wheel.locomotive];
    if (wheel.fit) list.push_back({&wheel.runs, &wheel.segment, &*wheel.fit});
  }
  std::map<std::string, WeeklyWearRate> duties;
  for (const auto& [locomotive, list] : by_locomotive) duties[locomotive] = weekly_wear_rate(list);
  return duties;
}

// The history fits' jackknifes moderated by theirs over the fleet, as the lines' are.
std::vector<std::optional<SerialSpread>> history_spreads(const std::vector<WheelWear>& wheels) {
  std::vector<SerialSpread> own;
  for (const WheelWear& wheel : wheels) {
    if (wheel.history_mean) own.push_back(wheel.history_mean->own_spread);
  }
  const InflationPrior prior = inflation_prior(own);
  std::vector<std::optional<SerialSpread>> spreads;
  for (const WheelWear& wheel : wheels) {
    if (!wheel.history_mean) {
      spreads.emplace_back();
      continue;
    }
    spreads.emplace_back(
        moderated_spread(wheel.history_mean->own_spread, prior, wheel.history_mean->rate_se));
  }
  return spreads;
}

// Every wheel's interval and forecasts, its jackknife moderated by the fleet's
// (moderated_spread.h): the prior from the wheels whose line is wear alone. A wheel with a drift
// fitted out keeps its own jackknife: its drift terms lean on the late runs in a way the others'
// lines do not. The same wheels whose line is wear alone give the fleet's acceleration
// (wear_acceleration.h), each weighted by its moderated inflation.
void finish_wheels(FleetWear& fleet) {
  std::vector<SerialSpread> plain;
  for (const WheelWear& wheel : fleet.wheels) {
    if (wheel.fit && !wheel.sensor_fault) plain.push_back(wheel.own_spread);
  }
  const InflationPrior prior = inflation_prior(plain);
  std::vector<SerialSpread> spreads;
  std::vector<AccelerationSample> samples;
  for (const WheelWear& wheel : fleet.wheels) {
    if (!wheel.fit) {
      spreads.emplace_back();
      continue;
    }
    spreads.push_back(wheel.sensor_fault
                          ? wheel.own_spread
                          : moderated_spread(wheel.own_spread, prior, wheel.fit->rate_se));
    if (!wheel.sensor_fault) {
      samples.push_back({wheel.wheel.locomotive, wheel.acceleration_evidence,
                         spreads.back().inflation, spreads.back().dof});
    }
  }
  fleet.acceleration = pool_acceleration(samples);
  const std::map<std::string, WeeklyWearRate> duties = locomotive_duties(fleet.wheels);
  const std::vector<std::optional<SerialSpread>> history = history_spreads(fleet.wheels);
  for (std::size_t i = 0; i < fleet.wheels.size(); ++i) {
    WheelWear& wheel = fleet.wheels[i];
    if (!wheel.fit) continue;
    finish_wheel(wheel, fleet, spreads[i], history[i], duties.at(wheel.wheel.locomotive));
  }
  const double fleet_median_rate = median_rate(fleet.wheels);
  for (WheelWear& wheel : fleet.wheels) mark_negative_rate(wheel, fleet_median_rate);
}

}  // namespace

std::pair<double, double> rate_interval(const WheelWear& wheel, double level) {
  const double half_width = t_quantile(level, wheel.rate_dof) * wheel.rate_se;
  return {wheel.rate_mm_per_1000km - half_width, wheel.rate_mm_per_1000km + half_width};
}

double days_to_warning(const WheelWear& wheel) {
  if (wheel.status == "too few runs") return std::numeric_limits<double>::infinity();
  if (wheel.warning.reached) return 0.0;
  return wheel.warning.days.value_or(std::numeric_limits<double>::infinity());
}

FleetWear estimate_fleet_wear(const std::vector<WheelHistory>& histories,
                              const ThresholdConfig& thresholds, const SensitivityAt& sensitivity) {
  FleetWear fleet;
  fleet.thresholds = thresholds;
  fleet.warning_clearance_mm = thresholds.warning_clearance_mm;
  fleet.critical_clearance_mm =
      thresholds.flange_nominal_mm + thresholds.sensor_gap_mm - thresholds.critical_flange_mm;
  std::map<std::pair<std::string, int>, std::pair<const WheelHistory*, const WheelHistory*>> axles;
  for (const WheelHistory& history : histories) {
    auto& pair = axles[{history.wheel.locomotive, history.wheel.axle}];
    (history.wheel.side == "left" ? pair.first : pair.second) = &history;
  }
  std::map<std::string, std::pair<std::vector<const WheelHistory*>,
                                  std::vector<const WheelHistory*>>> locomotives;
  for (const auto& [key, pair] : axles) {
    if (pair.first != nullptr && pair.second != nullptr) {
      locomotives[key.first].first.push_back(pair.first);
      locomotives[key.first].second.push_back(pair.second);
    } else {
      estimate_lone_wheel(fleet, pair.first != nullptr ? *pair.first : *pair.second);
    }
  }
  for (const auto& [locomotive, sides] : locomotives) {
    estimate_locomotive(fleet, sides.first, sides.second, sensitivity);
  }
  finish_wheels(fleet);
  std::stable_sort(fleet.wheels.begin(), fleet.wheels.end(),
                   [](const WheelWear& a, const WheelWear& b) {
                     return days_to_warning(a) < days_to_warning(b);
                   });
  return fleet;
}

}  // namespace flange::host

// SPDX-License-Identifier: MIT
#include "alarm_timing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "criteria.h"
#include "measurement_chain.h"
#include "null_replicas.h"

namespace flange::diagnose {

std::vector<AlarmChange> alarm_changes(const std::vector<double>& t,
                                       const std::vector<double>& clearance) {
  host::ThresholdStage stage{host::ThresholdConfig{}};
  std::vector<AlarmChange> changes;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const host::ThresholdOutput out = stage.step(t[i], clearance[i]);
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

bool AlarmTiming::exceeds() const { return gap_s > floor_s + criteria::kAlarmMarginS; }

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

namespace {

// The alarm-timing gap of the held-out part against the twin replayed on it, with its own floor.
AlarmTiming heldout_alarm_timing(const RecordingSeries& heldout, const std::vector<double>& sim_v,
                                 const WhiteNoise& white, const sim::PolynomialSensorModel& model,
                                 double fs_hz, std::uint64_t seed, const NullReplica& replica_of) {
  const std::vector<double> f_real =
      measurement_filter(clearance_of(model, heldout.voltage_v, heldout.temp_c), fs_hz);
  const std::vector<double> f_sim =
      measurement_filter(clearance_of(model, sim_v, heldout.temp_c), fs_hz);
  const double record_s = heldout.t_s.back() - heldout.t_s.front();
  const auto a_sim = alarm_changes(heldout.t_s, f_sim);
  std::vector<double> alarm_floor(criteria::kNullReplicas);
  for_each_null_replica(heldout, sim_v, white, model, fs_hz, sim::derive_seed(seed, 78),
                        [&](std::size_t replica, const std::vector<double>&,
                            const std::vector<double>&, const std::vector<double>& f_noisy) {
                          alarm_floor[replica] = alarm_timing_gap(
                              alarm_changes(heldout.t_s, f_noisy), a_sim, record_s);
                        },
                        replica_of);
  return alarm_timing(heldout, f_real, a_sim, alarm_floor);
}

}  // namespace

std::vector<StageGap> confirm_alarm_timing_on_heldout(const RecordingSeries& heldout,
                                                      const std::vector<double>& ho_sim_v,
                                                      const DiagnoseOptions& options,
                                                      const WhiteNoise& white, double fs_hz,
                                                      std::vector<StageGap> stages,
                                                      const NullReplica& replica_of) {
  for (StageGap& stage : stages) {
    if (stage.name != "alarm_timing" || !stage.significant) continue;
    const AlarmTiming held_out = heldout_alarm_timing(
        heldout, ho_sim_v, white, options.twin.nominal, fs_hz, options.seed,
        replica_of);
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
          criteria::kNullReplicas + 1);
    }
  }
  return stages;
}

}  // namespace flange::diagnose

// SPDX-License-Identifier: MIT
#include "stage_gaps.h"

#include <fmt/format.h>

#include "alarm_timing.h"
#include "criteria.h"
#include "gaussian_source.h"
#include "measurement_chain.h"
#include "null_replicas.h"
#include "series_statistics.h"
#include "series_arithmetic.h"

namespace flange::diagnose {

std::vector<StageGap> stage_gaps(const RecordingSeries& real, const std::vector<double>& sim_v,
                                 const WhiteNoise& white, const sim::PolynomialSensorModel& model,
                                 double fs_hz, std::uint64_t seed, const NullReplica& replica_of) {
  const std::vector<double> d_real = clearance_of(model, real.voltage_v, real.temp_c);
  const std::vector<double> d_sim = clearance_of(model, sim_v, real.temp_c);
  const std::vector<double> f_real = measurement_filter(d_real, fs_hz);
  const std::vector<double> f_sim = measurement_filter(d_sim, fs_hz);
  const double record_s = real.t_s.back() - real.t_s.front();
  const auto a_sim = alarm_changes(real.t_s, f_sim);

  // The noisy twin against the noiseless one: the floors every stage's gap is compared with.
  std::vector<double> voltage_floor(criteria::kNullReplicas),
      clearance_floor(criteria::kNullReplicas), filtered_floor(criteria::kNullReplicas),
      alarm_floor(criteria::kNullReplicas);
  for_each_null_replica(
      real, sim_v, white, model, fs_hz, sim::derive_seed(seed, 77),
      [&](std::size_t replica, const std::vector<double>& noisy_v,
          const std::vector<double>& d_noisy, const std::vector<double>& f_noisy) {
        voltage_floor[replica] = rms_of(minus(noisy_v, sim_v));
        clearance_floor[replica] = rms_of(minus(d_noisy, d_sim));
        filtered_floor[replica] = rms_of(minus(f_noisy, f_sim));
        alarm_floor[replica] = alarm_timing_gap(alarm_changes(real.t_s, f_noisy), a_sim, record_s);
      },
      replica_of);
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
                   alarm.real_changes, alarm.sim_changes, criteria::kNullReplicas)});
  for (StageGap& stage : stages) {
    stage.significant = stage.name == "alarm_timing"
                            ? alarm.exceeds()
                            : stage.gap_rms > criteria::kStageSignificanceRatio * stage.noise_floor;
  }
  return stages;
}

std::string first_significant_stage(const std::vector<StageGap>& stages) {
  for (const StageGap& stage : stages) {
    if (stage.significant) return stage.name;
  }
  return "";
}

}  // namespace flange::diagnose

// SPDX-License-Identifier: MIT
// The thesis's lab protocol (3.1.1): a micrometer moves a steel disk in front of the sensor in
// steps over 1.5-10 mm, up and down, while a heat blower takes the sensor from room temperature
// to about 98 degC and it then cools back. The DAQ samples at 6 Hz (4.3.1).
#pragma once

#include "scenario.h"

namespace flange::sim {

struct BenchProtocol {
  // Micrometer positions first, first + step, ..., last, then back down, repeated (Table 4-4
  // uses 0.5 mm steps over 1-10 mm; below 1.5 mm eq. 3.14 has no voltage at 98 degC).
  double first_position_mm = 1.5;
  double last_position_mm = 10.0;
  double step_mm = 0.5;
  double move_s = 4.0;    // turning the micrometer to the next position (a linear ramp)
  double dwell_s = 20.0;  // holding the position while the reading settles and is noted
  // Blower: on at t = 0, heating towards blower_target_c; off at blower_off_s, then cooling
  // towards room_c. Both first order.
  double room_c = 20.0;
  double blower_target_c = 99.0;  // reaches ~98.5 degC before it is switched off
  double heating_tau_s = 600.0;
  double blower_off_s = 3000.0;
  double cooling_tau_s = 900.0;
  double duration_s = 6600.0;  // back within 1.5 degC of room temperature
};

// The micrometer reading at time t (the bench's reference clearance).
double bench_clearance_mm(const BenchProtocol& protocol, double t_s);
// The temperature around the sensor and disk at time t.
double bench_temperature_c(const BenchProtocol& protocol, double t_s);

class BenchScenario final : public Scenario {
 public:
  // fs_hz > 0, duration_s >= 0 (the protocol's own duration is the usual choice).
  BenchScenario(const BenchProtocol& protocol, double fs_hz, double duration_s);

  std::int64_t sample_count() const override { return sample_count_; }
  TrueState next() override;

 private:
  BenchProtocol protocol_;
  double fs_hz_;
  std::int64_t sample_count_;
  std::int64_t next_sample_ = 0;
};

}  // namespace flange::sim

// SPDX-License-Identifier: MIT
#include "store_test_records.h"

#include <fmt/format.h>

namespace flange::testing {

std::string test_time(int day, int hour) {
  return fmt::format("2026-01-{:02d}T{:02d}:00:00Z", day + 1, 6 + hour);
}

host::RunRecord test_run(const std::string& locomotive, const std::string& started_at,
                         double odometer_km, double wear_mm) {
  host::RunRecord run;
  run.locomotive = locomotive;
  run.started_at = started_at;
  run.distance_km = 300.0;
  run.odometer_km = odometer_km;
  run.coefficient_set = "coeffs/measurement_sos.json";
  run.coefficient_sha256 = std::string(64, 'a');
  run.engine = "model";
  run.sample_rate_hz = 100.0;
  run.rows = 12000;
  run.final_alarm = "warning";
  run.summary_json = R"({"engine": "model"})";
  for (int channel = 0; channel < 12; ++channel) {
    host::WheelRunResult wheel;
    wheel.axle = channel / 2 + 1;
    wheel.side = channel % 2 ? "right" : "left";
    wheel.channel = channel;
    wheel.wear_mm = wear_mm + 0.01 * channel;
    wheel.clearance_mm = 10.0 - wheel.wear_mm.value();
    wheel.temp_c = 20.0 + channel;
    wheel.samples = 1000;
    wheel.final_alarm = channel == 0 ? "warning" : "none";
    run.wheels.push_back(wheel);
    for (int km = 0; km < 3; ++km) {
      run.trace.push_back({wheel.axle, wheel.side, static_cast<double>(km), *wheel.clearance_mm,
                           wheel.temp_c, 333});
    }
  }
  run.alarms.push_back({1, "left", 12.5, "warning"});
  run.alarms.push_back({0, "", 13.0, "wear_step 0.73 mm"});
  return run;
}

}  // namespace flange::testing

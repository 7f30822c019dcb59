// SPDX-License-Identifier: MIT
#include "twin_noise.h"

namespace flange::diagnose {

void estimate_noise(const RecordingSeries& calibration, const std::vector<double>& cal_base_v,
                    const DiagnoseOptions& options, DiagnosisDetail& detail) {
  detail.adc_grid = estimate_adc_grid(calibration.voltage_v);
  detail.white_noise = options.estimate_noise
                           ? estimate_white_noise(calibration.voltage_v, cal_base_v, detail.adc_grid)
                           : given_white_noise(options.twin.noise.voltage_std_v, detail.adc_grid);
  detail.noise_std_v = detail.white_noise.effective_std_v;
  detail.noise_source = detail.white_noise.source;
}

}  // namespace flange::diagnose

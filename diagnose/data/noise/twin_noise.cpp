// SPDX-License-Identifier: MIT
#include "twin_noise.h"

namespace flange::diagnose {

TwinNoise estimate_noise(const RecordingSeries& calibration, const std::vector<double>& cal_base_v,
                         const DiagnoseOptions& options) {
  TwinNoise noise;
  noise.adc_grid = estimate_adc_grid(calibration.voltage_v);
  noise.white_noise = options.estimate_noise
                          ? estimate_white_noise(calibration.voltage_v, cal_base_v, noise.adc_grid)
                          : given_white_noise(options.twin.noise.voltage_std_v, noise.adc_grid);
  noise.noise_std_v = noise.white_noise.effective_std_v;
  noise.noise_source = noise.white_noise.source;
  return noise;
}

}  // namespace flange::diagnose

// SPDX-License-Identifier: MIT
// The calibration loader (model.json) on any bytes: a calibration that estimates, or InputError.
#include <cstdint>

#include "calibration.h"
#include "fuzz_input_file.h"
#include "input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = flange::fuzz::write_fuzz_input(data, size, ".json");
  try {
    const flange::host::Calibration calibration = flange::host::load_calibration(path.string());
    calibration.estimate(5.0, 25.0);
  } catch (const flange::host::InputError&) {
  }
  return 0;
}

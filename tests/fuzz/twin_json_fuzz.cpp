// SPDX-License-Identifier: MIT
// The twin file loader on any bytes: a twin that simulates, or BadArgument.
#include <cstdint>

#include "fuzz_input_file.h"
#include "sensor_twin.h"
#include "sim_error.h"
#include "twin_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = flange::fuzz::write_fuzz_input(data, size, ".json");
  try {
    const flange::sim::TwinConfig config = flange::sim::load_twin(path);
    flange::sim::SensorTwin twin(config, 1);
  } catch (const flange::sim::BadArgument&) {
  }
  return 0;
}

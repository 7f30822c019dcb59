// SPDX-License-Identifier: MIT
// The filter.json loader on any bytes: a configuration the core can run, or FilterJsonError.
#include <cstdint>

#include "filter_json.h"
#include "fuzz_input_file.h"
#include "iir_core.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = flange::fuzz::write_fuzz_input(data, size, ".json");
  try {
    const flange::model::CoreConfig config = flange::model::load_core_config(path);
    // A configuration that passed every check must run: a few samples through the model.
    flange::model::IirCore core(config);
    // Samples within the set's own D-bit range (a valid set may have any width from 2 bits).
    for (const std::int32_t x : {0, 1, -1, core.sample_max(), core.sample_min()}) core.step(x);
  } catch (const flange::model::FilterJsonError&) {
  }
  try {
    flange::model::load_float_design(path);
  } catch (const flange::model::FilterJsonError&) {
  }
  return 0;
}

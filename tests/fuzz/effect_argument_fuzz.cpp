// SPDX-License-Identifier: MIT
// The --effect parser on any text: settings within their ranges, or BadArgument.
#include <cstdint>
#include <string>

#include "effect_argument.h"
#include "effect_catalogue.h"
#include "sim_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const flange::sim::EffectArgument argument = flange::sim::parse_effect_argument(text);
    flange::sim::make_effect_settings(argument.name, argument.values, "--effect");
  } catch (const flange::sim::BadArgument&) {
  }
  return 0;
}

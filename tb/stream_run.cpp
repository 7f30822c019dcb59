// SPDX-License-Identifier: MIT
#include "stream_run.h"

#include <cstdint>
#include <cstring>
#include <iostream>
#include <vector>

#include "filter_json.h"
#include "iir_core.h"

namespace flange::tb {

namespace {

std::int32_t sign_extend(std::uint32_t bits, int width) {
  const std::uint32_t mask = width >= 32 ? ~0u : (1u << width) - 1u;
  const std::uint32_t sign = 1u << (width - 1);
  return static_cast<std::int32_t>(((bits & mask) ^ sign) - sign);
}

}  // namespace

int serve_stream(const std::filesystem::path& filter_json, Dut& dut, std::FILE* in,
                 std::FILE* out, int channel) {
  model::IirCore core(model::load_core_config(filter_json));
  if (channel < 0 || channel >= core.config().num_channels) {
    std::cerr << "stream: channel " << channel << " outside 0 to " << core.config().num_channels - 1
              << "\n";
    return 2;
  }
  const int width = core.config().sample_width;
  const std::uint32_t mask = width >= 32 ? ~0u : (1u << width) - 1u;
  DutInputs reset;
  reset.rst_n = false;
  dut.clock(reset);  // the same reset edge the model's zero state stands for

  std::vector<std::int32_t> samples;
  std::vector<unsigned char> reply;
  for (;;) {
    std::uint32_t count = 0;
    if (std::fread(&count, sizeof count, 1, in) != 1 || count == 0) return 0;
    samples.resize(count);
    if (std::fread(samples.data(), sizeof(std::int32_t), count, in) != count) return 0;
    reply.resize(count * 5);
    for (std::uint32_t k = 0; k < count; ++k) {
      if (samples[k] < core.sample_min() || samples[k] > core.sample_max()) {
        std::cerr << "stream: sample " << samples[k] << " outside the " << width << "-bit range\n";
        return 2;
      }
      // Back to back: strobe in the first cycle the core is not busy, then wait for valid.
      while (dut.outputs().busy) dut.clock({});
      DutInputs strobe;
      strobe.sample_bits = static_cast<std::uint32_t>(samples[k]) & mask;
      strobe.sample_valid = true;
      strobe.channel = static_cast<std::uint32_t>(channel);
      dut.clock(strobe);
      int cycles = 1;
      DutOutputs pins = dut.outputs();
      while (!pins.sample_valid && cycles <= core.latency_cycles()) {
        dut.clock({});
        ++cycles;
        pins = dut.outputs();
      }
      const model::StepResult expected = core.step(samples[k], channel);
      const std::int32_t rtl = sign_extend(pins.sample_bits, width);
      unsigned flags = expected.saturated ? kStreamSaturated : 0u;
      if (!pins.sample_valid || rtl != expected.sample || cycles != core.latency_cycles() ||
          dut.assertion_failed()) {
        flags |= kStreamMismatch;
      }
      const std::int32_t value = pins.sample_valid ? rtl : 0;
      std::memcpy(&reply[k * 5], &value, 4);
      reply[k * 5 + 4] = static_cast<unsigned char>(flags);
    }
    std::fwrite(reply.data(), 1, reply.size(), out);
    std::fflush(out);
  }
}

}  // namespace flange::tb

// SPDX-License-Identifier: MIT
// Cycle-level co-simulation: drives the Verilated core (`dut`) and the bit-accurate model with
// the same schedule and compares every output pin in every cycle.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "iir_core.h"
#include "iir_core_dut.h"
#include "stimulus.h"

namespace flange::tb {

struct CosimReport {
  std::uint64_t cycles = 0;      // cycles simulated
  std::uint64_t accepted = 0;    // strobes the model accepted
  std::uint64_t dropped = 0;     // strobes the model dropped (overrun)
  std::uint64_t mismatches = 0;  // cycles in which some pin differed
  std::string first_mismatch;    // one line: cycle, sample index and input, DUT pins, model pins
  std::vector<std::int32_t> outputs;        // DUT sample_o in each sample_valid_o cycle
  std::vector<int> output_channels;         // DUT channel_o in those cycles
  std::vector<std::uint64_t> valid_cycles;  // those cycles
  std::vector<std::uint64_t> latencies;     // valid cycle - accept cycle, per model result
  bool saturation_seen = false;             // DUT saturation_o was high in some cycle
  bool overrun_seen = false;                // DUT overrun_o was high in some cycle
  std::uint32_t overrun_channels = 0;       // every overrun_o bit seen high
  std::uint32_t saturation_channels = 0;    // every saturation_o bit seen high
  bool channel_error_seen = false;          // DUT channel_error_o was high in some cycle
  bool rtl_assertion = false;               // an RTL assertion fired
};

std::string describe(const model::Pins& pins);

class CosimHarness {
 public:
  // `dut` must be fresh; the harness resets both sides in cycle 0.
  CosimHarness(model::CoreConfig config, std::unique_ptr<Dut> dut);

  // Runs every action of `stimulus` (cycles >= 1), then `tail` more cycles (at least the latency
  // is always added so the last output appears).
  CosimReport run(const Stimulus& stimulus, std::uint64_t tail = 0);

  model::IirCore& model() { return model_; }

 private:
  struct RunState;  // run()'s progress through the stimulus, defined with run()

  model::Pins dut_pins();
  void compare_pins(std::uint64_t cycle, const RunState& state, CosimReport& report);
  DutInputs apply_actions(std::uint64_t cycle, const Stimulus& stimulus, RunState& state,
                          CosimReport& report);
  void apply_strobe(std::uint64_t cycle, const Action& action, RunState& state,
                    CosimReport& report, DutInputs& in);

  model::IirCore model_;
  std::unique_ptr<Dut> dut;
};

}  // namespace flange::tb

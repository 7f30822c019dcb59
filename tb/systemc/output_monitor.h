// SPDX-License-Identifier: MIT
// Watches the core's outputs at every falling clock edge (mid-cycle, when the registered outputs
// of the cycle are stable) and pushes each new output (sample_valid_o high) with its sc_time into
// an sc_fifo for the scoreboard.
#pragma once

#include <cstdint>
#include <systemc>

#include "bench_records.h"

namespace flange::tb::sc {

// A fault the monitor plants in what it reports, to prove that the scoreboard catches it.
struct PlantedFault {
  enum class Kind {
    kNone,
    kWrongValue,   // the output's LSB flipped, as if the datapath were wrong
    kOneCycleLate  // the output reported a cycle later, as if the latency were one cycle longer
  };
  Kind kind = Kind::kNone;
  std::uint64_t output_index = 0;  // which output (0 = the first) gets the fault
};

class OutputMonitor : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk;
  sc_core::sc_in<std::uint32_t> sample;  // sample_o, two's complement in the low D bits
  sc_core::sc_in<bool> sample_valid;
  sc_core::sc_in<bool> busy;
  sc_core::sc_in<bool> overrun;
  sc_core::sc_in<bool> saturation;
  sc_core::sc_fifo_out<OutputRecord> observed;

  // `sample_width` is D (2..32); `clock_period` is the sc_clock's period.
  OutputMonitor(const sc_core::sc_module_name& name, int sample_width,
                const sc_core::sc_time& clock_period, PlantedFault fault = {});
  SC_HAS_PROCESS(OutputMonitor);

  std::uint64_t outputs_seen() const { return outputs_seen_; }

 private:
  void sample_pins();

  int sample_width_;
  sc_core::sc_time clock_period_;
  PlantedFault fault_;
  std::uint64_t outputs_seen_ = 0;
};

}  // namespace flange::tb::sc

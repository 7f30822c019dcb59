// SPDX-License-Identifier: MIT
// The sensor's sample clock as the core sees it: rst_ni low for the first cycles, then one EN
// strobe (sample_valid_i, one cycle) with its sample every `period_cycles` clock cycles. Every
// applied input also goes to the scoreboard through an sc_fifo.
#pragma once

#include <cstdint>
#include <systemc>
#include <vector>

#include "bench_records.h"

namespace flange::tb::sc {

struct SampleSchedule {
  std::vector<std::int32_t> samples;     // in [-2^(D-1), 2^(D-1) - 1]; one strobe each
  int sample_width = 16;                 // D, 2..32
  std::uint64_t reset_cycles = 2;        // rst_ni low in cycles 0 .. reset_cycles - 1, >= 1
  std::uint64_t first_strobe_cycle = 4;  // > reset_cycles
  std::uint64_t period_cycles = 1000;    // clock cycles from one strobe to the next, >= 1

  // The cycle of the last strobe (first_strobe_cycle when there are no samples).
  std::uint64_t last_strobe_cycle() const;
};

class SampleSource : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk;
  sc_core::sc_out<bool> rst_n;
  sc_core::sc_out<std::uint32_t> sample;  // two's complement in the low D bits
  sc_core::sc_out<bool> sample_valid;
  sc_core::sc_fifo_out<InputRecord> applied;

  SampleSource(const sc_core::sc_module_name& name, SampleSchedule schedule);
  SC_HAS_PROCESS(SampleSource);

  // All strobes have been applied.
  bool done() const { return done_; }

 private:
  void drive();
  void record(const InputRecord& input);

  SampleSchedule schedule_;
  bool done_ = false;
};

}  // namespace flange::tb::sc

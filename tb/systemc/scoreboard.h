// SPDX-License-Identifier: MIT
// Checks every output of the core against the bit-accurate model (model::IirCore): the inputs
// the sample source applied and the outputs the monitor saw arrive through sc_fifo channels; the
// model replays the inputs at their cycles and must predict each output's value, its cycle (so
// the EN-to-valid latency) and the other pins in that cycle.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <systemc>

#include "bench_records.h"
#include "iir_core.h"

namespace flange::tb::sc {

struct ScoreboardSummary {
  std::uint64_t outputs_checked = 0;   // outputs the monitor reported
  std::uint64_t mismatches = 0;        // wrong outputs + unexpected outputs + missing outputs
  std::uint64_t missing_outputs = 0;   // predicted by the model, never seen
  std::uint64_t strobes_accepted = 0;  // EN strobes the model accepted
  std::uint64_t min_latency_cycles = 0, max_latency_cycles = 0;  // observed, over all outputs
  std::string first_mismatch;  // one line, empty when there is none
};

class Scoreboard : public sc_core::sc_module {
 public:
  sc_core::sc_fifo_in<InputRecord> applied;
  sc_core::sc_fifo_in<OutputRecord> observed;

  // `clock_period` is the sc_clock's period; cycles are numbered as in bench_records.h.
  Scoreboard(const sc_core::sc_module_name& name, model::CoreConfig config,
             const sc_core::sc_time& clock_period);
  SC_HAS_PROCESS(Scoreboard);

  // After sc_start() has returned at `end`: takes what is left in the fifos and counts every
  // output the model predicted but the monitor never reported.
  ScoreboardSummary finish(const sc_core::sc_time& end);

  const model::IirCore& model() const { return model_; }

 private:
  void collect();
  void take_inputs();
  void apply_inputs_before(std::uint64_t cycle);
  void check(const OutputRecord& out);
  void mismatch(const std::string& what);

  model::IirCore model_;
  sc_core::sc_time clock_period_;
  std::deque<InputRecord> pending_inputs_;  // applied, not yet replayed into the model
  std::deque<model::StepResult> expected_;  // accepted strobes whose output is still due
  ScoreboardSummary summary_;
  bool any_latency_ = false;
};

}  // namespace flange::tb::sc

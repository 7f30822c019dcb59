// SPDX-License-Identifier: MIT
#include "scoreboard.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "cosim_harness.h"

namespace flange::tb::sc {

Scoreboard::Scoreboard(const sc_core::sc_module_name& name, model::CoreConfig config,
                       const sc_core::sc_time& clock_period)
    : sc_core::sc_module(name), model_(std::move(config)), clock_period_(clock_period) {
  SC_THREAD(collect);
}

void Scoreboard::collect() {
  for (;;) {
    wait(applied.data_written_event() | observed.data_written_event());
    take_inputs();
    OutputRecord out;
    while (observed.nb_read(out)) check(out);
  }
}

void Scoreboard::take_inputs() {
  InputRecord in;
  while (applied.nb_read(in)) pending_inputs_.push_back(in);
}

void Scoreboard::apply_inputs_before(std::uint64_t cycle) {
  // The model wants pins(c) before the inputs of cycle c, so an input waits until every output
  // of its own cycle has been checked.
  while (!pending_inputs_.empty() &&
         cycle_at(pending_inputs_.front().cycle_start, clock_period_) < cycle) {
    const InputRecord in = pending_inputs_.front();
    pending_inputs_.pop_front();
    const std::uint64_t c = cycle_at(in.cycle_start, clock_period_);
    if (in.kind == InputRecord::Kind::kReset) {
      model_.reset(c);
      // A computation in flight when reset comes never produces its output.
      std::erase_if(expected_, [c](const model::StepResult& r) { return r.valid_cycle > c; });
    } else if (const auto result = model_.strobe(c, in.sample)) {
      ++summary_.strobes_accepted;
      expected_.push_back(*result);
    }
  }
}

void Scoreboard::mismatch(const std::string& what) {
  if (summary_.mismatches == 0) summary_.first_mismatch = what;
  ++summary_.mismatches;
}

void Scoreboard::check(const OutputRecord& out) {
  const std::uint64_t cycle = cycle_at(out.seen_at, clock_period_);
  apply_inputs_before(cycle);
  ++summary_.outputs_checked;

  model::Pins got;
  got.sample = out.sample;
  got.sample_valid = true;
  got.busy = out.busy;
  got.overrun = out.overrun;
  got.saturation = out.saturation;
  const model::Pins want = model_.pins(cycle);

  // Outputs the model predicted before this one and that never came (the periods are longer
  // than the latency, so an output that came late still pairs with its own strobe).
  while (expected_.size() > 1 && expected_[1].valid_cycle <= cycle) {
    ++summary_.missing_outputs;
    mismatch(fmt::format("cycle {}: the output of the sample accepted in cycle {} never came",
                         expected_.front().valid_cycle, expected_.front().accept_cycle));
    expected_.pop_front();
  }
  if (expected_.empty()) {
    mismatch(fmt::format("cycle {} ({}): unexpected output: dut {}", cycle, out.seen_at.to_string(),
                         describe(got)));
    return;
  }
  const model::StepResult due = expected_.front();
  expected_.pop_front();
  const std::uint64_t latency = cycle - due.accept_cycle;
  if (!any_latency_) {
    summary_.min_latency_cycles = summary_.max_latency_cycles = latency;
    any_latency_ = true;
  }
  summary_.min_latency_cycles = std::min(summary_.min_latency_cycles, latency);
  summary_.max_latency_cycles = std::max(summary_.max_latency_cycles, latency);

  if (got.sample != due.sample || cycle != due.valid_cycle || !(got == want)) {
    mismatch(fmt::format(
        "cycle {} ({}): sample accepted in cycle {}: dut {} after {} cycles | model sample_o={} "
        "after {} cycles, pins {}",
        cycle, out.seen_at.to_string(), due.accept_cycle, describe(got), latency, due.sample,
        due.valid_cycle - due.accept_cycle, describe(want)));
  }
}

ScoreboardSummary Scoreboard::finish(const sc_core::sc_time& end) {
  take_inputs();
  OutputRecord out;
  while (observed.nb_read(out)) check(out);
  const std::uint64_t end_cycle = cycle_at(end, clock_period_);
  apply_inputs_before(end_cycle);
  // The run is long enough for every output (sc_main adds the latency and a margin), so anything
  // still expected is missing.
  for (const model::StepResult& due : expected_) {
    ++summary_.missing_outputs;
    mismatch(fmt::format("cycle {}: the output of the sample accepted in cycle {} never came",
                         due.valid_cycle, due.accept_cycle));
  }
  expected_.clear();
  return summary_;
}

}  // namespace flange::tb::sc

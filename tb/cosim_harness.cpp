// SPDX-License-Identifier: MIT
#include "cosim_harness.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <utility>

namespace flange::tb {

std::string describe(const model::Pins& p) {
  return fmt::format(
      "sample_o={} channel_o={} sample_valid_o={} busy_o={} overrun_o={:#x} saturation_o={:#x} "
      "channel_error_o={}",
      p.sample, p.channel, int{p.sample_valid}, int{p.busy}, p.overrun, p.saturation,
      int{p.channel_error});
}

CosimHarness::CosimHarness(model::CoreConfig config, std::unique_ptr<Dut> dut_in)
    : model_(std::move(config)), dut(std::move(dut_in)) {}

model::Pins CosimHarness::dut_pins() {
  const DutOutputs out = dut->outputs();
  const int width = model_.config().sample_width;
  model::Pins p;
  // sample_o is two's complement in the low `width` bits.
  const std::uint32_t mask = width >= 32 ? ~0u : (1u << width) - 1u;
  const std::uint32_t sign = 1u << (width - 1);
  p.sample = static_cast<std::int32_t>(((out.sample_bits & mask) ^ sign) - sign);
  p.channel = static_cast<int>(out.channel);
  p.sample_valid = out.sample_valid;
  p.busy = out.busy;
  p.overrun = out.overrun;
  p.saturation = out.saturation;
  p.channel_error = out.channel_error;
  return p;
}

namespace {

// One EN per cycle: the RTL cannot see two strobes in one cycle, the model must not either.
void require_one_action_of_a_kind_per_cycle(const Stimulus& stimulus) {
  for (std::size_t i = 1; i < stimulus.actions.size(); ++i) {
    const Action& a = stimulus.actions[i];
    for (std::size_t j = i; j-- > 0 && stimulus.actions[j].cycle == a.cycle;) {
      if (a.kind == stimulus.actions[j].kind) {
        throw std::invalid_argument(
            fmt::format("cosim stimulus: two actions of one kind in cycle {}", a.cycle));
      }
    }
  }
}

}  // namespace

struct CosimHarness::RunState {
  std::uint32_t sample_mask = 0;  // sample_i's `width` low bits
  std::size_t next = 0;           // the next action of the stimulus
  // The sample the core is working on (or last finished): its index among the strobes and its
  // input word, so that a mismatch names it.
  std::uint64_t strobes = 0;
  std::optional<std::pair<std::uint64_t, std::int32_t>> current;
};

CosimReport CosimHarness::run(const Stimulus& stimulus, std::uint64_t tail) {
  CosimReport report;
  const int width = model_.config().sample_width;
  RunState state;
  state.sample_mask = width >= 32 ? ~0u : (1u << width) - 1u;
  const std::uint64_t end = std::max<std::uint64_t>(stimulus.last_cycle(), 1) +
                            static_cast<std::uint64_t>(model_.latency_cycles()) + 1 + tail;
  require_one_action_of_a_kind_per_cycle(stimulus);
  for (std::uint64_t cycle = 0; cycle <= end; ++cycle) {
    // Compare what both sides show in this cycle (cycle 0 precedes the first reset edge).
    if (cycle > 0) compare_pins(cycle, state, report);
    dut->clock(apply_actions(cycle, stimulus, state, report));
    report.cycles = cycle + 1;
  }
  report.rtl_assertion = dut->assertion_failed();
  return report;
}

void CosimHarness::compare_pins(std::uint64_t cycle, const RunState& state, CosimReport& report) {
  const model::Pins expected = model_.pins(cycle);
  const model::Pins got = dut_pins();
  if (!(expected == got)) {
    if (report.mismatches == 0) {
      const std::string sample =
          state.current
              ? fmt::format("sample {} (input {})", state.current->first, state.current->second)
              : std::string("before the first sample");
      report.first_mismatch = fmt::format("cycle {}, {}: dut {} | model {}", cycle, sample,
                                          describe(got), describe(expected));
    }
    ++report.mismatches;
  }
  if (got.sample_valid) {
    report.outputs.push_back(got.sample);
    report.output_channels.push_back(got.channel);
    report.valid_cycles.push_back(cycle);
  }
  report.saturation_seen = report.saturation_seen || got.saturation;
  report.overrun_seen = report.overrun_seen || got.overrun;
  report.overrun_channels |= got.overrun;
  report.saturation_channels |= got.saturation;
  report.channel_error_seen = report.channel_error_seen || got.channel_error;
}

// This cycle's inputs, to the model and the DUT alike.
DutInputs CosimHarness::apply_actions(std::uint64_t cycle, const Stimulus& stimulus,
                                      RunState& state, CosimReport& report) {
  DutInputs in;
  if (cycle == 0) {
    in.rst_n = false;
    model_.reset(0);
  }
  for (; state.next < stimulus.actions.size() && stimulus.actions[state.next].cycle <= cycle;
       ++state.next) {
    const Action& action = stimulus.actions[state.next];
    if (action.cycle < cycle) continue;  // cycle 0 belongs to the harness reset
    switch (action.kind) {
      case Action::Kind::kReset:
        in.rst_n = false;
        model_.reset(cycle);
        break;
      case Action::Kind::kStrobe:
        apply_strobe(cycle, action, state, report, in);
        break;
      case Action::Kind::kClear:
        in.flag_clear = true;
        model_.clear_flags(cycle);
        break;
    }
  }
  return in;
}

void CosimHarness::apply_strobe(std::uint64_t cycle, const Action& action, RunState& state,
                                CosimReport& report, DutInputs& in) {
  const std::int32_t sample = action.sample;
  in.sample_valid = true;
  in.sample_bits = static_cast<std::uint32_t>(sample) & state.sample_mask;
  in.channel = static_cast<std::uint32_t>(action.channel);
  const auto result = model_.strobe(cycle, sample, action.channel);
  if (result) state.current = {state.strobes, sample};
  ++state.strobes;
  if (result) {
    ++report.accepted;
    report.latencies.push_back(result->valid_cycle - result->accept_cycle);
  } else if (in.rst_n) {
    ++report.dropped;
  }
}

}  // namespace flange::tb

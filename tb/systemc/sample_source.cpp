// SPDX-License-Identifier: MIT
#include "sample_source.h"

#include <limits>
#include <stdexcept>
#include <utility>

namespace flange::tb::sc {

std::uint64_t SampleSchedule::last_strobe_cycle() const {
  if (samples.empty()) return first_strobe_cycle;
  return first_strobe_cycle + (samples.size() - 1) * period_cycles;
}

SampleSource::SampleSource(const sc_core::sc_module_name& name, SampleSchedule schedule)
    : sc_core::sc_module(name), schedule_(std::move(schedule)) {
  constexpr std::uint64_t kMaxWait = std::numeric_limits<int>::max();  // wait(int n)
  if (schedule_.reset_cycles < 1 || schedule_.first_strobe_cycle <= schedule_.reset_cycles ||
      schedule_.first_strobe_cycle > kMaxWait || schedule_.period_cycles < 1 ||
      schedule_.period_cycles > kMaxWait) {
    throw std::invalid_argument(
        "SampleSource: need 1 <= reset_cycles < first_strobe_cycle <= 2^31 - 1 and "
        "1 <= period_cycles <= 2^31 - 1");
  }
  SC_CTHREAD(drive, clk.pos());
}

void SampleSource::record(const InputRecord& input) {
  // Never block: a clocked thread must not lose its edge. The scoreboard empties the fifo in
  // the next delta cycle, so a full fifo is a bench bug.
  if (!applied.nb_write(input)) {
    SC_REPORT_FATAL("SampleSource", "the scoreboard's input fifo is full");
  }
}

void SampleSource::drive() {
  // Woken at a rising edge: what is written now is sampled by the core at the next edge, i.e.
  // it is the input of the cycle that starts now.
  const int width = schedule_.sample_width;
  const std::uint32_t mask = width >= 32 ? ~0u : (1u << width) - 1u;
  rst_n.write(false);
  sample_valid.write(false);
  std::uint64_t cycle = 0;
  for (; cycle < schedule_.reset_cycles; ++cycle) {
    record({InputRecord::Kind::kReset, 0, sc_core::sc_time_stamp()});
    wait();
  }
  rst_n.write(true);
  // wait(n) counts clock edges without resuming the thread in between: a long sample period
  // costs the simulator next to nothing here.
  wait(static_cast<int>(schedule_.first_strobe_cycle - cycle));
  for (std::size_t i = 0; i < schedule_.samples.size(); ++i) {
    const std::int32_t x = schedule_.samples[i];
    sample.write(static_cast<std::uint32_t>(x) & mask);
    sample_valid.write(true);
    record({InputRecord::Kind::kStrobe, x, sc_core::sc_time_stamp()});
    wait();
    sample_valid.write(false);
    if (i + 1 < schedule_.samples.size() && schedule_.period_cycles > 1) {
      wait(static_cast<int>(schedule_.period_cycles - 1));
    }
  }
  done_ = true;
}

}  // namespace flange::tb::sc

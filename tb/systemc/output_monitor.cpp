// SPDX-License-Identifier: MIT
#include "output_monitor.h"

#include <stdexcept>

namespace flange::tb::sc {

OutputMonitor::OutputMonitor(const sc_core::sc_module_name& name, int sample_width,
                             const sc_core::sc_time& clock_period, PlantedFault fault)
    : sc_core::sc_module(name),
      sample_width_(sample_width),
      clock_period_(clock_period),
      fault_(fault) {
  if (sample_width < 2 || sample_width > 32) {
    throw std::invalid_argument("OutputMonitor: sample_width must be in 2..32");
  }
  // A method, not a thread: it runs at every clock cycle, and a method costs no context switch.
  SC_METHOD(sample_pins);
  sensitive << clk.neg();
  dont_initialize();
}

void OutputMonitor::sample_pins() {
  if (!sample_valid.read()) return;
  OutputRecord out;
  const std::uint32_t mask = sample_width_ >= 32 ? ~0u : (1u << sample_width_) - 1u;
  const std::uint32_t sign = 1u << (sample_width_ - 1);
  out.sample = static_cast<std::int32_t>(((sample.read() & mask) ^ sign) - sign);
  out.busy = busy.read();
  out.overrun = overrun.read();
  out.saturation = saturation.read();
  out.seen_at = sc_core::sc_time_stamp();
  if (fault_.kind != PlantedFault::Kind::kNone && fault_.output_index == outputs_seen_) {
    if (fault_.kind == PlantedFault::Kind::kWrongValue) out.sample ^= 1;
    if (fault_.kind == PlantedFault::Kind::kOneCycleLate) out.seen_at += clock_period_;
  }
  ++outputs_seen_;
  // The scoreboard empties the fifo in the next delta cycle: a full fifo is a bench bug.
  if (!observed.nb_write(out)) {
    SC_REPORT_FATAL("OutputMonitor", "the scoreboard's output fifo is full");
  }
}

}  // namespace flange::tb::sc

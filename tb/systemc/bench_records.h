// SPDX-License-Identifier: MIT
// What the SystemC bench's modules hand each other through sc_fifo channels: the inputs the sample
// source applied and the outputs the monitor saw, each stamped with its simulated time.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <systemc>

namespace flange::tb::sc {

// One input of the core for one clock cycle (rst_ni low, or an EN strobe with its sample).
struct InputRecord {
  enum class Kind { kReset, kStrobe };
  Kind kind = Kind::kStrobe;
  std::int32_t sample = 0;       // sample_i for kStrobe, in [-2^(D-1), 2^(D-1) - 1]
  sc_core::sc_time cycle_start;  // the rising edge that starts the cycle it is applied in
};

// The core's outputs in a cycle in which sample_valid_o was high.
struct OutputRecord {
  std::int32_t sample = 0;  // sample_o, sign-extended from D bits
  bool busy = false;
  bool overrun = false;
  bool saturation = false;
  sc_core::sc_time seen_at;  // when the monitor sampled the pins: the falling edge of that cycle
};

// sc_fifo prints its contents on request, so the records must be printable.
std::ostream& operator<<(std::ostream& os, const InputRecord& record);
std::ostream& operator<<(std::ostream& os, const OutputRecord& record);

// The cycle that `t` falls in, cycle c being [c * period, (c + 1) * period): the numbering of
// model::IirCore, whose cycle c follows the c-th rising edge (the first one at time 0).
inline std::uint64_t cycle_at(const sc_core::sc_time& t, const sc_core::sc_time& period) {
  return t.value() / period.value();
}

}  // namespace flange::tb::sc

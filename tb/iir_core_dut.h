// SPDX-License-Identifier: MIT
// The Verilated iir_core behind a small interface, so that the harness, the stimuli and the tests
// are compiled once and only this adapter is built per coefficient set (the RTL package differs).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace flange::tb {

// The inputs of rtl/iir_core.sv for one clock cycle.
struct DutInputs {
  bool rst_n = true;
  std::uint32_t sample_bits = 0;  // sample_i, two's complement in the low SampleWidth bits
  std::uint32_t channel = 0;      // channel_i
  bool sample_valid = false;
  bool flag_clear = false;
};

// The outputs of rtl/iir_core.sv in one clock cycle, as raw bits.
struct DutOutputs {
  std::uint32_t sample_bits = 0;  // sample_o
  std::uint32_t channel = 0;      // channel_o
  bool sample_valid = false;
  bool busy = false;
  std::uint32_t overrun = 0;     // overrun_o, bit c for channel c
  std::uint32_t saturation = 0;  // saturation_o, bit c for channel c
  bool channel_error = false;
};

class Dut {
 public:
  virtual ~Dut() = default;
  // The registered outputs in the current cycle.
  virtual DutOutputs outputs() = 0;
  // Drives `in` for the current cycle and applies the rising edge that ends it.
  virtual void clock(const DutInputs& in) = 0;
  // An RTL assertion ($error) fired since construction.
  virtual bool assertion_failed() const = 0;
};

// The coefficient set this binary's RTL was built for.
struct BuiltCoeffSet {
  std::string name;                   // folder name, e.g. vehicle_sos
  std::filesystem::path filter_json;  // its filter.json (the model reads it)
};
const BuiltCoeffSet& built_coeff_set();

// A fresh iir_core instance (registers 0, ROM loaded from the set's coeffs.mem). With a
// non-empty `fst_path` every half cycle is dumped there (FST).
std::unique_ptr<Dut> make_dut(const std::filesystem::path& fst_path = {});

}  // namespace flange::tb

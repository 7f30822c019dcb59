// SPDX-License-Identifier: MIT
// The filter stage of `flange run`, behind one interface: the bit-accurate model, the Verilated
// RTL (checked on the fly by the model), or the double-precision design.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace flange::host {

struct EngineSample {
  double unit = 0.0;      // the input in full-scale units, unquantised (the float engine's)
  std::int32_t word = 0;  // the same input as the core's sample word
};

struct EngineOutput {
  double unit = 0.0;       // the output in full-scale units, leftover gain applied
  bool saturated = false;  // the core clipped while computing it
  std::int32_t word = 0;   // the core's output word (model and rtl engines; 0 for float)
};

// Engines take blocks so that the RTL engine, which runs the Verilated core in a child process,
// pays one round trip per block rather than per sample.
class FilterEngine {
 public:
  virtual ~FilterEngine() = default;
  virtual std::string name() const = 0;
  // Filters `in` in order, continuing from the previous block; out gets one entry per input.
  virtual void process(const std::vector<EngineSample>& in, std::vector<EngineOutput>& out) = 0;
  // RTL engine: outputs where the RTL and the model disagreed (always 0 for the others).
  virtual std::uint64_t mismatches() const { return 0; }
};

// engine: "model", "float" or "rtl". `channel` picks one channel of a multichannel set (its own
// coefficient set when it has one; channels are independent, docs/core.md#channels). Throws
// std::invalid_argument for an unknown engine, std::out_of_range for a channel the set does not
// have and model::FilterJsonError for a bad filter.json.
std::unique_ptr<FilterEngine> make_filter_engine(const std::string& engine,
                                                 const std::filesystem::path& filter_json,
                                                 int channel = 0);

}  // namespace flange::host

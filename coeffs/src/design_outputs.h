// SPDX-License-Identifier: MIT
// What `flange design` writes: filter.json, the ROM image, the SystemVerilog parameter
// package, the frequency-response plot, and the report it prints.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "quantize.h"

namespace flange::coeffs {

// File names inside the output folder (the RTL build and the co-simulation look for these).
inline constexpr const char* kFilterJsonFile = "filter.json";
inline constexpr const char* kRomImageFile = "coeffs.mem";
inline constexpr const char* kPackageFile = "iir_coeffs_pkg.sv";
inline constexpr const char* kPlotFile = "response.svg";

// Everything known about one generated design.
// One channel's own coefficient set in a set per channel.
struct RecordChannelSet {
  FloatDesign design;
  QuantizedFilter quantized;
  QuantizedAnalysis analysis;
};

// Most channels one core serves: the model keeps a channel's sticky flags in one 32-bit mask.
inline constexpr int kMaxChannels = 32;

struct DesignRecord {
  std::string name;          // names the filter in reports and the package comment
  std::string generated_by;  // the command that made it, without --out
  FloatDesign design;
  QuantizedFilter quantized;
  QuantizedAnalysis analysis;
  // Channels that share the core (docs/core.md, "Channels"): one coefficient set for all of them
  // (channel_sets empty), or one set per channel, channel c's in channel_sets[c] (then design,
  // quantized and analysis above are channel 0's and channels == channel_sets.size()).
  int channels = 1;
  std::vector<RecordChannelSet> channel_sets;
  int coef_sets() const { return channel_sets.empty() ? 1 : static_cast<int>(channel_sets.size()); }
};

nlohmann::ordered_json filter_json(const DesignRecord& record);
std::string rom_image(const DesignRecord& record);
// The ROM's words in order: the one set, or every channel's set one after another.
std::vector<std::int64_t> all_words(const DesignRecord& record);
std::string params_package(const DesignRecord& record);
// Width of the core's channel ports: max(1, ceil(log2(channels))).
int channel_width(int channels);
// Runs gnuplot; throws std::runtime_error naming the fix when gnuplot is missing or fails.
void write_response_plot(const DesignRecord& record, const std::filesystem::path& svg_path);

// Human-readable summary printed by `flange design` and `flange demo`.
std::string design_report(const DesignRecord& record);

// Writes all outputs into `out_dir`, creating it. `with_plot` false skips the SVG.
void write_design(const DesignRecord& record, const std::filesystem::path& out_dir, bool with_plot);

}  // namespace flange::coeffs

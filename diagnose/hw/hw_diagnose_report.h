// SPDX-License-Identifier: MIT
// What `flange diagnose --hw` prints and writes: the step table and the final line on stdout;
// with --out DIR, hw_diagnosis.json, gap_steps.svg (the gap at each step, bars), traces.svg (the
// float design, the hardware and the remaining gap over time) and hw_diagnosis.html.
#pragma once

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "hw_gap.h"

namespace flange::diagnose {

struct HwDiagnosis {
  std::string coeffs;    // filter.json
  std::string stimulus;  // the --stimulus value
  std::uint64_t seed = 1;
  int sample_width = 16;  // D: the gap is in LSB of Q1.(D-1)
  // "rtl": the Verilated RTL is the real. "printed": printed coefficients (in double precision)
  // are the real, and coefficient rounding is the only effect.
  std::string mode = "rtl";
  std::string printed_source;  // "eq. 4.20" or "--tf-b/--tf-a" (printed mode)
  GapAttribution attribution;
  std::vector<double> input;  // analog, LSB
  std::vector<double> real;   // LSB
  // rtl mode: samples where the staged all-on filter and IirCore differ, where IirCore and the RTL
  // differ, and the runner's own cycle-by-cycle model checks that failed.
  std::size_t staged_vs_model = 0;
  std::size_t model_vs_rtl = 0;
  std::uint64_t runner_mismatches = 0;
  // printed mode: the analysis stops where the printed filter's output passes 10^6 x full scale.
  std::optional<std::size_t> diverged_at;
  std::size_t requested_samples = 0;

  // The gap is explained: zero after the last step, and (rtl mode) staged = model = RTL.
  bool explained() const;
  std::string final_line() const;  // one line, no newline
};

// The table (step, effect added, gap RMS and max in LSB, SNR, shrink, max |z|), then the final
// line.
void print_hw_diagnosis(const HwDiagnosis& d, std::ostream& out);

// Writes the four files into `dir` (created). Throws std::runtime_error naming the file that
// could not be written or gnuplot's failure.
void write_hw_diagnosis(const HwDiagnosis& d, const std::filesystem::path& dir);

}  // namespace flange::diagnose

// SPDX-License-Identifier: MIT
// The hardware layer of the sim-to-real diagnosis. The float design of a coefficient set is the
// sim, the Verilated RTL is the real; the gap between them on a stimulus is attributed by adding
// the fixed-point effects one at a time to the float model, greedily, down to zero (hw_gap.h).
// In printed mode the real is a printed set of direct-form coefficients instead (the thesis's
// eq. 4.20 or any given b, a), and the diagnosis says whether rounding to them alone makes the
// filter unstable.
#pragma once

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "filter_json.h"
#include "hw_diagnose_report.h"
#include "hw_stimulus.h"

namespace flange::diagnose {

struct HwRequest {
  std::filesystem::path coeffs;     // filter.json of a coefficient set (required)
  std::string stimulus = "random";  // random|fullscale|sweep|step|impulse|FILE.csv
  std::size_t samples = 10000;      // 1..10^7
  std::uint64_t seed = 1;           // random and fullscale stimuli
  bool thesis_eq_4_20 = false;      // the printed eq. 4.20 coefficients against `coeffs`
  std::vector<double> tf_b, tf_a;   // printed direct-form coefficients against `coeffs`
  bool printed() const { return thesis_eq_4_20 || !tf_b.empty() || !tf_a.empty(); }
};

// The set's core configuration and float design, and the stimulus made for them.
struct HwInputs {
  model::CoreConfig config;
  model::FloatDesign design;
  HwStimulus stimulus;
};

// Throws host::InputError naming the option or file and field that is out of range.
HwInputs load_hw_inputs(const HwRequest& request);

// The printed coefficients against the float design. Throws host::InputError for a bad printed
// set, std::runtime_error when the printed filter diverges at once.
HwDiagnosis diagnose_printed(const HwRequest& request, const HwInputs& inputs);

// The Verilated RTL (built on first use) against the float design. Throws host::InputError when
// the set's package or ROM image is missing, std::runtime_error when the RTL cannot be built or
// started. A disagreement of RTL and model is reported on `err` with the command to reproduce it.
HwDiagnosis diagnose_rtl(const HwRequest& request, const HwInputs& inputs, std::ostream& err);

}  // namespace flange::diagnose

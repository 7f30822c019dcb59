// SPDX-License-Identifier: MIT
// The double-precision filter that the fixed-point core approximates: the float design of the
// same filter.json, for fidelity measurements (SNR, error) against the bit-accurate model.
#pragma once

#include <complex>
#include <vector>

#include "filter_json.h"

namespace flange::model {

class ReferenceFilter {
 public:
  enum class Form {
    kSos,    // the float second-order sections, cascaded (what the sos hardware approximates)
    kDirect  // the whole b/a transfer function in one direct form I (poorly conditioned for
             // narrow high-order filters: use it to show why, not as the yardstick)
  };

  // The leftover gain of the design is applied to every output, as the host does.
  explicit ReferenceFilter(const FloatDesign& design, Form form = Form::kSos);

  // The core's own cascade in double: the ROM words of `config` as coefficients (b = B 2^-Fb,
  // a = -A 2^-Fa, docs/fixed_point.md), then `leftover_gain` (the design's). Against the
  // bit-accurate model it measures only the core's arithmetic; against the float design, only the
  // rounding of the coefficients. `config` must be valid (validate_core_config).
  static ReferenceFilter quantized(const CoreConfig& config, double leftover_gain);

  // The frequency response at `f_over_fs` (f / fs, 0 to 0.5), leftover gain included.
  std::complex<double> response(double f_over_fs) const;

  // One input in full-scale units (the core's sample / 2^(D-1)); returns the output in the same
  // units.
  double step(double x);
  void reset();

 private:
  ReferenceFilter(std::vector<std::vector<double>> b, std::vector<std::vector<double>> a,
                  double gain);

  Form form_;
  double gain_;
  std::vector<std::vector<double>> b_, a_;  // per stage, normalised so that a[0] = 1
  std::vector<std::vector<double>> x_, y_;  // per stage history, newest first
};

}  // namespace flange::model

// SPDX-License-Identifier: MIT
// The double-precision filter that the fixed-point core approximates: the float design of the
// same filter.json, for fidelity measurements (SNR, error) against the bit-accurate model.
#pragma once

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

  // One input in full-scale units (the core's sample / 2^(D-1)); returns the output in the same
  // units.
  double step(double x);
  void reset();

 private:
  Form form_;
  double gain_;
  std::vector<std::vector<double>> b_, a_;  // per stage, normalised so that a[0] = 1
  std::vector<std::vector<double>> x_, y_;  // per stage history, newest first
};

}  // namespace flange::model

// SPDX-License-Identifier: MIT
// From a design request (a spec, an order and cut-off, or given coefficients) to a quantised,
// analysed design record. The CLI, the demo and the benchmark all come through here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "design_outputs.h"

namespace flange::coeffs {

struct DesignRequest {
  std::string name = "iir";
  double fs_hz = 0.0;  // > 0, finite
  // Spec (all four, or none): 0 < fp < fa < fs/2, 0 < ap < aa.
  std::optional<double> fp_hz, fa_hz, ap_db, aa_db;
  // Explicit design: order in [1, 32], 0 < fc < fs/2.
  std::optional<int> order;
  std::optional<double> fc_hz;
  // Given transfer function (both, or neither): 2 to 33 finite values each, tf_a[0] != 0.
  std::vector<double> tf_b, tf_a;
  Structure structure = Structure::kSos;
  HardwareWidths widths;
  // Caps on s and F (channel sets share one format).
  std::optional<int> max_feedback_shift;
  std::optional<int> max_coef_frac_bits;
  AcceptanceLimits limits;
};

// Throws BadArgument (one line: argument and valid range) for an invalid request. A design
// that is valid but fails in hardware comes back with analysis.rejection set.
DesignRecord generate_design(const DesignRequest& request, const std::string& generated_by);

}  // namespace flange::coeffs

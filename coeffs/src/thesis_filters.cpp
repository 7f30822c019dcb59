// SPDX-License-Identifier: MIT
#include "thesis_filters.h"

namespace flange::coeffs {

const std::vector<ThesisFilter>& thesis_filters() {
  // Keep in step with coeffs/regenerate.sh; tests/coeffs/thesis_sets_test.cpp checks both.
  static const std::vector<ThesisFilter> filters = {
      {"measurement_sos",
       {"design", "--fs", "6", "--order", "5", "--fc", "0.5742", "--structure", "sos", "--name",
        "measurement"},
       false},
      {"measurement_df1",
       {"design", "--fs", "6", "--order", "5", "--fc", "0.5742", "--structure", "df1", "--name",
        "measurement"},
       false},
      {"vehicle_sos",
       {"design", "--fs", "100", "--order", "7", "--fc", "0.259", "--structure", "sos", "--name",
        "vehicle"},
       false},
      {"vehicle_df1",
       {"design", "--fs", "100", "--order", "7", "--fc", "0.259", "--structure", "df1", "--name",
        "vehicle"},
       true},
  };
  return filters;
}

const PrintedTransferFunction& thesis_eq_4_20_printed() {
  static const PrintedTransferFunction printed = {
      "eq. 4.20",
      {2.273e-15, 1.591e-14, 4.773e-14, 7.955e-14, 7.955e-14, 4.773e-14, 1.591e-14, 2.273e-15},
      {1, -6.927, 20.56, -33.92, 33.56, -19.93, 6.574, -0.9295}};
  return printed;
}

}  // namespace flange::coeffs

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

}  // namespace flange::coeffs

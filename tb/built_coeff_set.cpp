// SPDX-License-Identifier: MIT
// Names the coefficient set a test binary's RTL was Verilated for (compiled per set with
// FLANGE_COEFF_SET and FLANGE_FILTER_JSON defined by tb/CMakeLists.txt).
#include "iir_core_dut.h"

namespace flange::tb {

const BuiltCoeffSet& built_coeff_set() {
  static const BuiltCoeffSet set{FLANGE_COEFF_SET, FLANGE_FILTER_JSON};
  return set;
}

}  // namespace flange::tb

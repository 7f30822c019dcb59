// SPDX-License-Identifier: MIT
// The Verilated iir_core of one coefficient set (compiled once per set, against that set's
// Verilated model). The DUT instance is `dut`, as in every harness of the project.
#include "iir_core_dut.h"

#include <Viir_core.h>

#include "verilated_dut.h"

namespace flange::tb {

std::unique_ptr<Dut> make_dut(const std::filesystem::path& fst_path) {
  return std::make_unique<VerilatedDut<Viir_core>>(fst_path);
}

}  // namespace flange::tb

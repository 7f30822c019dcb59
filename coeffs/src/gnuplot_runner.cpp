// SPDX-License-Identifier: MIT
#include "gnuplot_runner.h"

#include <fmt/format.h>

#include <cstdio>
#include <stdexcept>

namespace flange::coeffs {

void run_gnuplot(const std::string& script, const std::string& what) {
  FILE* gnuplot = popen("gnuplot 1>&2", "w");
  if (gnuplot == nullptr) {
    throw std::runtime_error("cannot start gnuplot; install it (bash scripts/setup.sh)");
  }
  std::fwrite(script.data(), 1, script.size(), gnuplot);
  const int status = pclose(gnuplot);
  if (status != 0) {
    throw std::runtime_error(fmt::format(
        "gnuplot failed (status {}) writing {}; is gnuplot installed? (bash scripts/setup.sh)",
        status, what));
  }
}

}  // namespace flange::coeffs

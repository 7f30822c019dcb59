// SPDX-License-Identifier: MIT
// RTL line and toggle coverage of a Verilated model (docs/coverage.md). In the coverage build
// (cmake -DFLANGE_RTL_COVERAGE=ON, which scripts/rtl_coverage.sh configures) the harness calls
// write_rtl_coverage() before it destroys the model's context; in every other build it does
// nothing and needs no Verilator coverage runtime.
#pragma once

#include <verilated.h>

#if FLANGE_RTL_COVERAGE
#include <unistd.h>
#include <verilated_cov.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#endif

namespace flange::tb {

// Writes the counts `context` collected to $FLANGE_COVERAGE_DIR (default logs/coverage under the
// working directory) as <model>-<pid>-<n>-<random>.dat: a file of its own for every model instance
// of every process, since each context counts alone and CTest runs tests in parallel processes.
// scripts/rtl_coverage.sh merges them with verilator_coverage.
inline void write_rtl_coverage([[maybe_unused]] VerilatedContext& context,
                               [[maybe_unused]] const char* model) {
#if FLANGE_RTL_COVERAGE
  static std::atomic<unsigned> instances{0};
  const char* env = std::getenv("FLANGE_COVERAGE_DIR");
  const std::filesystem::path dir = env && *env ? env : "logs/coverage";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::string name = std::string(model) + "-" + std::to_string(::getpid()) + "-" +
                           std::to_string(instances++) + "-" +
                           std::to_string(std::random_device{}() & 0xFFFFFFu) + ".dat";
  context.coveragep()->write((dir / name).string().c_str());
#endif
}

}  // namespace flange::tb

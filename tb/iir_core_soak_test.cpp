// SPDX-License-Identifier: MIT
// One million full-scale random samples through the Verilated core and the model, back to back,
// every pin compared in every cycle. It prints its rate; its time is bounded by the CTest timeout.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <iostream>

#include "cosim_harness.h"
#include "filter_json.h"
#include "iir_core_dut.h"
#include "stimulus.h"

namespace flange::tb {
namespace {

TEST(IirCoreSoak, MillionRandomSamples) {
  const BuiltCoeffSet& set = built_coeff_set();
  const model::CoreConfig config = model::load_core_config(set.filter_json);
  SignalSpec spec;
  spec.sample_width = config.sample_width;
  constexpr std::size_t kSamples = 1'000'000;
  const auto samples = uniform_random(spec, kSamples, 1.0, 2024);

  const auto start = std::chrono::steady_clock::now();
  CosimHarness harness(config, make_dut());
  const auto latency = static_cast<std::uint64_t>(harness.model().latency_cycles());
  const CosimReport report = harness.run(every(samples, latency));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::cout << fmt::format(
      "[soak] {}: {} samples, {} cycles, {} mismatches, {:.1f} s "
      "({:.2f} Mcycles/s)\n",
      set.name, report.accepted, report.cycles, report.mismatches, seconds,
      static_cast<double>(report.cycles) / seconds / 1e6);
  const std::string reproduce =
      fmt::format("reproduce: ctest --test-dir {} -R '^{}' --output-on-failure", FLANGE_BINARY_DIR,
                  "VehicleSos\\.IirCoreSoak\\.MillionRandomSamples$");
  EXPECT_EQ(report.mismatches, 0u) << report.first_mismatch << "\n" << reproduce;
  EXPECT_FALSE(report.rtl_assertion) << reproduce;
  EXPECT_EQ(report.accepted, kSamples);
  EXPECT_EQ(report.outputs.size(), kSamples);
}

}  // namespace
}  // namespace flange::tb

// SPDX-License-Identifier: MIT
// The soak of the fast path (docs/benchmarks_core.md, "Soak"): N random and N full-scale samples
// of every checked-in set through IirSampleModel and the cycle model IirCore, word and flag
// compared on every sample. Usage: soak_model [SAMPLES_PER_STIMULUS] (default 5e7: 10^8 per set).
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "filter_json.h"
#include "iir_core.h"
#include "iir_sample_model.h"

namespace {

using flange::model::CoreConfig;

// Uniform over the whole input range, or a full-scale square with random half periods (1-64
// samples): the rails every time, so the sections clip.
std::int32_t next_input(bool full_scale, std::mt19937_64& rng, const CoreConfig& config,
                        std::int32_t& level, int& left) {
  const std::int32_t max = (1 << (config.sample_width - 1)) - 1;
  const std::int32_t min = -max - 1;
  if (!full_scale) return std::uniform_int_distribution<std::int32_t>(min, max)(rng);
  if (left-- <= 0) {
    level = level == max ? min : max;
    left = std::uniform_int_distribution<int>(1, 64)(rng);
  }
  return level;
}

// Mismatches between the two models on n samples of one stimulus.
std::uint64_t soak(const CoreConfig& config, bool full_scale, std::uint64_t n, std::uint64_t seed) {
  flange::model::IirCore cycle_model(config);
  flange::model::IirSampleModel sample_model(config);
  std::mt19937_64 rng(seed);
  std::int32_t level = 0;
  int left = 0;
  std::uint64_t mismatches = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::int32_t x = next_input(full_scale, rng, config, level, left);
    const flange::model::StepResult expected = cycle_model.step(x);
    const flange::model::SampleResult got = sample_model.step(x);
    if (got.sample != expected.sample || got.saturated != expected.saturated) {
      if (mismatches == 0) {
        std::printf(
            "  first mismatch at sample %llu (input %d): cycle model %d%s, sample model %d%s\n",
            static_cast<unsigned long long>(i), x, expected.sample,
            expected.saturated ? " saturated" : "", got.sample, got.saturated ? " saturated" : "");
      }
      ++mismatches;
    }
  }
  return mismatches;
}

}  // namespace

int main(int argc, char** argv) {
  const std::uint64_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 50'000'000ULL;
  std::uint64_t total_mismatches = 0;
  for (const std::string set : {"measurement_sos", "measurement_df1", "vehicle_sos"}) {
    const CoreConfig config = flange::model::load_core_config(std::string(FLANGE_SOURCE_DIR) +
                                                              "/coeffs/" + set + "/filter.json");
    for (const bool full_scale : {false, true}) {
      const auto start = std::chrono::steady_clock::now();
      const std::uint64_t mismatches = soak(config, full_scale, n, full_scale ? 2 : 1);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("%-16s %-10s %llu samples: %llu mismatches (%.1f s)\n", set.c_str(),
                  full_scale ? "fullscale" : "random", static_cast<unsigned long long>(n),
                  static_cast<unsigned long long>(mismatches), seconds);
      total_mismatches += mismatches;
    }
  }
  return total_mismatches == 0 ? 0 : 1;
}

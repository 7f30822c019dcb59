// SPDX-License-Identifier: MIT
// The sample model against the cycle model (IirCore, the specification of the RTL) under the
// fixed-point contract v2: the output word and the saturation flag must be equal on every sample,
// for every kernel that can run the configuration on this machine (two-phase, merged, vector):
// on every checked-in set and on hand-made sets of the generator's shapes, 1.1 million samples
// each (impulses, steps, full-scale squares that force saturation, random held levels, uniform
// random words over the full range); on random legal configurations; on an accumulator that wraps.
#include "iir_sample_model.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <ostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "filter_json.h"
#include "iir_core.h"
#include "iir_sample_vector.h"
#include "sample_model_configs.h"

namespace flange::model {
namespace {

constexpr SampleKernel kKernels[] = {SampleKernel::kTwoPhase, SampleKernel::kMerged,
                                     SampleKernel::kVector, SampleKernel::kVectorMerged};

std::vector<SampleKernel> available_kernels(const CoreConfig& config) {
  std::vector<SampleKernel> kernels;
  for (const SampleKernel k : kKernels) {
    if (IirSampleModel::kernel_available(config, k)) kernels.push_back(k);
  }
  return kernels;
}

// A stimulus made of named segments, fed as one stream (the state carries across segments).
struct Stimulus {
  std::vector<std::int32_t> samples;
  std::vector<std::pair<std::size_t, std::string>> segments;  // first index, what

  void begin(const std::string& what) { segments.emplace_back(samples.size(), what); }
  void hold(std::int32_t value, std::size_t n) { samples.insert(samples.end(), n, value); }
  std::string segment_of(std::size_t index) const {
    std::string what;
    for (const auto& [first, name] : segments) {
      if (first <= index) what = name;
    }
    return what;
  }
};

// A uniform word in [lo, hi] from the raw generator, the same on every platform.
std::int32_t uniform_word(std::mt19937_64& rng, std::int32_t lo, std::int32_t hi) {
  const auto span = static_cast<std::uint64_t>(std::int64_t{hi} - lo) + 1;
  return static_cast<std::int32_t>(lo + static_cast<std::int64_t>(rng() % span));
}

// 1,100,000 samples for D-bit words.
Stimulus million_sample_stimulus(int sample_width, std::uint64_t seed) {
  const auto hi = static_cast<std::int32_t>((std::int64_t{1} << (sample_width - 1)) - 1);
  const std::int32_t lo = -hi - 1;
  std::mt19937_64 rng(seed);
  Stimulus s;
  constexpr std::size_t kRest = 20'000;  // long enough for the narrowest set to ring down mostly
  for (const std::int32_t height : {hi, lo, std::int32_t{1}, std::int32_t{-1}, hi / 2}) {
    s.begin("impulse of " + std::to_string(height));
    s.hold(height, 1);
    s.hold(0, kRest - 1);
  }
  for (const auto& [from, to] : std::vector<std::pair<std::int32_t, std::int32_t>>{
           {0, hi}, {hi, lo}, {lo, 0}, {0, lo}, {lo, hi}}) {
    s.begin("step from " + std::to_string(from) + " to " + std::to_string(to));
    s.hold(to, kRest);
  }
  for (const std::size_t period : {2, 3, 4, 5, 8, 13, 32, 100, 1000, 10000}) {
    s.begin("full-scale square of period " + std::to_string(period));
    for (std::size_t n = 0; n < kRest; ++n) s.hold(2 * (n % period) < period ? hi : lo, 1);
  }
  s.begin("random held levels");
  while (s.samples.size() < 500'000) {
    // One draw after the other: the order of a call's argument evaluations is unspecified.
    const std::int32_t level = uniform_word(rng, lo, hi);
    s.hold(level, static_cast<std::size_t>(1 + rng() % 2000));
  }
  s.begin("uniform random over the full range");
  while (s.samples.size() < 1'100'000) s.hold(uniform_word(rng, lo, hi), 1);
  return s;
}

// IirCore::step on every sample: the expected results.
std::vector<SampleResult> core_results(const CoreConfig& config,
                                       const std::vector<std::int32_t>& x) {
  IirCore core(config);
  std::vector<SampleResult> want;
  want.reserve(x.size());
  for (const std::int32_t v : x) {
    const StepResult r = core.step(v);
    want.push_back({r.sample, r.saturated});
  }
  return want;
}

struct Comparison {
  std::size_t mismatches = 0;
  std::size_t first_mismatch = 0;
  std::size_t saturated = 0;  // samples flagged by the cycle model
  std::size_t nonzero = 0;    // outputs that are not 0
  SampleResult want, got;
};

// Feeds the sample model (one kernel) the stream in blocks through filter() and compares.
Comparison compare(const CoreConfig& config, const std::vector<std::int32_t>& x,
                   const std::vector<SampleResult>& want, SampleKernel kernel) {
  IirSampleModel fast(config, kernel);
  EXPECT_EQ(fast.kernel(), kernel);
  std::vector<SampleResult> got(x.size());
  constexpr std::size_t kBlock = 4093;  // blocks of odd length: the kernels' edges move around
  for (std::size_t start = 0; start < x.size(); start += kBlock) {
    const std::size_t n = std::min(kBlock, x.size() - start);
    fast.filter(std::span(x).subspan(start, n), std::span(got).subspan(start, n));
  }
  Comparison c;
  for (std::size_t i = 0; i < x.size(); ++i) {
    c.saturated += want[i].saturated ? 1 : 0;
    c.nonzero += want[i].sample != 0 ? 1 : 0;
    if (want[i] != got[i] && c.mismatches++ == 0) {
      c.first_mismatch = i;
      c.want = want[i];
      c.got = got[i];
    }
  }
  return c;
}

struct SetCase {
  std::string name;  // CamelCase, for the test name
  std::string what;  // the file, or "hand-made"
  std::function<CoreConfig()> load;
  bool saturates = true;  // whether the stimulus can reach a clip
};

std::vector<SetCase> every_set() {
  const std::filesystem::path root(FLANGE_SOURCE_DIR);
  std::vector<SetCase> sets;
  const auto file = [&](const std::string& name, const std::filesystem::path& json,
                        bool saturates) {
    sets.push_back({name, json.string(), [json] { return load_core_config(json); }, saturates});
  };
  file("MeasurementSos", root / "coeffs/measurement_sos/filter.json", true);
  file("MeasurementDf1", root / "coeffs/measurement_df1/filter.json", true);
  file("VehicleSos", root / "coeffs/vehicle_sos/filter.json", true);
  for (const int order : {1, 2, 3, 4, 8, 12}) {
    // A first-order low-pass does not overshoot: its output stays inside the input's range.
    file("SosOrder" + std::to_string(order),
         root / "tests/data/coeffs" / ("sos_order" + std::to_string(order)) / "filter.json",
         order > 1);
  }
  for (const testing::NamedConfig& named : testing::hand_made_configs()) {
    const CoreConfig config = named.config;
    sets.push_back(
        {"HandMade" + named.name, "hand-made " + config.name, [config] { return config; }, true});
  }
  return sets;
}

// gtest prints the parameter in the test's listing: the file, not its bytes.
void PrintTo(const SetCase& set, std::ostream* os) { *os << set.what; }

class IirSampleModelSet : public ::testing::TestWithParam<SetCase> {};

TEST_P(IirSampleModelSet, EveryKernelMatchesIirCoreOnEverySample) {
  const CoreConfig config = GetParam().load();
  const Stimulus stimulus = million_sample_stimulus(config.sample_width, 20261122);
  ASSERT_GE(stimulus.samples.size(), 1'000'000u);
  const std::vector<SampleResult> want = core_results(config, stimulus.samples);
  const std::string reproduce = "reproduce: ctest --test-dir build -R 'IirSampleModelSet.*" +
                                GetParam().name + "' --output-on-failure";
  // Generated sets never wrap (docs/fixed_point.md) and fit the merged kernel's int64 sums.
  EXPECT_FALSE(IirSampleModel(config).accumulator_can_wrap()) << reproduce;
  EXPECT_TRUE(IirSampleModel::kernel_available(config, SampleKernel::kMerged)) << reproduce;
  for (const SampleKernel kernel : available_kernels(config)) {
    const Comparison c = compare(config, stimulus.samples, want, kernel);
    EXPECT_EQ(c.mismatches, 0u) << to_string(kernel) << " kernel: " << c.mismatches
                                << " mismatches, first at sample " << c.first_mismatch << " ("
                                << stimulus.segment_of(c.first_mismatch) << "): IirCore "
                                << c.want.sample << (c.want.saturated ? " saturated" : "")
                                << ", IirSampleModel " << c.got.sample
                                << (c.got.saturated ? " saturated" : "") << "\n"
                                << reproduce;
    // The stimulus reaches the clips and the outputs move: the equality is not a trivial one.
    EXPECT_EQ(c.saturated > 0, GetParam().saturates) << c.saturated << " saturated\n" << reproduce;
    EXPECT_GT(c.nonzero, stimulus.samples.size() / 2) << reproduce;
    std::cout << GetParam().name << ": " << to_string(kernel) << " kernel equal on "
              << stimulus.samples.size() << " samples (" << c.saturated << " saturated)\n";
  }
}

INSTANTIATE_TEST_SUITE_P(EveryCheckedInSet, IirSampleModelSet, ::testing::ValuesIn(every_set()),
                         [](const ::testing::TestParamInfo<SetCase>& set) {
                           return set.param.name;
                         });

// One first-order section, 8-bit samples and words (L = 7), F = 1, s = 0, P = 16; every lo and hi
// word 127, E[1] = 1. A constant 127: the first sum acc = 127 + 127 * 127 = 16256 clips y_ext to
// 127, e = -1. The second lo = 2^7 + 3 * 127 * 127 = 48515 leaves 16 bits and wraps to -17021,
// >>> 7 = -133; acc = -133 + 3 * 127 * 127 - 1 = 48253 wraps to -17283, y_ext = -8642, clipped to
// -128. Without the wraps acc would be 379 + 48387 - 1 = 48765 and y_ext 127.
CoreConfig wrapping_config() {
  CoreConfig c;
  c.name = "wrapping";
  c.filter_order = 1;
  c.num_sections = 1;
  c.section_order = 1;
  c.sample_width = 8;
  c.coef_width = 8;
  c.coef_frac_bits = 1;
  c.feedback_shift = 0;
  c.acc_width = 16;
  c.rom = {127, 127, 127, 127, 127, 127, 1};  // W_b[0..1], W_a[1], H_b[0..1], H_a[1], E[1]
  return c;
}

TEST(IirSampleModel, AccumulatorWrapsLikeIirCore) {
  IirCore core(wrapping_config());
  IirSampleModel fast(wrapping_config());
  EXPECT_TRUE(fast.accumulator_can_wrap());
  EXPECT_EQ(fast.kernel(), SampleKernel::kTwoPhase);
  EXPECT_FALSE(IirSampleModel::kernel_available(wrapping_config(), SampleKernel::kMerged));
  EXPECT_FALSE(IirSampleModel::kernel_available(wrapping_config(), SampleKernel::kVector));
  EXPECT_FALSE(IirSampleModel::kernel_available(wrapping_config(), SampleKernel::kVectorMerged));
  EXPECT_THROW(IirSampleModel(wrapping_config(), SampleKernel::kMerged), std::invalid_argument);
  const SampleResult first = fast.step(127);
  EXPECT_EQ(first, (SampleResult{127, true}));
  EXPECT_EQ(core.step(127).sample, 127);
  const SampleResult second = fast.step(127);
  EXPECT_EQ(second, (SampleResult{-128, true})) << "without the wrap it would stay at 127";
  const StepResult want = core.step(127);
  EXPECT_EQ(second, (SampleResult{want.sample, want.saturated}));
  CoreConfig wide = wrapping_config();
  wide.acc_width = 64;
  IirCore unwrapped(wide);
  unwrapped.step(127);
  EXPECT_EQ(unwrapped.step(127).sample, 127) << "the wrap is what makes -128";
  // And on a longer stream of every kind.
  const std::vector<std::int32_t> x = million_sample_stimulus(8, 5).samples;
  const std::vector<std::int32_t> head(x.begin(), x.begin() + 200'000);
  const Comparison c = compare(wrapping_config(), head, core_results(wrapping_config(), head),
                               SampleKernel::kTwoPhase);
  EXPECT_EQ(c.mismatches, 0u) << "first at sample " << c.first_mismatch;
}

// A uniform whole number in [lo, hi] and a uniform real in [lo, hi) from the raw generator.
int pick(std::mt19937_64& rng, int lo, int hi) {
  return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1));
}
double real(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// The shape and widths of a random configuration of `kind` (0, 1: random words; 2: random words,
// wide P; 3: stable sections).
void draw_widths(std::mt19937_64& rng, int kind, CoreConfig& c) {
  c.num_sections = kind >= 2 ? pick(rng, 1, 8) : pick(rng, 1, 4);  // up to 8 vector lanes
  c.section_order = kind == 3 ? pick(rng, 1, 2) : pick(rng, 1, 4);
  c.filter_order = c.num_sections * c.section_order;
  if (kind == 3) {
    c.coef_width = pick(rng, 10, 18);
    c.coef_frac_bits = c.coef_width - 3;  // words up to +-4: any stable biquad
    c.sample_width = pick(rng, 4, 16);
    c.feedback_shift =
        pick(rng, std::max(0, c.coef_frac_bits - c.sample_width), 25 - c.sample_width);
  } else {
    c.sample_width = pick(rng, 2, 16);
    c.coef_width = pick(rng, 2, 18);
    c.feedback_shift = pick(rng, 0, 25 - c.sample_width);
    c.coef_frac_bits = pick(rng, 1, c.sample_width + c.feedback_shift);
  }
  const int d_ext = c.sample_width + c.feedback_shift;
  const int min_acc = std::max(
      {c.coef_frac_bits + d_ext, d_ext + c.coef_width, c.coef_frac_bits + c.split_shift()});
  c.acc_width = kind <= 1 ? min_acc : std::min(64, min_acc + pick(rng, 1, 24));
}

// A stable section's words: poles of radius < 1, zeros anywhere in [-2, 2].
void append_stable_section(std::mt19937_64& rng, CoreConfig& c) {
  testing::FloatSection s;
  const double r = real(rng, 0.0, 0.999), theta = real(rng, 0.0, 3.14159);
  s.a = c.section_order == 2 ? std::vector<double>{1.0, -2 * r * std::cos(theta), r * r}
                             : std::vector<double>{1.0, -r};
  for (int i = 0; i <= c.section_order; ++i) s.b.push_back(real(rng, -2.0, 2.0));
  const std::vector<std::int64_t> words = testing::quantize_section(
      s, {c.sample_width, c.coef_width, c.coef_frac_bits, c.feedback_shift, c.acc_width}, false);
  c.rom.insert(c.rom.end(), words.begin(), words.end());
}

// A section of random words: lo words in [0, 2^L), hi words any signed C-bit word, E in [-3, 3].
void append_random_section(std::mt19937_64& rng, CoreConfig& c) {
  const int m = c.section_order;
  const int split = c.split_shift();
  const auto hi_max = (std::int64_t{1} << (c.coef_width - 1)) - 1;
  for (int i = 0; i < 2 * m + 1; ++i) {  // lo words
    c.rom.push_back(static_cast<std::int64_t>(rng() >> (64 - split)));
  }
  for (int i = 0; i < 2 * m + 1; ++i) {  // hi words
    c.rom.push_back(static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(2 * hi_max + 2)) -
                    hi_max - 1);
  }
  for (int j = 1; j <= m; ++j) {  // error-feedback words
    c.rom.push_back(std::clamp<std::int64_t>(pick(rng, -3, 3), -hi_max - 1, hi_max));
  }
}

// A random legal configuration of contract v2 (see the test below).
CoreConfig random_configuration(std::mt19937_64& rng) {
  CoreConfig c;
  c.name = "random";
  const int kind = pick(rng, 0, 3);
  draw_widths(rng, kind, c);
  for (int k = 0; k < c.num_sections; ++k) {
    if (kind == 3) {
      append_stable_section(rng, c);
    } else {
      append_random_section(rng, c);
    }
  }
  return c;
}

// 6000 samples for D-bit words: uniform random words over the full range, a full-scale square, an
// impulse and its ring-down, small uniform random words.
std::vector<std::int32_t> random_configuration_stimulus(std::mt19937_64& rng, int sample_width) {
  const auto hi = static_cast<std::int32_t>((std::int64_t{1} << (sample_width - 1)) - 1);
  const std::int32_t lo = -hi - 1;
  std::vector<std::int32_t> x;
  for (int n = 0; n < 2000; ++n) x.push_back(uniform_word(rng, lo, hi));
  for (int n = 0; n < 2000; ++n) x.push_back(n % 7 < 3 ? hi : lo);
  for (int n = 0; n < 1000; ++n) x.push_back(n == 0 ? hi : 0);
  for (int n = 0; n < 1000; ++n) x.push_back(uniform_word(rng, lo / 8, hi / 8));
  return x;
}

// Random legal configurations of contract v2: lo words in [0, 2^L), hi words any signed C-bit
// word, E small integers; most of them unstable, many wrapping (the narrowest accumulator), some
// quantised stable sections. Every kernel must agree with IirCore wherever the contract allows
// the configuration, not only where the generator's sets live.
TEST(IirSampleModel, MatchesIirCoreOnRandomConfigurations) {
  std::mt19937_64 rng(7);
  int can_wrap = 0, wrapped = 0, saturating = 0;
  std::map<SampleKernel, int> runs;
  constexpr int kTrials = 300;
  for (int trial = 0; trial < kTrials; ++trial) {
    const CoreConfig c = random_configuration(rng);
    ASSERT_NO_THROW(validate_core_config(c)) << "trial " << trial;
    const std::vector<std::int32_t> x = random_configuration_stimulus(rng, c.sample_width);
    const std::vector<SampleResult> want = core_results(c, x);
    for (const SampleKernel kernel : available_kernels(c)) {
      const Comparison r = compare(c, x, want, kernel);
      ASSERT_EQ(r.mismatches, 0u) << "trial " << trial << ", " << to_string(kernel)
                                  << " kernel: first at sample " << r.first_mismatch << ": IirCore "
                                  << r.want.sample << " " << r.want.saturated << ", IirSampleModel "
                                  << r.got.sample << " " << r.got.saturated
                                  << "\nreproduce: ctest --test-dir build -R "
                                     "IirSampleModel.MatchesIirCoreOnRandomConfigurations";
      ++runs[kernel];
    }
    if (IirSampleModel(c).accumulator_can_wrap()) {
      ++can_wrap;
      // The wrap did happen if a 64-bit accumulator (which cannot wrap here) gives other outputs.
      CoreConfig wide = c;
      wide.acc_width = 64;
      if (core_results(wide, x) != want) ++wrapped;
    }
    bool any_saturated = false;
    for (const SampleResult& r : want) any_saturated = any_saturated || r.saturated;
    saturating += any_saturated ? 1 : 0;
  }
  std::cout << "random configurations: " << can_wrap << " can wrap, " << wrapped << " wrapped, "
            << saturating << " saturating; runs: two-phase " << runs[SampleKernel::kTwoPhase]
            << ", merged " << runs[SampleKernel::kMerged] << ", vector "
            << runs[SampleKernel::kVector] << ", vector-merged "
            << runs[SampleKernel::kVectorMerged] << "\n";
  EXPECT_EQ(runs[SampleKernel::kTwoPhase], kTrials);
  EXPECT_GT(wrapped, 30) << "too few configurations whose sum wraps";
  EXPECT_GT(saturating, 50) << "too few configurations that saturate";
  EXPECT_GT(runs[SampleKernel::kMerged], 60) << "the merged kernel is barely exercised";
  if (IirSampleModel::kernel_available(testing::hand_made_configs().front().config,
                                       SampleKernel::kVector)) {
    EXPECT_GT(runs[SampleKernel::kVector], 60) << "the vector kernel is barely exercised";
  }
  if (IirSampleModel::kernel_available(testing::hand_made_configs().front().config,
                                       SampleKernel::kVectorMerged)) {
    EXPECT_GT(runs[SampleKernel::kVectorMerged], 60)
        << "the vector-merged kernel is barely exercised";
  }
}

TEST(IirSampleModel, StepAndFilterAndResetAgree) {
  const CoreConfig config = testing::hand_made_configs().front().config;
  const std::vector<std::int32_t> x = million_sample_stimulus(config.sample_width, 3).samples;
  const std::vector<std::int32_t> head(x.begin(), x.begin() + 50'000);
  for (const SampleKernel kernel : available_kernels(config)) {
    IirSampleModel by_step(config, kernel), by_block(config, kernel);
    std::vector<SampleResult> blocked(head.size());
    by_block.filter(head, blocked);
    for (std::size_t i = 0; i < head.size(); ++i) {
      ASSERT_EQ(by_step.step(head[i]), blocked[i]) << to_string(kernel) << ", sample " << i;
    }
    by_block.reset();
    IirSampleModel fresh(config, kernel);
    for (std::size_t i = 0; i < 1000; ++i) {
      ASSERT_EQ(by_block.step(head[i]), fresh.step(head[i]))
          << to_string(kernel) << ", after reset, sample " << i;
    }
  }
}

// Blocks of random length, 1 to 300: the vector kernel hands blocks under 64 samples to the merged
// one, so the two alternate on one state; every kernel must still match IirCore on every sample.
TEST(IirSampleModel, BlocksOfAnyLengthMatchIirCore) {
  for (const testing::NamedConfig& named : testing::hand_made_configs()) {
    const CoreConfig& config = named.config;
    const std::vector<std::int32_t> head = [&] {
      const std::vector<std::int32_t> x = million_sample_stimulus(config.sample_width, 9).samples;
      // Impulses and steps first, then the full-scale squares (from 200'000 on), then random.
      std::vector<std::int32_t> picked(x.begin(), x.begin() + 60'000);
      picked.insert(picked.end(), x.begin() + 200'000, x.begin() + 260'000);
      picked.insert(picked.end(), x.end() - 60'000, x.end());
      return picked;
    }();
    const std::vector<SampleResult> want = core_results(config, head);
    for (const SampleKernel kernel : available_kernels(config)) {
      IirSampleModel fast(config, kernel);
      std::mt19937_64 rng(17);
      std::vector<SampleResult> got(head.size());
      for (std::size_t start = 0; start < head.size();) {
        const std::size_t n = std::min<std::size_t>(1 + rng() % 300, head.size() - start);
        fast.filter(std::span(head).subspan(start, n), std::span(got).subspan(start, n));
        start += n;
      }
      for (std::size_t i = 0; i < head.size(); ++i) {
        ASSERT_EQ(got[i], want[i])
            << named.name << ", " << to_string(kernel) << " kernel, sample " << i;
      }
    }
  }
}

TEST(IirSampleModel, AutoTakesTheFastestExactKernel) {
  for (const testing::NamedConfig& named : testing::hand_made_configs()) {
    const IirSampleModel model(named.config);
    // On AMD the merged sums' 64-bit products are the faster vector kernel, on Intel the split
    // sums' multiply-adds (model/iir_sample_vector.h).
    std::vector<SampleKernel> order = {SampleKernel::kVector, SampleKernel::kVectorMerged};
    if (vector::merged_preferred()) std::swap(order[0], order[1]);
    order.push_back(SampleKernel::kMerged);
    SampleKernel want = SampleKernel::kTwoPhase;
    for (const SampleKernel k : order) {
      if (IirSampleModel::kernel_available(named.config, k)) {
        want = k;
        break;
      }
    }
    EXPECT_EQ(model.kernel(), want) << named.name;
    EXPECT_FALSE(model.accumulator_can_wrap()) << named.name;
  }
  EXPECT_STREQ(to_string(SampleKernel::kVector), "vector");
  EXPECT_STREQ(to_string(SampleKernel::kVectorMerged), "vector-merged");
}

TEST(IirSampleModel, RejectsIllegalInputAndKeepsItsState) {
  const CoreConfig config = testing::hand_made_configs().front().config;
  for (const SampleKernel kernel : available_kernels(config)) {
    IirSampleModel fast(config, kernel), twin(config, kernel);
    EXPECT_EQ(fast.step(12345), twin.step(12345));
    EXPECT_THROW(fast.step(32768), std::out_of_range);
    EXPECT_THROW(fast.step(-32769), std::out_of_range);
    const std::vector<std::int32_t> bad = {1, 2, 40000};
    std::vector<SampleResult> out(bad.size());
    EXPECT_THROW(fast.filter(bad, out), std::out_of_range);
    std::vector<SampleResult> short_out(2);
    EXPECT_THROW(fast.filter(bad, short_out), std::invalid_argument);
    EXPECT_EQ(fast.step(-20000), twin.step(-20000)) << "a refused input changed the state";
  }
  CoreConfig broken = config;
  broken.rom.pop_back();
  EXPECT_THROW(IirSampleModel{broken}, std::invalid_argument);
  CoreConfig two = config;
  two.num_channels = 2;
  EXPECT_THROW(IirSampleModel{two}, std::invalid_argument) << "one channel only";
}

}  // namespace
}  // namespace flange::model

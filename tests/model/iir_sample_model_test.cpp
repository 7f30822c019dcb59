// SPDX-License-Identifier: MIT
// The sample model against the cycle model (IirCore, the specification of the RTL): the output
// word and the saturation flag must be equal on every sample, for every checked-in set on
// 1.1 million samples each (uniform random over the full input range, full-scale squares and
// alternation that force saturation, impulses, steps and random held levels), on random legal
// configurations, and on an accumulator that wraps.
#include "iir_sample_model.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "filter_json.h"
#include "iir_core.h"

namespace flange::model {
namespace {

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
    s.hold(uniform_word(rng, lo, hi), static_cast<std::size_t>(1 + rng() % 2000));
  }
  s.begin("uniform random over the full range");
  while (s.samples.size() < 1'100'000) s.hold(uniform_word(rng, lo, hi), 1);
  return s;
}

struct Comparison {
  std::size_t mismatches = 0;
  std::size_t first_mismatch = 0;
  std::size_t saturated = 0;  // samples flagged by the cycle model
  std::size_t nonzero = 0;    // outputs that are not 0
  SampleResult want, got;
};

// Steps IirCore and feeds the sample model the same stream in blocks through filter().
Comparison compare(const CoreConfig& config, const std::vector<std::int32_t>& x) {
  IirCore core(config);
  IirSampleModel fast(config);
  std::vector<SampleResult> got(x.size());
  constexpr std::size_t kBlock = 4096;
  for (std::size_t start = 0; start < x.size(); start += kBlock) {
    const std::size_t n = std::min(kBlock, x.size() - start);
    fast.filter(std::span(x).subspan(start, n), std::span(got).subspan(start, n));
  }
  Comparison c;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const StepResult r = core.step(x[i]);
    const SampleResult want{r.sample, r.saturated};
    c.saturated += want.saturated ? 1 : 0;
    c.nonzero += want.sample != 0 ? 1 : 0;
    if (want != got[i]) {
      if (c.mismatches++ == 0) {
        c.first_mismatch = i;
        c.want = want;
        c.got = got[i];
      }
    }
  }
  return c;
}

struct SetCase {
  std::string name;  // CamelCase, for the test name
  std::filesystem::path json;
  bool saturates = true;  // whether the stimulus can reach a clip
};

std::vector<SetCase> every_set() {
  const std::filesystem::path root(FLANGE_SOURCE_DIR);
  std::vector<SetCase> sets = {
      {"MeasurementSos", root / "coeffs/measurement_sos/filter.json"},
      {"MeasurementDf1", root / "coeffs/measurement_df1/filter.json"},
      {"VehicleSos", root / "coeffs/vehicle_sos/filter.json"},
  };
  for (const int order : {1, 2, 3, 4, 8, 12}) {
    // A first-order low-pass does not overshoot: its output stays inside the input's range.
    sets.push_back(
        {"SosOrder" + std::to_string(order),
         root / "tests/data/coeffs" / ("sos_order" + std::to_string(order)) / "filter.json",
         order > 1});
  }
  return sets;
}

// gtest prints the parameter in the test's listing: the file, not its bytes.
void PrintTo(const SetCase& set, std::ostream* os) { *os << set.json.string(); }

class IirSampleModelSet : public ::testing::TestWithParam<SetCase> {};

TEST_P(IirSampleModelSet, MatchesIirCoreOnEverySample) {
  const CoreConfig config = load_core_config(GetParam().json);
  const Stimulus stimulus = million_sample_stimulus(config.sample_width, 20261122);
  ASSERT_GE(stimulus.samples.size(), 1'000'000u);
  const Comparison c = compare(config, stimulus.samples);
  const std::string reproduce = "reproduce: ctest --test-dir build -R 'IirSampleModelSet.*" +
                                GetParam().name + "' --output-on-failure";
  EXPECT_EQ(c.mismatches, 0u) << "first at sample " << c.first_mismatch << " ("
                              << stimulus.segment_of(c.first_mismatch) << "): IirCore "
                              << c.want.sample << (c.want.saturated ? " saturated" : "")
                              << ", IirSampleModel " << c.got.sample
                              << (c.got.saturated ? " saturated" : "") << "\n"
                              << reproduce;
  // The stimulus reaches the clips and the outputs move: the equality is not a trivial one.
  EXPECT_EQ(c.saturated > 0, GetParam().saturates) << c.saturated << " saturated\n" << reproduce;
  EXPECT_GT(c.nonzero, stimulus.samples.size() / 2) << reproduce;
  // Generated sets never wrap (docs/fixed_point.md), so this is the path without the wrap.
  EXPECT_FALSE(IirSampleModel(config).accumulator_can_wrap()) << reproduce;
}

INSTANTIATE_TEST_SUITE_P(EveryCheckedInSet, IirSampleModelSet, ::testing::ValuesIn(every_set()),
                         [](const ::testing::TestParamInfo<SetCase>& set) {
                           return set.param.name;
                         });

// One section of order 1, 8-bit samples and words, Fa = Fb = 1, P = 16: B0 = B1 = -A1 = 127.
// A constant 127 clips y_ext to 127 on the first sample; on the second the sum
// 1 + 3 * 127 * 127 = 48388 leaves 16 bits and wraps to -17148, so y_ext = -8574, clipped to -128.
CoreConfig wrapping_config() {
  CoreConfig c;
  c.name = "wrapping";
  c.filter_order = 1;
  c.num_sections = 1;
  c.section_order = 1;
  c.sample_width = 8;
  c.coef_width = 8;
  c.num_frac_bits = 1;
  c.coef_frac_bits = 1;
  c.feedback_shift = 0;
  c.acc_width = 16;
  c.rom = {127, 127, 127};
  return c;
}

TEST(IirSampleModel, AccumulatorWrapsLikeIirCore) {
  IirCore core(wrapping_config());
  IirSampleModel fast(wrapping_config());
  EXPECT_TRUE(fast.accumulator_can_wrap());
  const SampleResult first = fast.step(127);
  EXPECT_EQ(first, (SampleResult{127, true}));
  EXPECT_EQ(core.step(127).sample, 127);
  const SampleResult second = fast.step(127);
  EXPECT_EQ(second, (SampleResult{-128, true})) << "without the wrap it would stay at 127";
  const StepResult want = core.step(127);
  EXPECT_EQ(second, (SampleResult{want.sample, want.saturated}));
}

// Random legal configurations, most of them unstable or wrapping: the arithmetic must agree
// wherever the contract allows it, not only where the generator's sets live.
TEST(IirSampleModel, MatchesIirCoreOnRandomConfigurations) {
  std::mt19937_64 rng(7);
  const auto pick = [&rng](int lo, int hi) {
    return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1));
  };
  int can_wrap = 0, wrapped = 0, saturating = 0;
  for (int trial = 0; trial < 200; ++trial) {
    CoreConfig c;
    c.name = "random";
    c.num_sections = pick(1, 3);
    c.section_order = pick(1, 4);
    c.filter_order = c.num_sections * c.section_order;
    c.sample_width = pick(2, 16);
    c.coef_width = pick(2, 18);
    c.coef_frac_bits = pick(1, c.coef_width);  // the generator takes C - 2 for biquads
    c.feedback_shift = pick(0, 25 - c.sample_width);
    c.num_frac_bits = c.coef_frac_bits + c.feedback_shift;
    const int min_acc = std::max(c.num_frac_bits + c.sample_width,
                                 c.sample_width + c.feedback_shift + c.coef_width);
    // Mostly the narrowest legal accumulator, where large words make the sum wrap.
    c.acc_width = std::min(64, min_acc + (pick(0, 3) == 0 ? pick(1, 12) : 0));
    const auto word_max = (std::int64_t{1} << (c.coef_width - 1)) - 1;
    for (int i = 0; i < c.rom_depth(); ++i) {
      c.rom.push_back(
          static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(2 * word_max + 2)) -
          word_max - 1);
    }
    const auto hi = static_cast<std::int32_t>((std::int64_t{1} << (c.sample_width - 1)) - 1);
    const std::int32_t lo = -hi - 1;
    std::vector<std::int32_t> x;
    for (int n = 0; n < 2000; ++n) x.push_back(uniform_word(rng, lo, hi));
    for (int n = 0; n < 2000; ++n) x.push_back(n % 7 < 3 ? hi : lo);
    for (int n = 0; n < 1000; ++n) x.push_back(n == 0 ? hi : 0);
    const Comparison r = compare(c, x);
    ASSERT_EQ(r.mismatches, 0u) << "trial " << trial << ": first at sample " << r.first_mismatch
                                << ": IirCore " << r.want.sample << " " << r.want.saturated
                                << ", IirSampleModel " << r.got.sample << " " << r.got.saturated
                                << "\nreproduce: ctest --test-dir build -R "
                                   "IirSampleModel.MatchesIirCoreOnRandomConfigurations";
    if (IirSampleModel(c).accumulator_can_wrap()) {
      ++can_wrap;
      // The wrap did happen if a 64-bit accumulator (which cannot wrap here) gives other outputs.
      CoreConfig wide = c;
      wide.acc_width = 64;
      IirCore unwrapped(wide), narrow(c);
      for (const std::int32_t v : x) {
        if (unwrapped.step(v).sample != narrow.step(v).sample) {
          ++wrapped;
          break;
        }
      }
    }
    saturating += r.saturated > 0 ? 1 : 0;
  }
  EXPECT_GT(wrapped, 10) << "too few configurations whose sum wraps";
  EXPECT_GT(saturating, 20) << "too few configurations that saturate";
  EXPECT_LT(can_wrap, 150) << "the path without the wrap is barely exercised";
}

TEST(IirSampleModel, StepAndFilterAndResetAgree) {
  const CoreConfig config =
      load_core_config(std::filesystem::path(FLANGE_SOURCE_DIR) / "coeffs/vehicle_sos/filter.json");
  const std::vector<std::int32_t> x = million_sample_stimulus(config.sample_width, 3).samples;
  const std::vector<std::int32_t> head(x.begin(), x.begin() + 50'000);
  IirSampleModel by_step(config), by_block(config);
  std::vector<SampleResult> blocked(head.size());
  by_block.filter(head, blocked);
  for (std::size_t i = 0; i < head.size(); ++i) {
    ASSERT_EQ(by_step.step(head[i]), blocked[i]) << "sample " << i;
  }
  by_block.reset();
  IirSampleModel fresh(config);
  for (std::size_t i = 0; i < 1000; ++i) {
    ASSERT_EQ(by_block.step(head[i]), fresh.step(head[i])) << "after reset, sample " << i;
  }
}

TEST(IirSampleModel, RejectsIllegalInputAndKeepsItsState) {
  const CoreConfig config = load_core_config(std::filesystem::path(FLANGE_SOURCE_DIR) /
                                             "coeffs/measurement_sos/filter.json");
  IirSampleModel fast(config), twin(config);
  EXPECT_EQ(fast.step(12345), twin.step(12345));
  EXPECT_THROW(fast.step(32768), std::out_of_range);
  EXPECT_THROW(fast.step(-32769), std::out_of_range);
  const std::vector<std::int32_t> bad = {1, 2, 40000};
  std::vector<SampleResult> out(bad.size());
  EXPECT_THROW(fast.filter(bad, out), std::out_of_range);
  std::vector<SampleResult> short_out(2);
  EXPECT_THROW(fast.filter(bad, short_out), std::invalid_argument);
  EXPECT_EQ(fast.step(-20000), twin.step(-20000)) << "a refused input changed the state";
  CoreConfig broken = config;
  broken.rom.pop_back();
  EXPECT_THROW(IirSampleModel{broken}, std::invalid_argument);
}

}  // namespace
}  // namespace flange::model

// SPDX-License-Identifier: MIT
// Co-simulation of rtl/iir_core.sv against model/iir_core.h: every output pin (sample_o,
// sample_valid_o, busy_o, overrun_o, saturation_o) must agree in every cycle. Compiled once and
// linked into one binary per coefficient set; ctest names carry the set
// (VehicleSos.IirCoreCosim.*). FLANGE_TRACE=1 in the environment dumps each test's waveform to
// logs/<set>_<test>.fst under the working directory (the build folder under ctest).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <random>
#include <set>
#include <string>

#include "cosim_harness.h"
#include "fidelity.h"
#include "filter_json.h"
#include "iir_core_dut.h"
#include "reference_filter.h"
#include "stimulus.h"

namespace flange::tb {
namespace {

std::string camel_case(const std::string& snake) {
  std::string out;
  bool upper = true;
  for (const char c : snake) {
    if (c == '_') {
      upper = true;
    } else {
      out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
      upper = false;
    }
  }
  return out;
}

class IirCoreCosim : public ::testing::Test {
 protected:
  void SetUp() override {
    const BuiltCoeffSet& set = built_coeff_set();
    config_ = model::load_core_config(set.filter_json);
    design_ = model::load_float_design(set.filter_json);
    spec_.sample_width = config_.sample_width;
    spec_.fs_hz = design_.fs_hz;
    spec_.fc_hz = design_.fc_hz.value_or(design_.fs_hz / 10);
    latency_ = model::IirCore(config_).latency_cycles();
  }

  // Samples per period of the cut-off frequency: the filter's slowest time scale.
  std::size_t cutoff_period() const {
    return static_cast<std::size_t>(std::ceil(spec_.fs_hz / spec_.fc_hz));
  }

  std::string reproduce() const {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return fmt::format(
        "reproduce: ctest --test-dir {} -R '^{}\\.{}\\.{}$' --output-on-failure "
        "(FLANGE_TRACE=1 for logs/{}_{}.fst)",
        FLANGE_BINARY_DIR, camel_case(built_coeff_set().name), info->test_suite_name(),
        info->name(), built_coeff_set().name, info->name());
  }

  CosimReport run(const Stimulus& stimulus, std::uint64_t tail = 0) {
    std::filesystem::path fst;
    if (const char* trace = std::getenv("FLANGE_TRACE"); trace && std::string(trace) == "1") {
      const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
      fst = std::filesystem::path("logs") / (built_coeff_set().name + "_" + info->name() + ".fst");
      std::cout << "trace: " << std::filesystem::absolute(fst).string() << "\n";
    }
    CosimHarness harness(config_, make_dut(fst));
    CosimReport report = harness.run(stimulus, tail);
    EXPECT_FALSE(report.rtl_assertion) << "an RTL assertion fired; " << reproduce();
    EXPECT_EQ(report.mismatches, 0u) << report.first_mismatch << "\n" << reproduce();
    for (const std::uint64_t latency : report.latencies) {
      EXPECT_EQ(latency, static_cast<std::uint64_t>(latency_)) << reproduce();
      if (latency != static_cast<std::uint64_t>(latency_)) break;
    }
    return report;
  }

  // Streams `samples` back to back (one every latency_ cycles) and checks that each gave an output.
  CosimReport stream(const std::vector<std::int32_t>& samples) {
    CosimReport report = run(every(samples, static_cast<std::uint64_t>(latency_)));
    EXPECT_EQ(report.accepted, samples.size());
    EXPECT_EQ(report.outputs.size(), samples.size());
    EXPECT_EQ(report.dropped, 0u);
    EXPECT_FALSE(report.overrun_seen);
    return report;
  }

  // The float design's response to the same samples, in LSB of the core's output.
  std::vector<double> reference(const std::vector<std::int32_t>& samples) const {
    model::ReferenceFilter filter(design_);
    const double scale = std::ldexp(1.0, config_.sample_width - 1);
    std::vector<double> y;
    y.reserve(samples.size());
    for (const std::int32_t x : samples) y.push_back(x / scale);
    filter.process(y, y);
    for (double& v : y) v *= scale;
    return y;
  }

  model::CoreConfig config_;
  model::FloatDesign design_;
  SignalSpec spec_;
  int latency_ = 0;
};

// How far the core's response is from the float design's is the model's business
// (tests/model/iir_core_test.cpp); here it is printed for the record, and RTL == model is the
// check.
void print_fidelity(const std::string& what, const std::vector<std::int32_t>& outputs,
                    const std::vector<double>& ref) {
  double worst = 0.0;
  double peak = 0.0;
  for (std::size_t i = 0; i < outputs.size() && i < ref.size(); ++i) {
    worst = std::max(worst, std::abs(outputs[i] - ref[i]));
    peak = std::max(peak, std::abs(ref[i]));
  }
  std::cout << fmt::format(
      "[{}] {}: float peak {:.1f} LSB, largest core - float error {:.1f} LSB\n", what,
      built_coeff_set().name, peak, worst);
}

TEST_F(IirCoreCosim, Impulse) {
  const auto x = impulse(spec_, 20 * cutoff_period());
  const CosimReport report = stream(x);
  print_fidelity("impulse", report.outputs, reference(x));
}

TEST_F(IirCoreCosim, Step) {
  const auto x = step(spec_, 20 * cutoff_period(), 0.5);
  const CosimReport report = stream(x);
  print_fidelity("step", report.outputs, reference(x));
}

TEST_F(IirCoreCosim, FullScaleSquare) {
  // Nyquist-rate alternation first (largest alternating sums in the feed-forward path), then a
  // slow square whose every edge overshoots the rails in any filter of order 2 or more.
  auto x = square(spec_, 256, 1);
  const auto slow = square(spec_, 6 * 3 * cutoff_period(), 3 * cutoff_period());
  x.insert(x.end(), slow.begin(), slow.end());
  const CosimReport report = stream(x);

  const std::vector<double> ref = reference(x);
  const double peak = *std::max_element(
      ref.begin(), ref.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
  const double full_scale = std::ldexp(1.0, config_.sample_width - 1);
  std::cout << fmt::format("[square] {}: float peak {:.4f} of full scale, saturation_o {}\n",
                           built_coeff_set().name, std::abs(peak) / full_scale,
                           int{report.saturation_seen});
  if (std::abs(peak) > 1.001 * full_scale) {
    EXPECT_TRUE(report.saturation_seen) << "the float output leaves full scale, so the core must "
                                           "clip and raise saturation_o; "
                                        << reproduce();
    EXPECT_TRUE(std::find(report.outputs.begin(), report.outputs.end(),
                          full_scale_max(config_.sample_width)) != report.outputs.end())
        << "no output sits on the positive rail; " << reproduce();
  }
}

// An input whose response takes the last section's y_ext into the 2^(s-1) words just below its
// rail: y_ext itself fits D + s bits, but sample_o rounded from it does not, so only the output's
// rounding step clips (docs/fixed_point.md; sections pass y_ext on unrounded, so no other section
// can clip this way). Found with the model: probe the last section's peak step gain, then try
// steps of the amplitudes around the one that puts that peak into the window, and, as the peak
// moves by about 2^s words per input LSB, steps whose last `lag` samples are a little higher or
// lower, which moves it by less (lags in steps of about 25 %). Sets whose step response never
// overshoots (order 1) cannot reach the window: nullopt.
std::optional<std::vector<std::int32_t>> find_second_step_clip(const model::CoreConfig& config,
                                                               std::size_t max_samples) {
  const int line = config.section_order + 1;
  const auto newest_ext = [line](const model::IirCore& core, int k) {
    return core.lr()[static_cast<std::size_t>((k + 1) * line)];
  };
  // Peak y_ext of every section, and when it comes, for a half-scale step.
  model::IirCore probe(config);
  const std::int32_t half = probe.sample_max() / 2 + 1;
  std::vector<std::int64_t> peak(static_cast<std::size_t>(config.num_sections), 0);
  std::vector<std::size_t> peak_at(peak.size(), 0);
  for (std::size_t n = 0; n < max_samples; ++n) {
    probe.step(half);
    for (int k = 0; k < config.num_sections; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      if (newest_ext(probe, k) > peak[kk]) {
        peak[kk] = newest_ext(probe, k);
        peak_at[kk] = n;
      }
    }
  }
  // A hit: some step clipped, and no y_ext ever sat on a rail (so the first step never clipped).
  const auto hits = [&](const std::vector<std::int32_t>& x) {
    model::IirCore core(config);
    bool clipped = false;
    for (const std::int32_t v : x) {
      clipped = core.step(v).saturated || clipped;
      for (int j = 0; j < config.num_sections; ++j) {
        const std::int64_t e = newest_ext(core, j);
        if (e == core.ext_max() || e == core.ext_min()) return false;
      }
    }
    return clipped;
  };
  const double window_middle =
      static_cast<double>(probe.ext_max()) - std::ldexp(1.0, config.feedback_shift - 2);
  for (std::size_t k = peak.size() - 1; k < peak.size(); ++k) {  // the last section only
    const double target = window_middle * half / static_cast<double>(peak[k]);
    if (target > probe.sample_max()) continue;  // the peak stays below the window
    const std::size_t n = peak_at[k] + 2;
    const auto step_of = [&](std::int32_t amplitude, std::size_t lag, std::int32_t delta) {
      std::vector<std::int32_t> x(n, amplitude);
      for (std::size_t i = n - std::min(n, lag); i < n; ++i) {
        x[i] = std::clamp(amplitude + delta, probe.sample_min(), probe.sample_max());
      }
      return x;
    };
    const auto centre = static_cast<std::int32_t>(std::lround(target));
    for (std::int32_t d = -16; d <= 16; ++d) {
      if (centre + d > probe.sample_max()) continue;
      if (auto x = step_of(centre + d, 0, 0); hits(x)) return x;
    }
    for (std::size_t lag = 1; lag <= n; lag = std::max(lag + 1, lag * 5 / 4)) {
      for (std::int32_t d = -2; d <= 2; ++d) {
        for (std::int32_t delta = -8; delta <= 8; ++delta) {
          if (centre + d > probe.sample_max() || delta == 0) continue;
          if (auto x = step_of(centre + d, lag, delta); hits(x)) return x;
        }
      }
    }
  }
  return std::nullopt;
}

TEST_F(IirCoreCosim, SaturationInTheSecondRoundingStep) {
  if (config_.feedback_shift == 0) GTEST_SKIP() << "s = 0: y = y_ext, one rounding step";
  const std::optional<std::vector<std::int32_t>> x =
      find_second_step_clip(config_, 8 * cutoff_period());
  if (!x) GTEST_SKIP() << "no step response of this set reaches the window below the rail";
  std::cout << fmt::format("[second-step clip] {}: step of {} LSB ending at {} LSB, {} samples\n",
                           built_coeff_set().name, x->front(), x->back(), x->size());
  std::vector<std::int32_t> samples = *x;
  samples.resize(samples.size() + 3, samples.back());
  const CosimReport report = stream(samples);
  EXPECT_TRUE(report.saturation_seen) << reproduce();
}

TEST_F(IirCoreCosim, SineSweep) {
  const std::size_t n = std::max<std::size_t>(4000, 40 * cutoff_period());
  const auto x = sine_sweep(spec_, n, spec_.fc_hz / 20, 0.49 * spec_.fs_hz, 0.7);
  const CosimReport report = stream(x);
  ASSERT_EQ(report.outputs.size(), n);
  // Passband (first tenth, below fc / 10): the sine goes through; stopband: it is attenuated.
  const double full_scale = std::ldexp(1.0, config_.sample_width - 1);
  const auto peak = [&](std::size_t from, std::size_t to) {
    std::int32_t p = 0;
    for (std::size_t i = from; i < to; ++i) p = std::max(p, std::abs(report.outputs[i]));
    return p / full_scale;
  };
  const double pass = peak(n / 20, n / 10);
  const double stop = peak(n - n / 20, n);
  const std::vector<double> ref = reference(x);
  double ref_stop = 0.0;
  for (std::size_t i = n - n / 20; i < n; ++i) ref_stop = std::max(ref_stop, std::abs(ref[i]));
  std::cout << fmt::format(
      "[sweep] {}: passband peak {:.3f}, stopband peak {:.5f} (float {:.5f})\n",
      built_coeff_set().name, pass, stop, ref_stop / full_scale);
  // Not a vacuous run: the low end of the sweep reaches the output.
  EXPECT_GT(pass, 0.6) << reproduce();
}

TEST_F(IirCoreCosim, UniformRandom) { stream(uniform_random(spec_, 5000, 0.5, 1)); }

TEST_F(IirCoreCosim, FullScaleRandom) { stream(uniform_random(spec_, 5000, 1.0, 2)); }

TEST_F(IirCoreCosim, ZeroInputAfterExcitation) {
  // Strong excitation, then a long run of zeros: does the core decay to 0, or settle into a
  // limit cycle or dead band (round half up in a recursive loop)?
  auto x = square(spec_, 4 * 2 * cutoff_period(), 2 * cutoff_period());
  const auto noise = uniform_random(spec_, 2 * cutoff_period(), 1.0, 3);
  x.insert(x.end(), noise.begin(), noise.end());
  const std::size_t excitation = x.size();
  const std::size_t zeros = std::max<std::size_t>(6000, 60 * cutoff_period());
  x.resize(excitation + zeros, 0);
  const CosimReport report = stream(x);
  ASSERT_EQ(report.outputs.size(), x.size());

  const std::size_t tail = 2000;
  const model::LimitCycle lc = model::find_limit_cycle(report.outputs, tail, tail / 2);
  std::cout << fmt::format("[limit cycle] {}: {} (excitation {} samples, then {} zeros)\n",
                           built_coeff_set().name, lc.describe(), excitation, zeros);
  ::testing::Test::RecordProperty("limit_cycle", lc.describe());
  EXPECT_NE(lc.period, 0u) << "the zero-input tail is not periodic yet: lengthen the run; "
                           << reproduce();
  EXPECT_LT(lc.settled_after, x.size() - tail / 2) << reproduce();
}

TEST_F(IirCoreCosim, OverrunWhileBusy) {
  // Strobes at random spacing, often closer than the core's cycles per sample: the extra ones
  // are dropped, overrun_o rises, and the history never sees them.
  std::mt19937_64 rng(4);
  std::uniform_int_distribution<int> gap(1, 2 * latency_);
  const auto samples = uniform_random(spec_, 3000, 0.5, 5);
  Stimulus s;
  std::uint64_t cycle = 1;
  for (const std::int32_t v : samples) {
    s.actions.push_back({cycle, Action::Kind::kStrobe, v});
    cycle += static_cast<std::uint64_t>(gap(rng));
  }
  const CosimReport report = run(s);
  EXPECT_GT(report.dropped, 0u);
  EXPECT_GT(report.accepted, 0u);
  EXPECT_EQ(report.accepted + report.dropped, samples.size());
  EXPECT_EQ(report.outputs.size(), report.accepted);
  EXPECT_TRUE(report.overrun_seen);
}

TEST_F(IirCoreCosim, StrobeOneCycleAfterAccept) {
  // The tightest overrun: a second strobe in the cycle right after an accepted one, and one in
  // the cycle sample_valid_o is high (accepted: the core is idle again).
  Stimulus s;
  const auto spacing = static_cast<std::uint64_t>(latency_);
  s.add({10, Action::Kind::kStrobe, 1000});
  s.add({11, Action::Kind::kStrobe, -2000});                   // dropped
  s.add({10 + spacing, Action::Kind::kStrobe, 3000});          // accepted in the valid cycle
  s.add({10 + 2 * spacing - 1, Action::Kind::kStrobe, 4000});  // dropped: one cycle early
  s.add({10 + 2 * spacing, Action::Kind::kStrobe, 5000});
  const CosimReport report = run(s);
  EXPECT_EQ(report.accepted, 3u);
  EXPECT_EQ(report.dropped, 2u);
  EXPECT_TRUE(report.overrun_seen);
  ASSERT_EQ(report.valid_cycles.size(), 3u);
  EXPECT_EQ(report.valid_cycles[0], 10 + spacing);
}

TEST_F(IirCoreCosim, FlagClear) {
  // Saturating input with overruns, and flag_clear_i pulses in between, some in the very cycle a
  // flag event lands (the event wins).
  auto samples = square(spec_, 12 * cutoff_period(), 3 * cutoff_period());
  Stimulus s = every(samples, static_cast<std::uint64_t>(latency_));
  std::mt19937_64 rng(6);
  std::uniform_int_distribution<std::uint64_t> when(1, s.last_cycle());
  const auto spacing = static_cast<std::uint64_t>(latency_);
  // One action of a kind per cycle; the streamed strobes sit at cycles 1 + i * spacing.
  std::set<std::uint64_t> clears, extra_strobes;
  for (int i = 0; i < 200; ++i) {
    const std::uint64_t c = when(rng);
    if (!clears.insert(c).second) continue;
    s.add({c, Action::Kind::kClear, 0});
    // An extra strobe in the next cycle, mostly while busy.
    const std::uint64_t e = c + 1;
    if (i % 4 == 0 && (e - 1) % spacing != 0 && extra_strobes.insert(e).second) {
      s.add({e, Action::Kind::kStrobe, 0});
    }
  }
  const CosimReport report = run(s);
  EXPECT_GT(report.accepted, 0u);
  EXPECT_GT(report.dropped, 0u);
  // A Butterworth low-pass of order 2 or more overshoots a full-scale square: it must clip. First-
  // order sections (df1_order1, the test-only cascade df1_order1x2) have real poles only: their
  // step response never overshoots.
  EXPECT_TRUE(report.saturation_seen || config_.filter_order < 2 || config_.section_order < 2)
      << reproduce();
}

TEST_F(IirCoreCosim, ResetMidComputation) {
  // Stream, and pull rst_ni low at every phase of a computation in turn: the output in flight
  // never appears, the history restarts from zero, and streaming resumes.
  const auto spacing = static_cast<std::uint64_t>(latency_);
  const auto samples = uniform_random(spec_, 40 * spacing, 0.8, 7);
  Stimulus s;
  std::uint64_t cycle = 1;
  std::size_t next = 0;
  std::uint64_t resets = 0;
  for (std::uint64_t phase = 0; phase <= spacing && next < samples.size(); ++phase) {
    for (int k = 0; k < 5 && next < samples.size(); ++k, cycle += spacing) {
      s.add({cycle, Action::Kind::kStrobe, samples[next++]});
    }
    // The last strobe was at cycle - spacing; reset `phase` cycles after it (phase 0: the same
    // cycle as a strobe, which the reset overrides).
    const std::uint64_t reset_cycle = cycle - spacing + phase;
    s.add({reset_cycle, Action::Kind::kReset, 0});
    ++resets;
    cycle = reset_cycle + 1 + phase % 3;  // resume right after, or a little later
  }
  const CosimReport report = run(s);
  EXPECT_GT(resets, 2u);
  EXPECT_LT(report.outputs.size(), report.accepted) << "no computation was cut short by reset";
  EXPECT_GT(report.outputs.size(), 0u);
}

TEST_F(IirCoreCosim, RandomProtocol) {
  // Everything at once: random strobes (full-scale samples), flag clears and resets.
  std::mt19937_64 rng(8);
  std::uniform_int_distribution<std::int32_t> value(full_scale_min(config_.sample_width),
                                                    full_scale_max(config_.sample_width));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Stimulus s;
  const std::uint64_t cycles = 200ull * static_cast<std::uint64_t>(latency_);
  for (std::uint64_t c = 1; c < cycles; ++c) {
    if (u(rng) < 1.5 / latency_) s.actions.push_back({c, Action::Kind::kStrobe, value(rng)});
    if (u(rng) < 0.01) s.actions.push_back({c, Action::Kind::kClear, 0});
    if (u(rng) < 0.001) s.actions.push_back({c, Action::Kind::kReset, 0});
  }
  const CosimReport report = run(s);
  EXPECT_GT(report.accepted, 50u);
  EXPECT_GT(report.dropped, 0u);
}

}  // namespace
}  // namespace flange::tb

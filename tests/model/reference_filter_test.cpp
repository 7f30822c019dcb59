// SPDX-License-Identifier: MIT
// The double-precision reference: the SOS cascade and the direct form agree where the direct form
// is well conditioned, and both match scipy's design of the thesis's measurement filter; the
// quantised cascade is the ROM's section values; the frequency response is the impulse
// response's transform; process() is step() over a block, for every form and stage count.
#include "reference_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <span>
#include <stdexcept>
#include <vector>

#include "filter_json.h"

namespace flange::model {
namespace {

std::filesystem::path set_json(const std::string& set) {
  return std::filesystem::path(FLANGE_SOURCE_DIR) / "coeffs" / set / "filter.json";
}

std::vector<double> impulse_response(ReferenceFilter& f, std::size_t n) {
  std::vector<double> h;
  for (std::size_t i = 0; i < n; ++i) h.push_back(f.step(i == 0 ? 1.0 : 0.0));
  return h;
}

TEST(ReferenceFilter, SosAndDirectFormAgreeOnTheMeasurementFilter) {
  const FloatDesign d = load_float_design(set_json("measurement_sos"));
  ReferenceFilter sos(d, ReferenceFilter::Form::kSos);
  ReferenceFilter direct(d, ReferenceFilter::Form::kDirect);
  const auto a = impulse_response(sos, 400);
  const auto b = impulse_response(direct, 400);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-12) << i;
  double dc = 0.0;
  for (const double v : a) dc += v;
  EXPECT_NEAR(dc, 1.0, 1e-9) << "Butterworth low-pass: unit DC gain";
}

TEST(ReferenceFilter, MatchesScipyDesign) {
  // tests/data/butterworth_scipy.json: scipy.signal.butter(5, 0.5742 Hz, fs = 6 Hz), whose b/a
  // the thesis printed (eq. 4.15). Our generator's float design must give the same filter.
  std::ifstream in(std::filesystem::path(FLANGE_SOURCE_DIR) / "tests/data/butterworth_scipy.json");
  const nlohmann::json scipy = nlohmann::json::parse(in);
  const nlohmann::json* entry = nullptr;
  for (const auto& e : scipy["from_order_and_cutoff"]) {
    if (e["order"] == 5 && std::abs(e["fc_hz"].get<double>() - 0.5742) < 1e-9) entry = &e;
  }
  ASSERT_NE(entry, nullptr);
  FloatDesign theirs;
  theirs.fs_hz = 6.0;
  theirs.b = (*entry)["b"].get<std::vector<double>>();
  theirs.a = (*entry)["a"].get<std::vector<double>>();
  for (const auto& row : (*entry)["sos"]) theirs.sos.push_back(row.get<std::array<double, 6>>());

  ReferenceFilter ours(load_float_design(set_json("measurement_sos")));
  ReferenceFilter scipy_sos(theirs, ReferenceFilter::Form::kSos);
  ReferenceFilter scipy_ba(theirs, ReferenceFilter::Form::kDirect);
  const auto h = impulse_response(ours, 300);
  const auto hs = impulse_response(scipy_sos, 300);
  const auto hb = impulse_response(scipy_ba, 300);
  for (std::size_t i = 0; i < h.size(); ++i) {
    EXPECT_NEAR(h[i], hs[i], 1e-9) << i;
    EXPECT_NEAR(h[i], hb[i], 1e-9) << i;
  }
}

TEST(ReferenceFilter, LeftoverGainScalesTheOutput) {
  FloatDesign d = load_float_design(set_json("measurement_sos"));
  ReferenceFilter unit(d);
  d.leftover_gain = 2.5;
  ReferenceFilter scaled(d);
  for (int i = 0; i < 50; ++i) {
    const double x = std::sin(0.3 * i);
    EXPECT_DOUBLE_EQ(scaled.step(x), 2.5 * unit.step(x));
  }
}

TEST(ReferenceFilter, ResetClearsTheState) {
  ReferenceFilter f(load_float_design(set_json("vehicle_sos")));
  const auto first = impulse_response(f, 100);
  f.reset();
  EXPECT_EQ(impulse_response(f, 100), first);
}

TEST(ReferenceFilter, QuantizedIsTheSectionValuesOfFilterJson) {
  for (const std::string set : {"measurement_sos", "measurement_df1", "vehicle_sos"}) {
    // filter.json's quantized.section_values, written by the generator beside the ROM words.
    std::ifstream in(set_json(set));
    const nlohmann::json json = nlohmann::json::parse(in);
    FloatDesign values = load_float_design(set_json(set));
    values.sos.clear();
    for (const auto& section : json["quantized"]["section_values"]) {
      const auto b = section["b"].get<std::vector<double>>();
      const auto a = section["a"].get<std::vector<double>>();
      if (b.size() == 3 && a.size() == 3)
        values.sos.push_back({b[0], b[1], b[2], a[0], a[1], a[2]});
      values.b = b;  // a single section (measurement_df1) as one direct form
      values.a = a;
    }
    const bool one_section = json["quantized"]["section_values"].size() == 1;
    ReferenceFilter expected(
        values, one_section ? ReferenceFilter::Form::kDirect : ReferenceFilter::Form::kSos);
    ReferenceFilter quantized =
        ReferenceFilter::quantized(load_core_config(set_json(set)), values.leftover_gain);
    EXPECT_EQ(impulse_response(quantized, 500), impulse_response(expected, 500)) << set;
  }
}

TEST(ReferenceFilter, ResponseIsTheTransformOfTheImpulseResponse) {
  const std::filesystem::path json = set_json("measurement_sos");
  ReferenceFilter design(load_float_design(json));
  ReferenceFilter quantized = ReferenceFilter::quantized(load_core_config(json), 1.0);
  for (ReferenceFilter* filter : {&design, &quantized}) {
    const auto h = impulse_response(*filter, 2000);  // decayed far below 1e-12 by then
    for (const double f : {0.0, 0.01, 0.1, 0.25, 0.5}) {
      std::complex<double> sum = 0.0;
      for (std::size_t n = 0; n < h.size(); ++n) {
        sum += h[n] * std::polar(1.0, -2.0 * std::numbers::pi * f * static_cast<double>(n));
      }
      EXPECT_NEAR(std::abs(filter->response(f) - sum), 0.0, 1e-12) << "f/fs = " << f;
    }
  }
}

// A stable low-pass cascade of `order` (odd orders end with a first-order row, b2 = a2 = 0):
// poles spread over radii 0.3 to 0.99, zeros at z = -1; b/a is the rows' product.
FloatDesign cascade_of_order(int order) {
  FloatDesign d;
  d.fs_hz = 100.0;
  d.b = {1.0};
  d.a = {1.0};
  const auto times = [](const std::vector<double>& p, const std::vector<double>& q) {
    std::vector<double> r(p.size() + q.size() - 1, 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) {
      for (std::size_t j = 0; j < q.size(); ++j) r[i + j] += p[i] * q[j];
    }
    return r;
  };
  for (int k = 0; 2 * k < order; ++k) {
    const double radius = 0.3 + 0.69 * (k + 1) / ((order + 1) / 2);
    std::array<double, 6> row{};
    if (2 * k + 1 == order) {  // first order: (1 + z^-1) / (1 - r z^-1)
      row = {0.5 * (1.0 - radius), 0.5 * (1.0 - radius), 0.0, 1.0, -radius, 0.0};
    } else {
      const double theta = 0.05 + 0.4 * k / std::max(1, order / 2);
      const double a1 = -2.0 * radius * std::cos(theta), a2 = radius * radius;
      const double g = (1.0 + a1 + a2) / 4.0;  // unit DC gain
      row = {g, 2.0 * g, g, 1.0, a1, a2};
    }
    d.sos.push_back(row);
    d.b = times(d.b, {row[0], row[1], row[2]});
    d.a = times(d.a, {row[3], row[4], row[5]});
  }
  d.leftover_gain = 0.75;
  return d;
}

// What step() gives, sample by sample, on a fresh copy of `filter`.
std::vector<double> stepped(ReferenceFilter filter, const std::vector<double>& x) {
  std::vector<double> y;
  for (const double v : x) y.push_back(filter.step(v));
  return y;
}

// `filter` through process() in blocks of varying length (1 to 4097 samples), one block in place,
// with single step() calls between some blocks; every output within `tolerance` of full scale of
// step()'s (in a build without floating-point contraction they are equal bit for bit).
void expect_process_is_step(const ReferenceFilter& filter, const std::string& what) {
  constexpr double kTolerance = 1e-13;
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<double> x(30000);
  for (double& v : x) v = uniform(rng);
  const std::vector<double> want = stepped(filter, x);
  ReferenceFilter blocks = filter;
  std::vector<double> got(x.size());
  const std::size_t lengths[] = {1, 2, 3, 7, 64, 4097, 5, 1000, 63};
  std::size_t at = 0;
  for (std::size_t b = 0; at < x.size(); ++b) {
    if (b % 3 == 2) {
      got[at] = blocks.step(x[at]);
      ++at;
      continue;
    }
    const std::size_t n = std::min(lengths[b % std::size(lengths)], x.size() - at);
    if (b % 5 == 4) {  // in place
      std::copy(x.begin() + at, x.begin() + at + n, got.begin() + at);
      const std::span<double> block(got.data() + at, n);
      blocks.process(block, block);
    } else {
      blocks.process(std::span(x).subspan(at, n), std::span(got).subspan(at, n));
    }
    at += n;
  }
  double worst = 0.0;
  std::size_t worst_at = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (std::abs(got[i] - want[i]) > worst) {
      worst = std::abs(got[i] - want[i]);
      worst_at = i;
    }
  }
  EXPECT_LE(worst, kTolerance) << what << ": sample " << worst_at << " process " << got[worst_at]
                               << ", step " << want[worst_at];
}

TEST(ReferenceFilter, ProcessIsStepOnEveryCheckedInSet) {
  for (const std::string set : {"measurement_sos", "measurement_df1", "vehicle_sos"}) {
    const FloatDesign design = load_float_design(set_json(set));
    expect_process_is_step(ReferenceFilter(design, ReferenceFilter::Form::kSos), set + " sos");
    expect_process_is_step(ReferenceFilter(design, ReferenceFilter::Form::kDirect),
                           set + " direct");
    expect_process_is_step(
        ReferenceFilter::quantized(load_core_config(set_json(set)), design.leftover_gain),
        set + " quantized");
  }
}

TEST(ReferenceFilter, ProcessIsStepForOddAndEvenOrders) {
  // Orders 1 to 18: one to nine stages, so both the unrolled kernels (up to eight) and the
  // general loop; the direct form is the general loop with one stage of order N.
  for (int order = 1; order <= 18; ++order) {
    const FloatDesign design = cascade_of_order(order);
    const std::string what = "order " + std::to_string(order);
    expect_process_is_step(ReferenceFilter(design, ReferenceFilter::Form::kSos), what + " sos");
    if (order <= 8) {  // higher orders in one direct form are too ill-conditioned to be useful
      expect_process_is_step(ReferenceFilter(design, ReferenceFilter::Form::kDirect),
                             what + " direct");
    }
  }
}

TEST(ReferenceFilter, ProcessWantsOneOutputPerInput) {
  ReferenceFilter f(load_float_design(set_json("vehicle_sos")));
  std::vector<double> in(4), out(3);
  EXPECT_THROW(f.process(in, out), std::invalid_argument);
}

}  // namespace
}  // namespace flange::model

// SPDX-License-Identifier: MIT
// The double-precision reference: the SOS cascade and the direct form agree where the direct form
// is well conditioned, and both match scipy's design of the thesis's measurement filter; the
// quantised cascade is the ROM's section values; the frequency response is the impulse
// response's transform.
#include "reference_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

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

}  // namespace
}  // namespace flange::model

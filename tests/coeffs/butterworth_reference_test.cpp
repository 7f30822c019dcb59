// SPDX-License-Identifier: MIT
// Every design in tests/data/butterworth_scipy.json (scipy.signal 1.10) is reproduced: order,
// cut-off, b/a, zeros/poles, the nearest-pairing sections, and the cascade equals b/a.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "butterworth.h"
#include "float_design.h"
#include "second_order_sections.h"

namespace flange::coeffs {
namespace {

constexpr double kRelative = 1e-9;
constexpr double kTinyAbsolute = 1e-15;

// Loaded once and kept: the tests iterate over parts of it (a temporary would dangle there).
const nlohmann::json& reference() {
  static const nlohmann::json loaded = [] {
    std::ifstream file(std::string(FLANGE_SOURCE_DIR) + "/tests/data/butterworth_scipy.json");
    return nlohmann::json::parse(file);
  }();
  return loaded;
}

// The response from zeros, poles and gain: k prod(e^jw - z) / prod(e^jw - p). Unlike b/a expanded
// to order 23, it is well conditioned, so the check below does not depend on how one compiler
// happens to round (the direct form's answer moved by 2 % between g++ and clang).
Complex eval_zpk(const Zpk& zpk, double omega) {
  const Complex e = std::polar(1.0, omega);
  Complex h(zpk.gain, 0.0);
  for (const Complex& z : zpk.zeros) h *= e - z;
  for (const Complex& p : zpk.poles) h /= e - p;
  for (std::size_t k = zpk.zeros.size(); k < zpk.poles.size(); ++k) h *= e;  // zeros at z = 0
  return h;
}

void expect_close(double expected, double actual, const std::string& what) {
  const double tolerance = std::max(kTinyAbsolute, kRelative * std::abs(expected));
  EXPECT_NEAR(expected, actual, tolerance) << what;
}

std::vector<Complex> complex_list(const nlohmann::json& list) {
  std::vector<Complex> values;
  for (const auto& pair : list) values.emplace_back(pair[0].get<double>(), pair[1].get<double>());
  return values;
}

// Every expected root has its own actual root within 1e-9 (a matching, not just a cover).
void expect_same_roots(std::vector<Complex> expected, std::vector<Complex> actual,
                       const std::string& what) {
  ASSERT_EQ(expected.size(), actual.size()) << what;
  for (const Complex& root : expected) {
    auto nearest = std::min_element(actual.begin(), actual.end(), [&](Complex x, Complex y) {
      return std::abs(x - root) < std::abs(y - root);
    });
    EXPECT_LT(std::abs(*nearest - root), 1e-9) << what << " root " << root;
    actual.erase(nearest);
  }
}

void check_design(const nlohmann::json& entry, const FloatDesign& design, const std::string& what) {
  EXPECT_EQ(entry["order"].get<int>(), design.order) << what;
  expect_close(entry["fc_hz"].get<double>(), design.fc_hz, what + " fc");
  const auto b = entry["b"].get<std::vector<double>>();
  const auto a = entry["a"].get<std::vector<double>>();
  ASSERT_EQ(b.size(), design.b.size()) << what;
  ASSERT_EQ(a.size(), design.a.size()) << what;
  for (std::size_t i = 0; i < b.size(); ++i) {
    expect_close(b[i], design.b[i], what + " b[" + std::to_string(i) + "]");
    expect_close(a[i], design.a[i], what + " a[" + std::to_string(i) + "]");
  }
  expect_close(entry["gain"].get<double>(), design.zpk.gain, what + " gain");
  expect_same_roots(complex_list(entry["zeros"]), design.zpk.zeros, what + " zeros");
  expect_same_roots(complex_list(entry["poles"]), design.zpk.poles, what + " poles");

  // Same sections in the same order as scipy's nearest pairing, up to where the gain sits.
  const std::vector<Section> paired = pair_sections_nearest(design.zpk);
  const auto& sos = entry["sos"];
  ASSERT_EQ(sos.size(), paired.size()) << what;
  for (std::size_t k = 0; k < paired.size(); ++k) {
    const auto row = sos[k].get<std::vector<double>>();
    const double scale = row[0];
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(row[static_cast<std::size_t>(i)] / scale,
                  paired[k].b[static_cast<std::size_t>(i)], 1e-9)
          << what << " section " << k << " b" << i;
      EXPECT_NEAR(row[static_cast<std::size_t>(3 + i)], paired[k].a[static_cast<std::size_t>(i)],
                  1e-9)
          << what << " section " << k << " a" << i;
    }
  }

  // The scaled cascade, with its leftover gain, has the response of the zeros, poles and gain.
  for (int i = 0; i <= 512; ++i) {
    const double omega = std::numbers::pi * i / 512.0;
    Complex cascade(design.cascade.leftover_gain, 0.0);
    for (const Section& section : design.cascade.sections) {
      cascade *= eval_z_inverse({section.b.begin(), section.b.end()}, omega) /
                 eval_z_inverse({section.a.begin(), section.a.end()}, omega);
    }
    const Complex direct = eval_zpk(design.zpk, omega);
    EXPECT_LT(std::abs(cascade - direct), 1e-9 * std::max(1.0, std::abs(direct)) + 1e-12)
        << what << " at omega " << omega;
  }
  // L-infinity scaling: no cumulative response peaks above full scale.
  for (std::size_t k = 1; k <= design.cascade.sections.size(); ++k) {
    EXPECT_LE(cumulative_peak_magnitude(design.cascade.sections, k), 1.0 + 1e-9) << what;
  }
}

TEST(ButterworthReference, SpecDesignsMatchScipy) {
  for (const auto& entry : reference()["from_specs"]) {
    const auto& s = entry["spec"];
    const LowpassSpec spec{s["fs_hz"], s["fp_hz"], s["fa_hz"], s["ap_db"], s["aa_db"]};
    const int order = butterworth_min_order(spec);
    const FloatDesign design =
        design_butterworth(order, butterworth_cutoff_hz(spec, order), spec.fs_hz, spec);
    check_design(entry, design,
                 "spec fs=" + std::to_string(spec.fs_hz) + " order " + std::to_string(order));
  }
}

TEST(ButterworthReference, OrderAndCutoffDesignsMatchScipy) {
  for (const auto& entry : reference()["from_order_and_cutoff"]) {
    const auto& s = entry["spec"];
    const FloatDesign design = design_butterworth(s["order"], s["fc_hz"], s["fs_hz"], {});
    check_design(entry, design,
                 "order " + std::to_string(s["order"].get<int>()) + " fc " +
                     std::to_string(s["fc_hz"].get<double>()));
  }
}

TEST(ButterworthReference, PassbandEdgeIsMetExactly) {
  for (const auto& entry : reference()["from_specs"]) {
    const auto& s = entry["spec"];
    const LowpassSpec spec{s["fs_hz"], s["fp_hz"], s["fa_hz"], s["ap_db"], s["aa_db"]};
    const int order = butterworth_min_order(spec);
    const FloatDesign design =
        design_butterworth(order, butterworth_cutoff_hz(spec, order), spec.fs_hz, spec);
    const Complex at_fp = eval_zpk(design.zpk, 2 * std::numbers::pi * spec.fp_hz / spec.fs_hz);
    EXPECT_NEAR(-20.0 * std::log10(std::abs(at_fp)), spec.ap_db, 1e-6);
    EXPECT_NEAR(entry["gain_db_at_fp"].get<double>(), -spec.ap_db, 1e-9);
  }
}

}  // namespace
}  // namespace flange::coeffs

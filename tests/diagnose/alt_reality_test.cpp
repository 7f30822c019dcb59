// SPDX-License-Identifier: MIT
// The alternative reality (diagnose/alt_reality/): its sensor is eq. 3.14, its pairs are
// reproducible and hold every kind and class, every shape of every class changes what an ideal
// twin sees, sizes follow the noise, clocks restart while the age runs on, a converter leaves a
// grid, and the truth goes to a sidecar beside the recordings.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "alt_classes.h"
#include "alt_pairs.h"
#include "alt_sensor.h"
#include "alt_truth.h"
#include "recording_series.h"
#include "test_files.h"

namespace flange::alt_reality {
namespace {

double eq_3_14(double v, double t) {
  return 1.16 + 0.3672 * v - 0.0036 * t + 0.05812 * v * v + 0.0006618 * v * t;
}

TEST(AltReality, SensorSolvesEq314InClosedForm) {
  for (double t = 0.0; t <= 100.0; t += 12.5) {
    for (double d = 1.5; d <= 9.0; d += 0.37) {
      const double v = ideal_sensor_voltage(d, t);
      ASSERT_GT(v, 0.0);
      EXPECT_NEAR(eq_3_14(v, t), d, 1e-9) << d << " mm at " << t << " degC";
      const double h = 1e-6;
      EXPECT_NEAR(ideal_sensor_slope_v_per_mm(d, t),
                  (ideal_sensor_voltage(d + h, t) - ideal_sensor_voltage(d - h, t)) / (2 * h),
                  1e-5);
    }
  }
  EXPECT_EQ(ideal_sensor_voltage(30.0, 20.0), kSensorHighV);  // beyond the range: the rail
}

TEST(AltReality, PairsAreReproducibleAndHoldEveryKindAndClass) {
  std::map<std::string, int> kinds, classes;
  for (int i = 1; i <= 110; ++i) {
    const AltPairSpec a = draw_alt_pair(i, 5, 900.0);
    kinds[alt_pair_kind_name(a.kind)]++;
    for (const TruthEffect& e : a.truth) classes[e.draw.class_name]++;
    if (i <= 12) {
      const AltPairSpec b = draw_alt_pair(i, 5, 900.0);
      ASSERT_EQ(a.truth.size(), b.truth.size());
      for (std::size_t k = 0; k < a.truth.size(); ++k) {
        EXPECT_EQ(a.truth[k].draw.params, b.truth[k].draw.params) << i;
      }
      EXPECT_EQ(a.fit.noise_seed, b.fit.noise_seed);
    }
  }
  EXPECT_EQ(kinds["single"], 66);
  EXPECT_EQ(kinds["double"], 11);
  EXPECT_EQ(kinds["null"], 22);
  EXPECT_EQ(kinds["outside"], 11);
  for (const AltClass& c : alt_classes()) EXPECT_GE(classes[c.name], 6) << c.name;
  EXPECT_NE(draw_alt_pair(1, 5).fit.noise_seed, draw_alt_pair(1, 6).fit.noise_seed);
}

TEST(AltReality, SessionsRestartTheirClocksWhileTheSensorAges) {
  for (int i = 1; i <= 10; ++i) {
    const AltPairSpec spec = draw_alt_pair(i, 9, 1200.0);
    const AltPair pair = render_alt_pair(spec);
    EXPECT_EQ(pair.fit.t_s.front(), 0.0);
    EXPECT_EQ(pair.heldout.t_s.front(), 0.0);
    EXPECT_GT(spec.heldout.start_age_s, spec.fit.start_age_s + spec.fit.duration_s);
    EXPECT_EQ(spec.fit.fs_hz, spec.heldout.fs_hz);
    EXPECT_GE(spec.fit.noise_v, 0.01 - 1e-12);
    EXPECT_LE(spec.fit.noise_v, 0.1);
    EXPECT_NEAR(pair.fit.t_s[1], 1.0 / spec.fit.fs_hz, 1e-6);
  }
}

// Every shape of every class, drawn and rendered alone on one session, changes the gap an ideal
// twin sees (recorded voltage less the ideal sensor's at the recorded clearance and temperature).
TEST(AltReality, EveryShapeOfEveryClassChangesWhatAnIdealTwinSees) {
  AltPairSpec spec = draw_alt_pair(8, 3, 1800.0);  // a null pair: its sessions, no effect
  ASSERT_EQ(spec.kind, AltPairKind::kNull);
  const AltRecording base = render_session(spec.fit, {}, false);
  std::vector<AltClass> classes = alt_classes();
  classes.push_back(alt_class("outside"));
  AltRandom random(17);
  for (const AltClass& c : classes) {
    ASSERT_GE(c.shapes.size(), 2u) << c.name;
    for (const std::string& shape : c.shapes) {
      AltEffectDraw draw = c.draw(shape, {spec.fit.fs_hz, spec.fit.start_age_s, 1800.0}, random);
      if (!draw.amplitude_key.empty()) draw.params[draw.amplitude_key] *= 0.2;
      // A knee low enough for this session's clearances to reach it.
      if (c.name == "range_compression") draw.params["knee0_v"] = 6.0;
      const AltRecording with = render_session(spec.fit, {draw}, false);
      double sum = 0.0;
      for (std::size_t i = 0; i < base.size(); ++i) {
        const double ideal_with = ideal_sensor_voltage(with.clearance_mm[i], with.temp_c[i]);
        const double ideal_base = ideal_sensor_voltage(base.clearance_mm[i], base.temp_c[i]);
        sum += std::pow((with.voltage_v[i] - ideal_with) - (base.voltage_v[i] - ideal_base), 2);
      }
      EXPECT_GT(std::sqrt(sum / static_cast<double>(base.size())), 1e-3) << c.name << "/" << shape;
    }
  }
}

TEST(AltReality, AmplitudesAreScaledToOneToFiveTimesTheNoise) {
  int scaled = 0;
  for (int i = 1; i <= 40; ++i) {
    const AltPairSpec spec = draw_alt_pair(i, 21, 900.0);
    for (const TruthEffect& e : spec.truth) {
      if (e.draw.amplitude_key.empty()) continue;
      ++scaled;
      const double size = e.rms_v / spec.fit.noise_v;
      EXPECT_GT(size, 0.9) << e.draw.class_name << "/" << e.draw.shape;
      EXPECT_LT(size, 5.5) << e.draw.class_name << "/" << e.draw.shape;
    }
  }
  EXPECT_GT(scaled, 15);
}

// A converter pair records on a grid of at most 2^bits values; a null pair on none.
TEST(AltReality, AConverterLeavesAGridAndANullPairNone) {
  for (int i = 1; i <= 110; ++i) {
    const AltPairSpec spec = draw_alt_pair(i, 4, 900.0);
    if (spec.truth.size() != 1 || spec.truth[0].draw.class_name != "quantisation") continue;
    const AltRecording fit = render_alt_pair(spec).fit;
    const std::set<double> values(fit.voltage_v.begin(), fit.voltage_v.end());
    EXPECT_LE(values.size(),
              std::ldexp(1.0, static_cast<int>(spec.truth[0].draw.params.at("bits"))));
  }
  const AltPairSpec null_spec = draw_alt_pair(8, 4, 900.0);
  const AltRecording null_fit = render_alt_pair(null_spec).fit;
  const std::set<double> values(null_fit.voltage_v.begin(), null_fit.voltage_v.end());
  EXPECT_GT(values.size(), null_fit.size() / 2);
}

TEST(AltReality, TheTruthGoesToASidecarBesideTheRecordings) {
  const auto dir = testing::fresh_test_dir("alt_reality_pair");
  const AltPairSpec spec = draw_alt_pair(7, 2, 900.0);  // a double
  const AltPair pair = render_alt_pair(spec);
  const auto paths = write_alt_pair(dir, spec, pair);
  ASSERT_EQ(paths.size(), 3u);
  const diagnose::RecordingSeries fit = diagnose::read_recording_series(paths[0].string());
  ASSERT_EQ(fit.size(), pair.fit.size());
  for (std::size_t i = 0; i < fit.size(); i += 97) {
    EXPECT_EQ(fit.voltage_v[i], pair.fit.voltage_v[i]) << i;  // memory holds what the CSV holds
    EXPECT_EQ(fit.temp_c[i], pair.fit.temp_c[i]) << i;
  }
  std::ifstream in(paths[2]);
  const nlohmann::json truth = nlohmann::json::parse(in);
  EXPECT_EQ(truth["kind"], "double");
  ASSERT_EQ(truth["truth"].size(), 2u);
  for (const auto& e : truth["truth"]) {
    EXPECT_TRUE(e.contains("class") && e.contains("shape") && e.contains("params")) << e.dump();
  }
  EXPECT_GT(truth["heldout_session"]["start_age_s"].get<double>(),
            truth["fit_session"]["start_age_s"].get<double>());
}

}  // namespace
}  // namespace flange::alt_reality

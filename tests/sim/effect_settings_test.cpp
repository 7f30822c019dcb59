// SPDX-License-Identifier: MIT
// Effect names, keys and values from the command line or a twin file: defaults, ranges, and
// one-line errors that name the effect, the key and the valid range.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>
#include <string>

#include "effect_argument.h"
#include "effect_catalogue.h"
#include "sim_error.h"

namespace flange::sim {
namespace {

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const BadArgument& error) {
    return error.what();
  }
  return "";
}

TEST(EffectCatalogue, HoldsTheTwelveEffectsInChainOrderWithSaneDefaults) {
  const std::vector<std::string> expected = {
      "vibration",         "thermal_lag",       "nonlinearity",      "temp_gain_drift",
      "temp_offset_drift", "ageing_drift",      "range_compression", "thermal_lag_volts",
      "mains_pickup",      "channel_skew",      "tabulated",         "adc_quantization"};
  ASSERT_EQ(effect_catalogue().size(), expected.size());
  ChainStage previous = ChainStage::kMount;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const EffectSpec& spec = effect_catalogue()[i];
    EXPECT_EQ(spec.name, expected[i]);
    EXPECT_GE(spec.stage, previous) << spec.name;
    previous = spec.stage;
    std::set<std::string> keys;
    for (const ParamSpec& param : spec.params) {
      EXPECT_TRUE(keys.insert(param.key).second) << spec.name << "." << param.key;
      EXPECT_LE(param.min, param.default_value) << spec.name << "." << param.key;
      EXPECT_LE(param.default_value, param.max) << spec.name << "." << param.key;
      EXPECT_FALSE(param.meaning.empty()) << spec.name << "." << param.key;
    }
    // Every effect builds from its defaults alone, but the tabulated one, which needs its table.
    if (spec.name == tabulated_effect_name()) {
      EXPECT_THROW(make_effect(make_effect_settings(spec.name, {}, "test"), 0.0, 10.0, 1),
                   BadArgument);
      continue;
    }
    EXPECT_NE(make_effect(make_effect_settings(spec.name, {}, "test"), 0.0, 10.0, 1), nullptr);
  }
}

TEST(EffectSettings, DefaultsAreReplacedOnlyByTheGivenKeys) {
  const EffectSettings settings =
      make_effect_settings("mains_pickup", {{"amplitude_v", 0.2}}, "test");
  EXPECT_EQ(settings.params.at("amplitude_v"), 0.2);
  EXPECT_EQ(settings.params.at("mains_hz"), 50.0);
  EXPECT_EQ(settings.params.size(), 5u);
}

TEST(EffectSettings, ErrorsNameEffectKeyAndRangeInOneLine) {
  const std::string unknown_effect =
      error_of([] { make_effect_settings("hum", {}, "--effect hum"); });
  EXPECT_NE(unknown_effect.find("unknown effect 'hum'"), std::string::npos) << unknown_effect;
  EXPECT_NE(unknown_effect.find("mains_pickup"), std::string::npos) << unknown_effect;

  const std::string unknown_key = error_of([] {
    make_effect_settings("mains_pickup", {{"amp", 1.0}}, "--effect mains_pickup");
  });
  EXPECT_NE(unknown_key.find("unknown key 'amp'"), std::string::npos) << unknown_key;
  EXPECT_NE(unknown_key.find("amplitude_v"), std::string::npos) << unknown_key;

  const std::string out_of_range = error_of([] {
    make_effect_settings("mains_pickup", {{"amplitude_v", 5.0}}, "--effect mains_pickup");
  });
  EXPECT_EQ(out_of_range,
            "--effect mains_pickup: amplitude_v = 5 is outside its valid range [0, 1] V");

  const std::string fraction = error_of([] {
    make_effect_settings("adc_quantization", {{"bits", 12.5}}, "w");
  });
  EXPECT_EQ(fraction, "w: bits = 12.5 is outside its valid range [4, 24] (integer)");

  const std::string not_finite = error_of([] {
    make_effect_settings("thermal_lag", {{"tau_s", std::nan("")}}, "w");
  });
  EXPECT_NE(not_finite.find("tau_s = nan is outside its valid range [-3600, 3600] s"),
            std::string::npos)
      << not_finite;

  const std::string inverted_band = error_of([] {
    make_effect_settings("vibration", {{"f_low_hz", 50.0}, {"f_high_hz", 20.0}}, "w");
  });
  EXPECT_EQ(inverted_band, "w: f_low_hz must be below f_high_hz (vibration)");
  for (const std::string& message :
       {unknown_effect, unknown_key, out_of_range, fraction, not_finite, inverted_band}) {
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(EffectArgument, SplitsNameAndKeyValuePairs) {
  const EffectArgument bare = parse_effect_argument("vibration");
  EXPECT_EQ(bare.name, "vibration");
  EXPECT_TRUE(bare.values.empty());
  const EffectArgument tuned = parse_effect_argument("mains_pickup:amplitude_v=0.1,mains_hz=+60");
  EXPECT_EQ(tuned.name, "mains_pickup");
  EXPECT_EQ(tuned.values.at("amplitude_v"), 0.1);
  EXPECT_EQ(tuned.values.at("mains_hz"), 60.0);
  EXPECT_EQ(parse_effect_argument("thermal_lag:tau_s=-1e2").values.at("tau_s"), -100.0);
}

TEST(EffectArgument, MalformedArgumentsAreRejectedWithTheArgumentNamed) {
  for (const std::string& text :
       {std::string(""), std::string(":tau_s=1"), std::string("thermal_lag:"),
        std::string("thermal_lag:tau_s"), std::string("thermal_lag:=1"),
        std::string("thermal_lag:tau_s=abc"), std::string("thermal_lag:tau_s=1x"),
        std::string("thermal_lag:tau_s="), std::string("thermal_lag:tau_s=1,,"),
        std::string("thermal_lag:tau_s=1,tau_s=2")}) {
    const std::string message = error_of([&] { parse_effect_argument(text); });
    EXPECT_EQ(message.rfind("--effect '" + text + "'", 0), 0u) << text << " -> " << message;
  }
}

}  // namespace
}  // namespace flange::sim

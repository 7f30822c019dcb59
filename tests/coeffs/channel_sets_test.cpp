// SPDX-License-Identifier: MIT
// A coefficient set per channel (coeffs/src/channel_sets.h): one format for all channels, each
// channel's words those of its own design in that format, and the outputs that carry them.
#include <gtest/gtest.h>

#include <numeric>

#include "channel_sets.h"
#include "design_error.h"
#include "design_outputs.h"
#include "generator.h"

namespace flange::coeffs {
namespace {

DesignRequest vehicle_order() {
  DesignRequest request;
  request.fs_hz = 100.0;
  request.order = 7;
  request.name = "sets";
  return request;
}

TEST(ChannelSets, EveryChannelSharesTheNarrowestFormat) {
  const DesignRecord record = generate_channel_designs(vehicle_order(), {0.259, 0.5, 1.0}, "test");
  ASSERT_EQ(record.channel_sets.size(), 3u);
  EXPECT_EQ(record.channels, 3);
  EXPECT_EQ(record.coef_sets(), 3);
  EXPECT_TRUE(record.analysis.rejection.empty()) << record.analysis.rejection;
  // Alone, the widest channel keeps the smallest feedback shift; every channel takes it.
  DesignRequest alone = vehicle_order();
  int smallest = 99;
  for (double fc : {0.259, 0.5, 1.0}) {
    alone.fc_hz = fc;
    smallest = std::min(smallest, generate_design(alone, "alone").quantized.feedback_shift);
  }
  for (const RecordChannelSet& set : record.channel_sets) {
    EXPECT_EQ(set.quantized.feedback_shift, smallest);
    EXPECT_EQ(set.quantized.coef_frac_bits, record.quantized.coef_frac_bits);
  }
  // Channel 1's words are its own design's in the shared format.
  alone.fc_hz = 0.5;
  alone.max_feedback_shift = smallest;
  alone.max_coef_frac_bits = record.quantized.coef_frac_bits;
  EXPECT_EQ(record.channel_sets[1].quantized.words, generate_design(alone, "x").quantized.words);
  EXPECT_NE(record.channel_sets[0].quantized.words, record.channel_sets[1].quantized.words);
}

TEST(ChannelSets, OutputsCarryEverySet) {
  const DesignRecord record = generate_channel_designs(vehicle_order(), {0.259, 0.5}, "test");
  const std::vector<std::int64_t> words = all_words(record);
  ASSERT_EQ(words.size(), 2 * record.quantized.words.size());
  EXPECT_TRUE(std::equal(record.channel_sets[1].quantized.words.begin(),
                         record.channel_sets[1].quantized.words.end(),
                         words.begin() + static_cast<std::ptrdiff_t>(record.quantized.words.size())));
  const std::string package = params_package(record);
  EXPECT_NE(package.find("NumChannels = 2;"), std::string::npos) << package;
  EXPECT_NE(package.find("CoefSets = 2;"), std::string::npos) << package;
  EXPECT_NE(package.find("RomDepth = 48;"), std::string::npos) << "words of one set";
  const nlohmann::ordered_json json = filter_json(record);
  EXPECT_EQ(json["quantized"]["coef_sets"], 2);
  EXPECT_EQ(json["quantized"]["words"].size(), words.size());
  EXPECT_EQ(json["channel_sets"].size(), 2u);
  EXPECT_EQ(json["channel_sets"][1]["fc_hz"], 0.5);
}

TEST(ChannelSets, SharedSetForManyChannels) {
  DesignRequest request = vehicle_order();
  request.fc_hz = 0.259;
  DesignRecord record = generate_design(request, "test");
  record.channels = 12;
  EXPECT_EQ(record.coef_sets(), 1);
  const std::string package = params_package(record);
  EXPECT_NE(package.find("NumChannels = 12;"), std::string::npos);
  EXPECT_NE(package.find("CoefSets = 1;"), std::string::npos);
  EXPECT_NE(package.find("ChannelWidth = 4;"), std::string::npos);
  EXPECT_EQ(channel_width(1), 1);
  EXPECT_EQ(channel_width(2), 1);
  EXPECT_EQ(channel_width(3), 2);
  EXPECT_EQ(channel_width(32), 5);
}

TEST(ChannelSets, RefusesWhatOneCoreCannotHold) {
  EXPECT_THROW(generate_channel_designs(vehicle_order(), {}, "t"), BadArgument);
  EXPECT_THROW(generate_channel_designs(vehicle_order(), std::vector<double>(33, 1.0), "t"),
               BadArgument);
  DesignRequest no_order = vehicle_order();
  no_order.order.reset();
  EXPECT_THROW(generate_channel_designs(no_order, {1.0}, "t"), BadArgument);
  // Split coefficients keep 33 fractional bits whatever the shared F, so cut-offs two decades
  // apart fit one core (before contract v2 the 0.259 Hz channel lost its poles in the 30 Hz
  // channel's format).
  const DesignRecord far_apart = generate_channel_designs(vehicle_order(), {0.259, 30.0}, "t");
  EXPECT_TRUE(far_apart.analysis.rejection.empty()) << far_apart.analysis.rejection;
}

}  // namespace
}  // namespace flange::coeffs

// SPDX-License-Identifier: MIT
// The blind check's score of one diagnosis (diagnose/data/selftest/blind_check.h): a finding
// named with the classes the data cannot tell it from is right first only where its own class is
// a true one, and right among the indistinguishable ones where any of them is.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "blind_check.h"
#include "finding_class.h"

namespace flange::diagnose {
namespace {

EffectFinding finding(const std::string& name, std::vector<std::string> alike = {}) {
  EffectFinding f;
  f.name = name;
  f.indistinguishable_from = std::move(alike);
  return f;
}

BlindScore scored(const std::vector<std::string>& truth, const std::vector<EffectFinding>& named) {
  BlindTruth t;
  t.kind = truth.size() == 1 ? BlindKind::kSingle : BlindKind::kPair;
  t.classes = truth;
  Diagnosis d;
  d.status = Status::kExplained;
  d.effects = named;
  return score_blind(t, d, {}, class_of_finding);
}

TEST(BlindScore, AFindingIndistinguishableFromTheTrueClassIsRightOnlyAmongThem) {
  const BlindScore both =
      scored({"range_compression"}, {finding("nonlinearity", {"range_compression"})});
  EXPECT_FALSE(both.top_correct);
  EXPECT_FALSE(both.all_found);
  EXPECT_TRUE(both.top_among_indistinguishable);
  EXPECT_TRUE(both.all_among_indistinguishable);

  const BlindScore alone = scored({"range_compression"}, {finding("nonlinearity")});
  EXPECT_FALSE(alone.top_among_indistinguishable);
  EXPECT_FALSE(alone.all_among_indistinguishable);

  const BlindScore pair =
      scored({"temperature_offset", "ageing"},
             {finding("temp_gain_drift", {"temp_offset_drift"}), finding("vibration")});
  EXPECT_TRUE(pair.top_among_indistinguishable);
  EXPECT_FALSE(pair.all_among_indistinguishable);  // the ageing is in no finding's set
}

}  // namespace
}  // namespace flange::diagnose

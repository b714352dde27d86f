// LocalizationVerdict (issue 25): "localized" only when the match and the pose agree. The old
// rule (localized whenever match >= min_match) said "localized" on every scan of the first
// sequence below, while the pose was wrong.
#include <gtest/gtest.h>

#include <cmath>

#include "amigobot_tracking/localization/localization_verdict.h"

using namespace amigobot_tracking::localization;

namespace {

VerdictConfig verdictConfig() {
  VerdictConfig c;
  c.min_match = 0.4;
  c.localized_match = 0.8;
  c.max_correction = 0.1;
  c.window = 5;
  return c;
}

}  // namespace

TEST(LocalizationVerdict, AWrongPoseInAnIcpMinimumIsNotLocalizedThoughItsMatchPassesMinMatch) {
  LocalizationVerdict verdict(verdictConfig());
  verdict.poseSet();  // a wrong /initialpose
  // ICP pulls the pose (large corrections), then settles in a wrong minimum that fits part of
  // the scan: 0.6 of the beams, above min_match, small corrections.
  for (double correction : {0.5, 0.4, 0.3}) {
    EXPECT_EQ(verdict.update({0.85, correction, 0.0}), LocalizationVerdict::State::kConverging);
    EXPECT_NE(verdict.reason().find("moved the pose"), std::string::npos) << verdict.reason();
  }
  for (int i = 0; i < 50; ++i) {
    EXPECT_EQ(verdict.update({0.6, 0.01, 0.0}), LocalizationVerdict::State::kConverging) << "scan " << i;
    EXPECT_FALSE(verdict.reason().empty());
  }
  // The pose found (e.g. global localisation): localized only after `window` agreeing scans.
  verdict.poseSet();
  for (int i = 0; i < 4; ++i) EXPECT_EQ(verdict.update({0.95, 0.02, 0.0}), LocalizationVerdict::State::kConverging) << "scan " << i;
  EXPECT_EQ(verdict.update({0.95, 0.02, 0.0}), LocalizationVerdict::State::kLocalized);
  EXPECT_TRUE(verdict.reason().empty());
}

TEST(LocalizationVerdict, LocalizedHoldsThroughClutterButNotThroughLossOrAJump) {
  LocalizationVerdict verdict(verdictConfig());
  for (int i = 0; i < 5; ++i) verdict.update({0.9, 0.0, 0.0});
  ASSERT_TRUE(verdict.localized());
  EXPECT_EQ(verdict.update({0.5, 0.02, 0.0}), LocalizationVerdict::State::kLocalized);  // a passer-by
  EXPECT_EQ(verdict.update({0.3, 0.0, 0.0}), LocalizationVerdict::State::kLost);
  EXPECT_NE(verdict.reason().find("min_match"), std::string::npos) << verdict.reason();
  for (int i = 0; i < 5; ++i) verdict.update({0.9, 0.0, 0.0});
  ASSERT_TRUE(verdict.localized());
  EXPECT_EQ(verdict.update({0.9, 0.0, 0.3}), LocalizationVerdict::State::kConverging);  // a heading jump
  EXPECT_EQ(verdict.update({0.9, 0.0, 0.0}), LocalizationVerdict::State::kConverging);  // a new window starts
  EXPECT_EQ(verdict.update({std::nan(""), 0.0, 0.0}), LocalizationVerdict::State::kLost);
}

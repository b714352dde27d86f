// A laser that sees nothing, or too few scans (core/perception/scan_health.h): the blind and rate
// judgements on synthetic scans and arrival times.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "amigobot_tracking/core/perception/scan_health.h"

using namespace amigobot_tracking::core;

namespace {

constexpr float kInfRange = std::numeric_limits<float>::infinity(), kNaNRange = std::numeric_limits<float>::quiet_NaN();

// A TiM-like scan: 541 beams over 270 degrees, 0.05..25 m.
ScanGeometry tim() {
  ScanGeometry g;
  g.angle_min = -0.75 * M_PI;
  g.angle_increment = 1.5 * M_PI / 540;
  g.range_min = 0.05;
  g.range_max = 25.0;
  return g;
}

std::string blind(const std::vector<float>& ranges) { return blindScanProblem(tim(), ranges.data(), ranges.size()); }

// `seconds` of arrivals every `period` from t0; each promises `scan_time`.
double feed(ScanRateJudge* judge, double t0, double seconds, double period, double scan_time) {
  double t = t0;
  for (; t < t0 + seconds; t += period) judge->arrived(t, scan_time);
  return t - period;
}

}  // namespace

TEST(BlindScan, AllAtRangeMaxInfOrBeyondIsBlindAndNamed) {
  EXPECT_EQ(blind(std::vector<float>(541, 25.0f)),
            "laser sees nothing: 541 beams, all at or beyond range_max 25 m; set ~open_space if the lab really is "
            "empty around the laser");
  EXPECT_NE(blind(std::vector<float>(541, kInfRange)), "");
  EXPECT_NE(blind(std::vector<float>(541, 25.01f)), "");  // just above range_max
  std::vector<float> mixed(541, kInfRange);
  mixed[3] = kNaNRange;
  mixed[4] = 0.01f;  // below range_min
  mixed[5] = 30.0f;
  const std::string why = blind(mixed);
  EXPECT_NE(why.find("none within [range_min 0.05, range_max 25) m (539 at or beyond range_max, 1 NaN, 1 below "
                     "range_min)"),
            std::string::npos)
      << why;
}

TEST(BlindScan, OneReturnInsideTheRangeSees) {
  std::vector<float> ranges(541, kInfRange);
  ranges[270] = 24.9f;  // a pole far ahead
  EXPECT_EQ(blind(ranges), "");
  ranges[270] = 0.05f;  // at range_min: a return
  EXPECT_EQ(blind(ranges), "");
}

TEST(ScanRate, APromisedRateKeptIsNoProblem) {
  ScanRateJudge judge;
  feed(&judge, 100.0, 5.0, 1.0 / 15, 1.0 / 15);
  EXPECT_NEAR(judge.measuredRate(), 15.0, 1.0);
  EXPECT_EQ(judge.problem(), "");
}

TEST(ScanRate, EveryOtherScanLostStopsNamingBothRates) {
  ScanRateJudge judge;
  const double t = feed(&judge, 100.0, 3.0, 1.0 / 15, 1.0 / 15);
  EXPECT_EQ(judge.problem(), "");
  feed(&judge, t + 2.0 / 15, 2.5, 2.0 / 15, 1.0 / 15);  // every other scan dropped
  EXPECT_NEAR(judge.measuredRate(), 7.5, 1.0);
  const std::string why = judge.problem();
  EXPECT_NE(why.find("scan rate 7.5 Hz is below 0.70 x the 15.0 Hz the laser promises (its scan_time)"),
            std::string::npos)
      << why;
}

TEST(ScanRate, RecoversWhenTheRateComesBack) {
  ScanRateJudge judge;
  double t = feed(&judge, 0.0, 3.0, 2.0 / 15, 1.0 / 15);
  EXPECT_NE(judge.problem(), "");
  feed(&judge, t + 1.0 / 15, 2.1, 1.0 / 15, 1.0 / 15);
  EXPECT_EQ(judge.problem(), "");
}

TEST(ScanRate, JitterUnderLoadIsNoProblem) {
  // Arrivals bunched by a busy machine: pairs 20 ms apart, the next pair 113 ms later (15 Hz on average)
  // and one 0.4 s hiccup.
  ScanRateJudge judge;
  double t = 0.0;
  for (int i = 0; i < 90; ++i) {
    if (i == 60) t += 0.4;  // and one hiccup of 0.4 s
    judge.arrived(t, 1.0 / 15);
    t += (i % 2 == 0) ? 0.02 : 2.0 / 15 - 0.02;
    EXPECT_EQ(judge.problem(), "") << "at " << t;
  }
}

TEST(ScanRate, NoVerdictBeforeOneWindowNorAfterAStall) {
  ScanRateJudge judge;
  feed(&judge, 0.0, 0.9, 2.0 / 15, 1.0 / 15);  // slow, but less than one window
  EXPECT_EQ(judge.problem(), "");
  ScanRateJudge stalled;
  const double t = feed(&stalled, 0.0, 3.0, 1.0 / 15, 1.0 / 15);
  stalled.arrived(t + 3.0, 1.0 / 15);  // back after a 3 s stall: that is scan_timeout's fault
  EXPECT_EQ(stalled.problem(), "");
}

TEST(ScanRate, UnknownPromiseIsNotJudgedUnlessExpectedRateIsGiven) {
  ScanRateJudge unknown;
  feed(&unknown, 0.0, 3.0, 0.5, 0.0);  // 2 Hz, scan_time 0
  EXPECT_EQ(unknown.problem(), "");
  ScanRateConfig config;
  config.expected_rate = 10.0;
  ScanRateJudge expected(config);
  feed(&expected, 0.0, 3.0, 0.5, 0.0);
  EXPECT_NE(expected.problem().find("the 10.0 Hz the laser promises (expected_scan_rate)"), std::string::npos)
      << expected.problem();
  ScanRateConfig off;
  off.min_fraction = 0.0;
  ScanRateJudge disabled(off);
  feed(&disabled, 0.0, 3.0, 0.5, 0.1);
  EXPECT_EQ(disabled.problem(), "");
}

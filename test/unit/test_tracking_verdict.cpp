// judgeTracking: the true error must stay within rho_inf + tolerance outside obstacle
// episodes (a clearance inside the detection band) and their recovery time, and at the end.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "amigobot_tracking/sim/tracking_verdict.h"

using namespace amigobot_tracking::sim;

namespace {

constexpr double kFar = 2.0;  // [m] clearance well outside the 0.25 m band

// 60 s at 20 Hz; error(t) [m] and offset clearance(t) [m]; the target's clearance far.
std::vector<TrackingSample> run(const std::function<double(double)>& error,
                                const std::function<double(double)>& clearance) {
  std::vector<TrackingSample> samples;
  for (int k = 0; k <= 1200; ++k) {
    const double t = 0.05 * k;
    samples.push_back(TrackingSample{t, error(t), clearance(t), kFar});
  }
  return samples;
}

TrackingVerdictConfig config() {
  TrackingVerdictConfig c;  // rho_inf 0.1 m + tolerance 0.05 m = 0.15 m; recovery 10 s; band 0.25 m
  c.recovery_time = 10.0;
  return c;
}

}  // namespace

TEST(TrackingVerdict, SmallErrorAfterTheStartTransientTracks) {
  // 0.8 m at the start (rho_0 = 1 m), 0.08 m from t = 8 s: within 0.15 m from 10 s on.
  const auto v = judgeTracking(run([](double t) { return t < 8.0 ? 0.8 : 0.08; }, [](double) { return kFar; }),
                               config());
  EXPECT_TRUE(v.tracked) << v.reason;
  EXPECT_DOUBLE_EQ(v.bound, 0.15);
  EXPECT_NEAR(v.max_judged_error, 0.08, 1e-12);
  EXPECT_NEAR(v.judged_time, 50.0, 0.05 + 1e-9);
  EXPECT_NEAR(v.judged_fraction, 50.0 / 60.0, 1e-3);
  EXPECT_TRUE(v.episodes.empty());
}

TEST(TrackingVerdict, LargeErrorInsideAnEpisodeAndItsRecoveryIsNotJudged) {
  // In the band from 20 to 25 s; error 1.2 m until 30 s (5 s after the episode), then 0.05 m.
  const auto v = judgeTracking(run([](double t) { return t >= 20.0 && t < 30.0 ? 1.2 : 0.05; },
                                   [](double t) { return t >= 20.0 && t < 25.0 ? 0.1 : kFar; }),
                               config());
  EXPECT_TRUE(v.tracked) << v.reason;
  ASSERT_EQ(v.episodes.size(), 1u);
  EXPECT_NEAR(v.episodes[0].start, 20.0, 1e-9);
  EXPECT_NEAR(v.episodes[0].end, 25.0, 1e-9);  // the first sample outside the band
  EXPECT_NEAR(v.episodes[0].peak_error, 1.2, 1e-12);
  EXPECT_NEAR(v.episodes[0].recovered_after, 5.0, 1e-9);
  EXPECT_NEAR(v.max_judged_error, 0.05, 1e-12);
}

TEST(TrackingVerdict, ARecoverySlowerThanTheRecoveryTimeFailsAndSaysWhen) {
  // The same episode, but the error stays 0.4 m until 40 s: 15 s after it, 5 s too long.
  const auto v = judgeTracking(run([](double t) { return t >= 20.0 && t < 40.0 ? 0.4 : 0.05; },
                                   [](double t) { return t >= 20.0 && t < 25.0 ? 0.1 : kFar; }),
                               config());
  EXPECT_FALSE(v.tracked);
  EXPECT_NEAR(v.max_judged_error, 0.4, 1e-12);
  EXPECT_NEAR(v.worst_time, 35.0, 1e-9);  // the first judged sample after the recovery time
  EXPECT_NEAR(v.judged_over_bound_time, 5.0, 0.05 + 1e-9);
  EXPECT_NEAR(v.episodes[0].recovered_after, 15.0, 1e-9);
  EXPECT_NE(v.reason.find("0.400 m > rho_inf + tolerance = 0.150 m"), std::string::npos) << v.reason;
}

TEST(TrackingVerdict, TheTargetNearAnObstacleIsAnEpisodeToo) {
  // The robot stays clear, but the target passes within the band from 30 to 33 s.
  std::vector<TrackingSample> samples = run([](double t) { return t >= 30.0 && t < 38.0 ? 0.5 : 0.05; },
                                            [](double) { return kFar; });
  for (TrackingSample& s : samples) s.clearance_target = s.t >= 30.0 && s.t < 33.0 ? 0.2 : kFar;
  const auto v = judgeTracking(samples, config());
  EXPECT_TRUE(v.tracked) << v.reason;
  EXPECT_EQ(v.episodes.size(), 1u);
}

TEST(TrackingVerdict, TheToleranceAbsorbsACentimetreLocalisationError) {
  // A steady 0.13 m (rho_inf 0.1 m plus 3 cm of localisation error) passes with 0.05 m, not with 0.
  const auto samples = run([](double) { return 0.13; }, [](double) { return kFar; });
  EXPECT_TRUE(judgeTracking(samples, config()).tracked);
  TrackingVerdictConfig strict = config();
  strict.tolerance = 0.0;
  EXPECT_FALSE(judgeTracking(samples, strict).tracked);
}

TEST(TrackingVerdict, ALargeFinalErrorFailsEvenInsideARecovery) {
  // The run ends 2 s after an episode with the robot 0.7 m behind.
  const auto v = judgeTracking(run([](double t) { return t >= 50.0 ? 0.7 : 0.05; },
                                   [](double t) { return t >= 50.0 && t < 58.0 ? 0.1 : kFar; }),
                               config());
  EXPECT_FALSE(v.tracked);
  EXPECT_NEAR(v.final_error, 0.7, 1e-12);
  EXPECT_NE(v.reason.find("final"), std::string::npos) << v.reason;
  EXPECT_LT(v.episodes[0].recovered_after, 0.0) << "never recovered within the run";
}

TEST(TrackingVerdict, NothingJudgedIsNotTracking) {
  const auto v = judgeTracking(run([](double) { return 0.0; }, [](double) { return 0.0; }), config());
  EXPECT_FALSE(v.tracked);
  EXPECT_NE(v.reason.find("nothing judged"), std::string::npos);
  EXPECT_FALSE(judgeTracking({}, config()).tracked);
}

TEST(TrackingVerdict, ValidateNamesTheBadKey) {
  TrackingVerdictConfig c;
  EXPECT_EQ(c.validate(), "");
  c.tolerance = -0.01;
  EXPECT_EQ(c.validate().rfind("tolerance:", 0), 0u);
  c = TrackingVerdictConfig{};
  c.recovery_time = std::nan("");
  EXPECT_EQ(c.validate().rfind("recovery_time:", 0), 0u);
}

// Run metrics on small hand-computed trajectories, and the variable-step rule.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "amigobot_tracking/sim/metrics.h"
#include "amigobot_tracking/sim/step_size.h"

using namespace amigobot_tracking::core;
using namespace amigobot_tracking::sim;

namespace {

MetricSample sample(double h, Eigen::Vector2d e, double rho, Twist2 u) {
  MetricSample s;
  s.h = h;
  s.e = e;
  s.rho = rho;
  s.u = u;
  return s;
}

}  // namespace

TEST(Metrics, AveragesAreTimeWeightedLeftSums) {
  MetricsAccumulator acc;
  acc.add(sample(1.0, {3.0, 4.0}, 10.0, {1.0, 2.0}));  // |e| = 5 held 1 s
  acc.add(sample(3.0, {0.0, 1.0}, 2.0, {0.0, 1.0}));   // |e| = 1 held 3 s
  acc.add(sample(0.0, {0.6, 0.8}, 1.25, {9.0, 9.0}));  // last step: no time, counts for final/max
  const RunMetrics m = acc.result();
  EXPECT_DOUBLE_EQ(m.sim_time, 4.0);
  EXPECT_DOUBLE_EQ(m.ase, (25.0 * 1.0 + 1.0 * 3.0) / 4.0);  // 7
  EXPECT_DOUBLE_EQ(m.aae, (5.0 * 1.0 + 1.0 * 3.0) / 4.0);   // 2
  EXPECT_DOUBLE_EQ(m.tec, 1.0 * (1.0 + 4.0) + 3.0 * (0.0 + 1.0));  // 8
  EXPECT_DOUBLE_EQ(m.max_e_over_rho, 0.8);  // 1 / 1.25 at the last step
  EXPECT_DOUBLE_EQ(m.max_rho, 10.0);
  EXPECT_DOUBLE_EQ(m.final_error, 1.0);
  EXPECT_EQ(m.steps, 3u);
}

TEST(Metrics, IntegralsOfAConstantErrorAreESquaredTAndET) {
  // |e| = 0.25 m held for T = 8 s in 160 steps of 0.05 s: ISE = e^2 T = 0.5 m^2 s, IAE = e T = 2 m s,
  // and the averages are the integrals over T.
  MetricsAccumulator acc;
  for (int k = 0; k < 160; ++k) {
    MetricSample s = sample(0.05, {0.15, 0.2}, 1.0, {});
    s.e_true = {0.0, 0.5};  // |e*| = 0.5 m
    acc.add(s);
  }
  acc.add(sample(0.0, {0.15, 0.2}, 1.0, {}));  // the last step holds for no time
  const RunMetrics m = acc.result();
  EXPECT_NEAR(m.sim_time, 8.0, 1e-12);
  EXPECT_NEAR(m.ise, 0.25 * 0.25 * 8.0, 1e-12);
  EXPECT_NEAR(m.iae, 0.25 * 8.0, 1e-12);
  EXPECT_NEAR(m.true_ise, 0.5 * 0.5 * 8.0, 1e-12);
  EXPECT_NEAR(m.true_iae, 0.5 * 8.0, 1e-12);
  EXPECT_NEAR(m.ise, m.ase * m.sim_time, 1e-12);
  EXPECT_NEAR(m.iae, m.aae * m.sim_time, 1e-12);
}

TEST(Metrics, AseIsAtLeastAaeSquared) {
  // Jensen: the time average of |e|^2 is never below the square of the average of |e|.
  MetricsAccumulator acc;
  for (int k = 0; k < 50; ++k) acc.add(sample(0.1, {std::sin(0.3 * k), 0.5}, 2.0, {}));
  const RunMetrics m = acc.result();
  EXPECT_GE(m.ase, m.aae * m.aae);
}

TEST(Metrics, LawWithoutRhoDoesNotCountTheRatio) {
  MetricsAccumulator acc;
  acc.add(sample(1.0, {1.0, 0.0}, 0.0, {}));
  EXPECT_DOUBLE_EQ(acc.result().max_e_over_rho, 0.0);
}

TEST(Metrics, CollisionsAreEpisodesAndContactTimeIsSummed) {
  MetricsAccumulator acc;
  const double clearances[] = {1.0, -0.1, -0.2, 0.5, -0.05, 0.0};
  for (double c : clearances) {
    MetricSample s = sample(0.5, {0.0, 0.0}, 1.0, {});
    s.clearance_body = c;
    s.clearance_offset = c + 1.0;  // never in contact
    acc.add(s);
  }
  const RunMetrics m = acc.result();
  EXPECT_EQ(m.body_collisions, 2u);
  EXPECT_DOUBLE_EQ(m.body_contact_time, 1.5);
  EXPECT_DOUBLE_EQ(m.min_clearance_body, -0.2);
  EXPECT_EQ(m.offset_collisions, 0u);
  EXPECT_DOUBLE_EQ(m.min_clearance_offset, 0.8);
}

TEST(Metrics, CountsDiamondViolationsBeyondTheTolerance) {
  MetricsAccumulator acc;
  for (double norm : {1.0, 1.0 + 0.5e-9, 1.0 + 2e-9, 1.5}) {
    MetricSample s = sample(0.1, {0.0, 0.0}, 1.0, {});
    s.diamond_norm = norm;
    acc.add(s);
  }
  EXPECT_EQ(acc.result().diamond_violations, 2u);
}

TEST(Metrics, NonFiniteStepsAreCountedAndKeptOutOfTheAverages) {
  MetricsAccumulator acc;
  acc.add(sample(1.0, {2.0, 0.0}, 4.0, {}));
  acc.add(sample(1.0, {std::numeric_limits<double>::quiet_NaN(), 0.0}, 4.0, {}));
  MetricSample invalid = sample(1.0, {0.0, 0.0}, 4.0, {});
  invalid.valid = false;
  acc.add(invalid);
  const RunMetrics m = acc.result();
  EXPECT_EQ(m.nan_count, 2u);
  EXPECT_DOUBLE_EQ(m.ase, 4.0);
  EXPECT_DOUBLE_EQ(m.sim_time, 1.0);
}

TEST(Metrics, EstimatorErrorIsTimeRmsAndSettledMaximum) {
  MetricsAccumulator acc;
  MetricSample a = sample(1.0, {0.0, 0.0}, 1.0, {});
  a.velocity_error = {3.0, 4.0};  // transient: in the RMS, not in the settled maximum
  acc.add(a);
  MetricSample b = sample(3.0, {0.0, 0.0}, 1.0, {});
  b.velocity_error = {1.0, 0.0};
  b.estimator_settled = true;
  acc.add(b);
  const RunMetrics m = acc.result();
  EXPECT_DOUBLE_EQ(m.estimator_rms_error, std::sqrt((25.0 * 1.0 + 1.0 * 3.0) / 4.0));
  EXPECT_DOUBLE_EQ(m.estimator_max_error_settled, 1.0);
}

TEST(StepSize, LongStepFarFromEverything) {
  const StepPolicy policy{1e-3, 2e-2};
  StepSituation s;
  s.distance = std::numeric_limits<double>::infinity();
  s.max_speed = 15.0;
  EXPECT_DOUBLE_EQ(chooseStep(policy, s), 2e-2);
}

TEST(StepSize, CannotJumpThroughTheDetectionBand) {
  const StepPolicy policy{1e-3, 2e-2};
  StepSituation s;
  s.distance = 0.09;  // m to the band
  s.max_speed = 9.0;
  EXPECT_DOUBLE_EQ(chooseStep(policy, s), 0.01);
  s.distance = 0.0;
  EXPECT_DOUBLE_EQ(chooseStep(policy, s), 1e-3);
  s.distance = std::numeric_limits<double>::quiet_NaN();
  EXPECT_DOUBLE_EQ(chooseStep(policy, s), 1e-3);
}

TEST(StepSize, ShrinksWithTheErrorRatio) {
  const StepPolicy policy{1e-3, 2e-2};  // comfortable 0.5, tight 0.9
  StepSituation s;
  s.distance = std::numeric_limits<double>::infinity();
  s.error_ratio = 0.7;  // half way
  EXPECT_NEAR(chooseStep(policy, s), 1e-3 + 0.5 * 19e-3, 1e-15);
  s.error_ratio = 0.95;
  EXPECT_DOUBLE_EQ(chooseStep(policy, s), 1e-3);
}

TEST(StepSize, FineStepInsideABand) {
  const StepPolicy policy{1e-3, 2e-2};
  StepSituation s;
  s.distance = std::numeric_limits<double>::infinity();
  s.in_band = true;
  EXPECT_DOUBLE_EQ(chooseStep(policy, s), 1e-3);
}

TEST(StepSize, FixedWhenMaxIsNotAboveMin) {
  StepSituation s;
  s.distance = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(chooseStep(StepPolicy{1e-3, 0.0}, s), 1e-3);
}

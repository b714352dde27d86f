// Poses checked where they enter (core/supervision/transform_check.h, core/supervision/clock_offset.h,
// core/supervision/transform_intake.h): NaN and non-unit quaternions refused by field, a sample stamped
// ahead dropped without hiding the next good one, a publisher's clock offset named.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "amigobot_tracking/core/supervision/clock_offset.h"
#include "amigobot_tracking/core/supervision/transform_check.h"
#include "amigobot_tracking/core/supervision/transform_intake.h"

using namespace amigobot_tracking::core;

namespace {
const double kIntakeNaN = std::numeric_limits<double>::quiet_NaN();
const double kIntakeInf = std::numeric_limits<double>::infinity();
const Translation3 kOrigin{};
const Quaternion4 kIdentity{};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
}  // namespace

TEST(TransformCheck, AGoodTransformPasses) {
  EXPECT_EQ(transformProblem({1.0, -2.0, 0.0}, {0.0, 0.0, std::sin(0.3), std::cos(0.3)}), "");
  // Float32 round-off and a little more: within the tolerance.
  EXPECT_EQ(transformProblem(kOrigin, {0.0, 0.0, 0.0, 1.0005}), "");
}

TEST(TransformCheck, NaNAndInfAreNamedByField) {
  EXPECT_EQ(transformProblem({kIntakeNaN, 0.0, 0.0}, kIdentity), "translation x is nan");
  EXPECT_EQ(transformProblem({0.0, 0.0, -kIntakeInf}, kIdentity), "translation z is -inf");
  EXPECT_EQ(transformProblem(kOrigin, {kIntakeNaN, kIntakeNaN, kIntakeNaN, kIntakeNaN}), "rotation x is nan");
  EXPECT_EQ(transformProblem(kOrigin, {0.0, 0.0, 0.0, kIntakeInf}), "rotation w is inf");
}

TEST(TransformCheck, ZeroAndNonUnitQuaternionsAreRefused) {
  const std::string zero = transformProblem(kOrigin, {0.0, 0.0, 0.0, 0.0});  // a hand-written message's default
  EXPECT_TRUE(contains(zero, "not a unit quaternion (norm 0.000")) << zero;
  EXPECT_TRUE(contains(transformProblem(kOrigin, {0.0, 0.0, 0.0, 1.01}), "norm 1.010")) << "1 % off is refused";
  EXPECT_TRUE(contains(transformProblem(kOrigin, {0.0, 0.0, 0.0, 0.998}), "not a unit quaternion"));
}

TEST(TransformCheck, NormalisedIsUnit) {
  const Quaternion4 q = normalised({0.0, 0.0, 0.0006, 1.0004});
  EXPECT_NEAR(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w, 1.0, 1e-12);
}

TEST(ClockOffset, TheLeastDelayedSampleEstimatesTheOffset) {
  ClockOffsetEstimator clock(2.0);
  EXPECT_EQ(clock.at(0.0).samples, 0u);
  // Stamps 0.45 s behind, delays 1..20 ms, 50 Hz.
  for (int i = 0; i < 100; ++i) {
    const double stamp = 100.0 + 0.02 * i;
    clock.add(stamp, stamp + 0.45 + 0.001 + 0.019 * ((i * 7) % 10) / 9.0);
  }
  const ClockOffset c = clock.at(102.5);
  EXPECT_GE(c.samples, 90u);
  EXPECT_NEAR(c.offset, 0.451, 1e-9);
  EXPECT_EQ(clockOffsetText("target", c.offset), "target clock 0.45 s behind this machine: synchronise the clocks (chrony)");
  EXPECT_EQ(clockOffsetText("target", -0.3), "target clock 0.30 s ahead of this machine: synchronise the clocks (chrony)");
}

TEST(ClockOffset, OldSamplesLeaveTheWindow) {
  ClockOffsetEstimator clock(2.0);
  clock.add(100.0, 101.0);  // 1 s behind, long ago
  for (int i = 0; i < 10; ++i) clock.add(110.0 + 0.1 * i, 110.005 + 0.1 * i);
  EXPECT_NEAR(clock.at(111.0).offset, 0.005, 1e-9);
  EXPECT_EQ(clock.at(111.0).samples, 10u);
  EXPECT_EQ(clock.at(120.0).samples, 0u);
  clock.add(kIntakeNaN, 120.0);  // ignored
  EXPECT_DOUBLE_EQ(clock.lastArrival(), 110.905);
}

TEST(TransformIntake, ASampleStampedAheadIsDroppedAndTheNextGoodOneTaken) {
  TransformIntake intake(0.1);
  EXPECT_TRUE(intake.judge("target", 100.0, 100.001, kOrigin, kIdentity, false).accept);
  const IntakeVerdict ahead = intake.judge("target", 130.02, 100.02, kOrigin, kIdentity, false);
  EXPECT_FALSE(ahead.accept);
  EXPECT_EQ(ahead.problem, "stamped 30.000 s ahead of its arrival (tolerance 0.100 s)");
  EXPECT_TRUE(intake.judge("target", 100.04, 100.041, kOrigin, kIdentity, false).accept) << "the bad stamp was remembered";
  // Within the tolerance (the localisation's map -> odom is stamped ahead like amcl's).
  EXPECT_TRUE(intake.judge("odom", 100.15, 100.06, kOrigin, kIdentity, false).accept);
  // One stray sample does not make a clock problem.
  EXPECT_EQ(intake.clock("target", 100.05).problem, "");
}

TEST(TransformIntake, BadPosesAreRefusedStaticOrNot) {
  TransformIntake intake(0.1);
  EXPECT_EQ(intake.judge("target", 100.0, 100.0, {kIntakeNaN, 0.0, 0.0}, kIdentity, false).problem, "translation x is nan");
  const IntakeVerdict zero = intake.judge("laser", 0.0, 100.0, kOrigin, {0.0, 0.0, 0.0, 0.0}, true);
  EXPECT_FALSE(zero.accept);
  EXPECT_TRUE(contains(zero.problem, "not a unit quaternion")) << zero.problem;
  // A static transform's stamp carries no time: long ago is fine.
  EXPECT_TRUE(intake.judge("laser", 5.0, 100.0, kOrigin, kIdentity, true).accept);
  EXPECT_FALSE(intake.clock("laser", 100.0).known);
}

TEST(TransformIntake, AStreamStampedOneSecondOldAtAHealthyRateIsAClockProblem) {
  TransformIntake intake(0.1);
  for (int i = 0; i < 100; ++i) intake.judge("target", 99.0 + 0.02 * i, 100.0 + 0.02 * i + 0.002, kOrigin, kIdentity, false);
  const FrameClock c = intake.clock("target", 102.0);
  EXPECT_TRUE(c.known);
  EXPECT_NEAR(c.offset, 1.002, 1e-9);
  EXPECT_NEAR(c.since_arrival, 0.018, 1e-9);  // alive: not a dead publisher
  EXPECT_EQ(c.problem, "target clock 1.00 s behind this machine: synchronise the clocks (chrony)");
  EXPECT_EQ(intake.clock("nobody", 102.0).since_arrival, -1.0);
}

TEST(TransformIntake, AClockAheadIsNamedAlthoughEverySampleIsDropped) {
  TransformIntake intake(0.1);
  for (int i = 0; i < 50; ++i) {
    EXPECT_FALSE(intake.judge("target", 100.3 + 0.02 * i, 100.0 + 0.02 * i + 0.013, kOrigin, kIdentity, false).accept);
  }
  EXPECT_EQ(intake.clock("target", 101.0).problem,
            "target clock 0.29 s ahead of this machine: synchronise the clocks (chrony)");
  // A healthy clock: nothing said.
  TransformIntake healthy(0.1);
  for (int i = 0; i < 50; ++i) healthy.judge("target", 100.0 + 0.02 * i, 100.0 + 0.02 * i + 0.003, kOrigin, kIdentity, false);
  EXPECT_TRUE(healthy.clock("target", 101.0).known);
  EXPECT_EQ(healthy.clock("target", 101.0).problem, "");
}

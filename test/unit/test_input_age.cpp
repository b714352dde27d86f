// Input age on the receiver's clock (core/supervision/input_age.h): untrusted stamps are stale and named,
// a stream that stops is stale however it was stamped.
#include <gtest/gtest.h>

#include <cmath>

#include "amigobot_tracking/core/supervision/input_age.h"

using amigobot_tracking::core::InputAge;
using amigobot_tracking::core::InputAgeTracker;

TEST(InputAge, NothingYet) {
  const InputAgeTracker tracker(0.1);
  EXPECT_FALSE(tracker.at(5.0).have);
}

TEST(InputAge, AGoodStampAgesFromItself) {
  InputAgeTracker tracker(0.1);
  tracker.arrived(99.9, 100.0);
  const InputAge a = tracker.at(100.2);
  EXPECT_TRUE(a.have);
  EXPECT_EQ(a.problem, "");
  EXPECT_NEAR(a.age, 0.3, 1e-9);
}

TEST(InputAge, AStampOfZeroIsStaleAndNamed) {  // issue 25: it read as "always current"
  InputAgeTracker tracker(0.1);
  tracker.arrived(0.0, 100.0);
  const InputAge a = tracker.at(100.0);
  EXPECT_TRUE(std::isinf(a.age));
  EXPECT_EQ(a.problem, "stamp is 0");
}

TEST(InputAge, AFutureStampBeyondTheToleranceIsStaleAndNamed) {  // issue 25: it was clamped to 0
  InputAgeTracker tracker(0.1);
  tracker.arrived(130.0, 100.0);
  const InputAge a = tracker.at(100.0);
  EXPECT_TRUE(std::isinf(a.age));
  EXPECT_NE(a.problem.find("30.000 s in the future"), std::string::npos) << a.problem;
  // Slightly ahead (clocks of two hosts): within the tolerance it is fresh.
  tracker.arrived(100.05, 100.0);
  EXPECT_EQ(tracker.at(100.0).problem, "");
  EXPECT_DOUBLE_EQ(tracker.at(100.0).age, 0.0);
}

TEST(InputAge, AStreamThatStopsGoesStaleOnTheReceiversClock) {
  InputAgeTracker tracker(0.1);
  tracker.arrived(100.08, 100.0);  // ahead, but within the tolerance
  // Silence: age grows from the arrival although now - stamp stays small or negative.
  EXPECT_NEAR(tracker.at(100.5).age, 0.5, 1e-9);
  EXPECT_NEAR(tracker.at(102.0).age, 2.0, 1e-9);
}

TEST(InputAge, APolledStreamArrivesOnlyWhenItsStampChanges) {
  InputAgeTracker tracker(0.1);
  tracker.seen(100.0, 100.0);
  tracker.seen(100.0, 101.0);  // the same transform again: no arrival
  EXPECT_NEAR(tracker.at(101.0).age, 1.0, 1e-9);
  tracker.seen(101.0, 101.0);
  EXPECT_NEAR(tracker.at(101.0).age, 0.0, 1e-9);
}

TEST(InputAge, NonFiniteTimesAreStale) {
  InputAgeTracker tracker(0.1);
  tracker.arrived(std::nan(""), 100.0);
  EXPECT_TRUE(std::isinf(tracker.at(100.0).age));
  EXPECT_NE(tracker.at(100.0).problem, "");
}

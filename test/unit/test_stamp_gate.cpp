// The localisation's map -> odom goes out only when its stamp advances (no TF_REPEATED_DATA
// when a replayed /clock stands still, or jumps back at a bag's loop).
#include <gtest/gtest.h>

#include "amigobot_tracking/ros/stamp_gate.h"

using amigobot_tracking::ros_layer::StampGate;

TEST(StampGate, PassesOnlyStampsThatAdvance) {
  StampGate gate;
  EXPECT_TRUE(gate.pass(ros::Time(0, 0)));  // the first, even at time zero
  EXPECT_FALSE(gate.pass(ros::Time(0, 0)));
  EXPECT_TRUE(gate.pass(ros::Time(10, 0)));
  EXPECT_FALSE(gate.pass(ros::Time(10, 0)));   // the clock stands still: 30 Hz of the same stamp
  EXPECT_FALSE(gate.pass(ros::Time(9, 500)));  // or goes back
  EXPECT_TRUE(gate.pass(ros::Time(10, 1)));
}

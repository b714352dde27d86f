// ROS <-> core conversions (ros/conversions.h), no master needed.
#include <gtest/gtest.h>

#include <cmath>

#include "amigobot_tracking/ros/conversions.h"

using namespace amigobot_tracking;
using namespace amigobot_tracking::ros_layer;

TEST(Conversions, PoseRoundTripsThroughATransform) {
  for (double yaw = -3.1; yaw < 3.14; yaw += 0.37) {
    const core::Pose2 pose{1.5, -2.0, yaw};
    const core::Pose2 back = toPose2(toTransform("map", "base_link", pose, ros::Time(1.0)).transform);
    EXPECT_DOUBLE_EQ(back.x, 1.5);
    EXPECT_DOUBLE_EQ(back.y, -2.0);
    EXPECT_NEAR(back.theta, yaw, 1e-12);
  }
}

TEST(Conversions, UpsideDownLaserIsAReflection) {
  // Laser rolled by pi about x (mounted upside down) at (0.1, 0) on a robot at yaw 0:
  // a point at +y in the laser frame is at -y in the parent frame.
  geometry_msgs::Transform t;
  t.translation.x = 0.1;
  t.rotation.x = 1.0;  // quaternion of a roll of pi
  t.rotation.w = 0.0;
  const Eigen::Affine2d a = toAffine2d(t);
  const Eigen::Vector2d p = a * Eigen::Vector2d(1.0, 0.5);
  EXPECT_NEAR(p.x(), 1.1, 1e-12);
  EXPECT_NEAR(p.y(), -0.5, 1e-12);
  EXPECT_NEAR(a.linear().determinant(), -1.0, 1e-12);
}

TEST(Conversions, StateCarriesTheControllerOutput) {
  core::ControllerOutput out;
  out.valid = true;
  out.e = {0.3, -0.4};
  out.rho = 0.6;
  out.u = {0.2, -0.1};
  out.u_d = {0.5, -0.25};
  out.active.saturated = true;
  out.active.yielding = true;
  out.detected_obstacles = 2;
  out.u_t = {0.05, -0.02};
  out.passing_side = -1;
  TrackingState state;
  fillState(out, &state);
  EXPECT_TRUE(state.valid);
  EXPECT_DOUBLE_EQ(state.e_norm, 0.5);
  EXPECT_DOUBLE_EQ(state.v, 0.2);
  EXPECT_DOUBLE_EQ(state.omega_d, -0.25);
  EXPECT_TRUE(state.saturated);
  EXPECT_FALSE(state.avoiding);
  EXPECT_TRUE(state.yielding);
  EXPECT_EQ(state.detected_obstacles, 2);
  EXPECT_DOUBLE_EQ(state.u_t.x, 0.05);
  EXPECT_DOUBLE_EQ(state.u_t.y, -0.02);
  EXPECT_EQ(state.passing_side, -1);
  const geometry_msgs::Twist twist = toTwist(out.u);
  EXPECT_DOUBLE_EQ(twist.linear.x, 0.2);
  EXPECT_DOUBLE_EQ(twist.angular.z, -0.1);
}

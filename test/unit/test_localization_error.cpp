// LocalizationErrorMeter: the believed pose (tf map -> odom -> base_link from a bag's /tf)
// against the ground truth at the truth's stamps.
#include <gtest/gtest.h>

#include <cmath>

#include <tf2/LinearMath/Quaternion.h>

#include "amigobot_tracking/ros/localization_error.h"

using namespace amigobot_tracking;

namespace {

geometry_msgs::TransformStamped transform(const std::string& parent, const std::string& child, double t, double x,
                                          double y, double yaw) {
  geometry_msgs::TransformStamped out;
  out.header.stamp = ros::Time(t);
  out.header.frame_id = parent;
  out.child_frame_id = child;
  out.transform.translation.x = x;
  out.transform.translation.y = y;
  tf2::Quaternion q;
  q.setRPY(0.0, 0.0, yaw);
  out.transform.rotation.x = q.x();
  out.transform.rotation.y = q.y();
  out.transform.rotation.z = q.z();
  out.transform.rotation.w = q.w();
  return out;
}

tf2_msgs::TFMessage message(const geometry_msgs::TransformStamped& t) {
  tf2_msgs::TFMessage m;
  m.transforms.push_back(t);
  return m;
}

// A robot driving along x at 0.2 m/s for 10 s; odometry (odom -> base_footprint) exact, a
// static base_footprint -> base_link, and map -> odom off by (dx, dy, dyaw) from the truth.
ros_layer::LocalizationErrorStats drive(double dx, double dy, double dyaw, double skip_first = 0.0) {
  ros_layer::LocalizationErrorMeter meter("map", "base_link", skip_first);
  meter.addTf(message(transform("base_footprint", "base_link", 0.0, 0.0, 0.0, 0.0)), true);
  for (int k = 0; k <= 100; ++k) {
    const double t = 100.0 + 0.1 * k, x = 0.02 * k;
    meter.addTf(message(transform("odom", "base_footprint", t, x, 0.0, 0.0)), false);
    meter.addTf(message(transform("map", "odom", t, dx, dy, dyaw)), false);
  }
  for (int k = 1; k < 100; ++k) meter.addTruth(ros::Time(100.0 + 0.1 * k + 0.05), core::Pose2{0.02 * k + 0.01, 0.0, 0.0});
  return meter.finish();
}

}  // namespace

TEST(LocalizationError, ExactLocalisationHasNoError) {
  const auto s = drive(0.0, 0.0, 0.0);
  EXPECT_EQ(s.samples, 99u);
  EXPECT_EQ(s.missed, 0u);
  EXPECT_NEAR(s.rms_position, 0.0, 1e-9);
  EXPECT_NEAR(s.max_heading, 0.0, 1e-9);
}

TEST(LocalizationError, AConstantOffsetIsMeasured) {
  const auto s = drive(0.03, -0.04, 0.0);
  EXPECT_NEAR(s.rms_position, 0.05, 1e-9);
  EXPECT_NEAR(s.max_position, 0.05, 1e-9);
}

TEST(LocalizationError, AHeadingOffsetRotatesThePositionToo) {
  // map -> odom rotated by 0.1 rad about the origin: the robot at (x, 0) is believed at
  // x (cos 0.1, sin 0.1), so the position error grows with x, and the heading error is 0.1.
  const auto s = drive(0.0, 0.0, 0.1);
  EXPECT_NEAR(s.rms_heading, 0.1, 1e-9);
  EXPECT_NEAR(s.max_heading, 0.1, 1e-9);
  EXPECT_NEAR(s.max_position, 2.0 * 1.99 * std::sin(0.05), 1e-9);  // chord at x = 1.99 m
}

TEST(LocalizationError, HeadingErrorIsWrapped) {
  const auto s = drive(0.0, 0.0, 2.0 * M_PI - 0.02);
  EXPECT_NEAR(s.max_heading, 0.02, 1e-9);
}

TEST(LocalizationError, TruthWithoutABelievedPoseIsCountedAsMissed) {
  ros_layer::LocalizationErrorMeter meter("map", "base_link");
  meter.addTruth(ros::Time(5.0), core::Pose2{});
  const auto s = meter.finish();
  EXPECT_EQ(s.samples, 0u);
  EXPECT_EQ(s.missed, 1u);
  EXPECT_TRUE(std::isnan(s.rms_position));
}

TEST(LocalizationError, TheStartUpIsSkipped) {
  const auto s = drive(0.0, 0.0, 0.0, 2.0);
  EXPECT_EQ(s.samples, 79u);
}

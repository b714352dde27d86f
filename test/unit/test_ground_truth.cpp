// ground_truth_localization: the map -> odom correction, its parameters, and the status
// client it reads (aria/emulator_status.h) against the real emulator, including the
// emulator going away.
#include <cmath>

#include <gtest/gtest.h>

#include "amigobot_tracking/aria/emulator_status.h"
#include "amigobot_tracking/ros/ground_truth.h"
#include "emulator_process.h"

using namespace amigobot_tracking;

TEST(GroundTruth, MapToOdomComposesToTheTruth) {
  const core::Pose2 truth{2.0, -1.0, 2.5};
  const core::Pose2 odom_base{0.7, 0.3, -1.2};
  const core::Pose2 m = ros_layer::mapToOdom(truth, odom_base);
  // (map -> odom) * (odom -> base)
  const double c = std::cos(m.theta), s = std::sin(m.theta);
  EXPECT_NEAR(m.x + c * odom_base.x - s * odom_base.y, truth.x, 1e-12);
  EXPECT_NEAR(m.y + s * odom_base.x + c * odom_base.y, truth.y, 1e-12);
  EXPECT_NEAR(core::wrapAngle(m.theta + odom_base.theta - truth.theta), 0.0, 1e-12);
}

TEST(GroundTruth, ValidateNamesTheBadField) {
  ros_layer::GroundTruthConfig c;
  EXPECT_EQ(c.validate(), "");
  c.port = 0;
  EXPECT_NE(c.validate().find("port"), std::string::npos);
  c = ros_layer::GroundTruthConfig();
  c.rate = -1;
  EXPECT_NE(c.validate().find("rate"), std::string::npos);
}

TEST(GroundTruth, ClientReadsTheEmulatorAndReportsItsLoss) {
  amigobot_test::EmulatorProcess emu;
  aria::StatusClient client("127.0.0.1", emu.statusPort(), 5.0);
  aria::EmulatorStatus s;
  ASSERT_EQ(client.query(&s), "");
  EXPECT_TRUE(client.connected());
  EXPECT_NEAR(s.pose.x, 0.0, 1e-9);  // default world: the robot starts at the origin
  aria::EmulatorStatus later;
  ASSERT_EQ(client.query(&later), "");
  EXPECT_GE(later.t, s.t);
  emu.kill(SIGTERM);
  std::string error;
  for (int i = 0; i < 5 && error.empty(); ++i) error = client.query(&s);  // the first send may still succeed
  EXPECT_FALSE(error.empty());
  EXPECT_FALSE(client.connected());
  EXPECT_NE(client.query(&s).find("cannot connect"), std::string::npos);
}

// trail_publisher: poses closer than min_distance are skipped; the oldest go beyond max_poses.
#include <gtest/gtest.h>

#include "amigobot_tracking/ros/trail.h"

using namespace amigobot_tracking;

namespace {
geometry_msgs::PoseStamped at(double x, double y) {
  geometry_msgs::PoseStamped p;
  p.pose.position.x = x;
  p.pose.position.y = y;
  return p;
}
}  // namespace

TEST(Trail, SkipsPosesThatDidNotMove) {
  ros_layer::TrailConfig c;
  c.min_distance = 0.1;
  nav_msgs::Path path;
  EXPECT_TRUE(ros_layer::appendToTrail(c, at(0, 0), &path));
  EXPECT_FALSE(ros_layer::appendToTrail(c, at(0.05, 0.05), &path));
  EXPECT_TRUE(ros_layer::appendToTrail(c, at(0.1, 0.05), &path));
  EXPECT_EQ(path.poses.size(), 2u);
}

TEST(Trail, KeepsTheNewestMaxPoses) {
  ros_layer::TrailConfig c;
  c.min_distance = 0.0;
  c.max_poses = 3;
  nav_msgs::Path path;
  for (int i = 0; i < 5; ++i) ros_layer::appendToTrail(c, at(i, 0), &path);
  ASSERT_EQ(path.poses.size(), 3u);
  EXPECT_DOUBLE_EQ(path.poses.front().pose.position.x, 2.0);
  EXPECT_DOUBLE_EQ(path.poses.back().pose.position.x, 4.0);
}

TEST(Trail, ValidateNamesTheBadField) {
  ros_layer::TrailConfig c;
  EXPECT_EQ(c.validate(), "");
  c.max_poses = 1;
  EXPECT_NE(c.validate().find("max_poses"), std::string::npos);
}

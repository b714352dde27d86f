// Parameter structs of the tracking node without a ROS master: validate() names the bad
// field, and URDF geometry is read with urdfdom. (The ROS loaders are checked in the
// rostest, which has a master.)
#include <gtest/gtest.h>

#include <limits>

#include "amigobot_tracking/ros/tracking_params.h"

using namespace amigobot_tracking::ros_layer;

TEST(TrackingParams, DefaultsAreValid) { EXPECT_EQ(TrackingNodeConfig().validate(), ""); }

TEST(TrackingParams, ValidateNamesTheBadField) {
  struct Case {
    const char* field;
    void (*spoil)(TrackingNodeConfig&);
  };
  const Case cases[] = {
      {"global_frame", [](TrackingNodeConfig& c) { c.global_frame.clear(); }},
      {"target_frame", [](TrackingNodeConfig& c) { c.target_frame = c.base_frame; }},
      {"control_rate", [](TrackingNodeConfig& c) { c.control_rate = 0.0; }},
      {"control_rate", [](TrackingNodeConfig& c) { c.control_rate = 5000.0; }},
      {"pose_timeout", [](TrackingNodeConfig& c) { c.pose_timeout = -1.0; }},
      {"scan_timeout", [](TrackingNodeConfig& c) { c.scan_timeout = std::numeric_limits<double>::infinity(); }},
      {"clicked_point_radius", [](TrackingNodeConfig& c) { c.clicked_point_radius = 0.0; }},
      // Upper bounds (issue 25): a minute without input is not fresh, no disk is 100 m.
      {"pose_timeout", [](TrackingNodeConfig& c) { c.pose_timeout = 61.0; }},
      {"scan_timeout", [](TrackingNodeConfig& c) { c.scan_timeout = 1e308; }},
      {"clicked_point_radius", [](TrackingNodeConfig& c) { c.clicked_point_radius = 1e6; }},
      {"target_exclusion_radius", [](TrackingNodeConfig& c) { c.target_exclusion_radius = 101.0; }},
      {"robot_model", [](TrackingNodeConfig& c) { c.robot.robot_model = "pioneer"; }},
      {"resume_v_accel", [](TrackingNodeConfig& c) { c.resume_v_accel = 0.0; }},
      {"resume_w_accel", [](TrackingNodeConfig& c) { c.resume_w_accel = std::numeric_limits<double>::quiet_NaN(); }},
  };
  for (const Case& test : cases) {
    TrackingNodeConfig config;
    test.spoil(config);
    const std::string error = config.validate();
    EXPECT_NE(error.find(test.field), std::string::npos) << "expected " << test.field << " in: " << error;
  }
}

// URDF geometry with urdfdom: radius from the base link's collision cylinder, offset from a
// fixed child link; a parse failure is an error, a missing link is reported.
TEST(TrackingParams, UrdfGeometry) {
  const std::string urdf = R"(<robot name="r">
    <link name="base_link"><collision><geometry><cylinder radius="0.18" length="0.2"/></geometry></collision></link>
    <link name="control_point"/>
    <joint name="cp" type="fixed"><parent link="base_link"/><child link="control_point"/>
      <origin xyz="0.25 0 0"/></joint></robot>)";
  UrdfGeometry g;
  ASSERT_EQ(readUrdfGeometry(urdf, "base_link", "control_point", &g), "");
  EXPECT_TRUE(g.found_radius);
  EXPECT_DOUBLE_EQ(g.radius, 0.18);
  EXPECT_TRUE(g.found_offset);
  EXPECT_DOUBLE_EQ(g.offset, 0.25);
  EXPECT_EQ(readUrdfGeometry(urdf, "base_link", "nothing", &g), "");
  EXPECT_FALSE(g.found_offset);
  EXPECT_NE(readUrdfGeometry(urdf, "chassis", "control_point", &g), "");
  EXPECT_NE(readUrdfGeometry("<robot", "base_link", "control_point", &g), "");
}


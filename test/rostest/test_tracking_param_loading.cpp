// rostest (tracking_nodelet.test, beside test_tracking_nodelet.cpp's cases): the
// tracking parameter loaders against a real master: refusals naming the bad parameter, and
// the shipped config files loading to what they say.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>

#include <string>
#include <vector>

#include <ros/ros.h>

#include "amigobot_tracking/ros/tracking_params.h"

namespace tracking_param_loading_test {

using namespace amigobot_tracking;

// The loaders refuse bad parameters with a message naming them (run here: they need a master).
TEST(TrackingParams, LoadersNameTheBadParameter) {
  ros::NodeHandle pnh("~bad");
  ros_layer::TrackingNodeConfig node;
  EXPECT_EQ(ros_layer::loadNodeConfig(pnh, &node), "");
  pnh.setParam("control_rate", -5.0);
  EXPECT_NE(ros_layer::loadNodeConfig(pnh, &node).find("control_rate"), std::string::npos);
  pnh.deleteParam("control_rate");
  pnh.setParam("autostart", "yes");  // wrong type must not fall back to a default
  node = ros_layer::TrackingNodeConfig();
  EXPECT_NE(ros_layer::loadNodeConfig(pnh, &node).find("autostart"), std::string::npos);
  pnh.deleteParam("autostart");

  core::ControllerConfig controller;
  pnh.setParam("v_max", 0.9);  // above the robot's diamond
  node = ros_layer::TrackingNodeConfig();
  node.description.v_max = 0.5;
  EXPECT_NE(ros_layer::loadControllerConfig(pnh, node, &controller).find("v_max: must be <= the robot's v_max 0.5"),
            std::string::npos);
  pnh.setParam("v_max", 0.3);
  pnh.setParam("estimator/rho_o", -1.0);
  controller = core::ControllerConfig();
  EXPECT_NE(ros_layer::loadControllerConfig(pnh, node, &controller).find("rho_o"), std::string::npos);
  pnh.deleteParam("estimator");
  // Table 1's band (16 mm) at 20 Hz and 5 m/s: p_r moves up to 25 cm per period.
  node.description.v_max = node.description.w_max = node.description.dynamics.max_velocity = 5.0;
  pnh.setParam("v_max", 5.0);
  pnh.setParam("w_max", 5.0);
  pnh.setParam("delta", 0.016);
  controller = core::ControllerConfig();
  const std::string band = ros_layer::loadControllerConfig(pnh, node, &controller);
  EXPECT_NE(band.find("delta = 0.016"), std::string::npos) << band;
  EXPECT_NE(band.find("control_rate = 20"), std::string::npos) << band;
  for (const char* key : {"v_max", "w_max", "delta"}) pnh.deleteParam(key);
  node = ros_layer::TrackingNodeConfig();
  node.description.v_max = 0.5;

  core::ScanObstacleConfig scan;
  pnh.setParam("scan/max_disk_radius", 0.0);
  EXPECT_NE(ros_layer::loadScanObstacleConfig(pnh, &scan).find("max_disk_radius"), std::string::npos);

  // Geometry from a URDF found by searching up from ~ (here ~bad/robot_description);
  // parameters override it.
  pnh.setParam("robot_description", std::string(R"(<robot name="r">
    <link name="base_link"><collision><geometry><box size="0.32 0.24 0.2"/></geometry></collision></link>
    <link name="control_point"/>
    <joint name="cp" type="fixed"><parent link="base_link"/><child link="control_point"/>
      <origin xyz="0.25 0 0"/></joint></robot>)"));
  controller = core::ControllerConfig();
  ASSERT_EQ(ros_layer::loadControllerConfig(pnh, node, &controller), "");
  EXPECT_DOUBLE_EQ(controller.robot_radius, 0.2);  // half diagonal of 0.32 x 0.24
  EXPECT_DOUBLE_EQ(controller.offset, 0.25);
  pnh.setParam("offset", 0.35);
  ASSERT_EQ(ros_layer::loadControllerConfig(pnh, node, &controller), "");
  EXPECT_DOUBLE_EQ(controller.offset, 0.35);
  pnh.setParam("robot_description", std::string("<robot"));
  EXPECT_NE(ros_layer::loadControllerConfig(pnh, node, &controller).find("robot_description"), std::string::npos);
  pnh.deleteParam("robot_description");

  std::vector<core::VirtualObstacle> list;
  XmlRpc::XmlRpcValue entries;
  entries[0]["id"] = "a";
  entries[0]["center"][0] = 1.0;
  entries[0]["center"][1] = 2.0;
  entries[0]["radius"] = 0.2;
  entries[1]["id"] = "b";
  entries[1]["center"][0] = 1.0;  // missing y
  entries[1]["radius"] = 0.2;
  pnh.setParam("virtual_obstacles", entries);
  const std::string error = ros_layer::loadVirtualObstacles(pnh, &list);
  EXPECT_NE(error.find("entry 1"), std::string::npos) << error;
  EXPECT_NE(error.find("center"), std::string::npos) << error;
}

// config/tracking.yaml and config/virtual_obstacles.yaml load without error (YAML 1.1 has
// traps: 1.0e9 is a string) and give what they say.
TEST(TrackingParams, ShippedConfigLoads) {
  ros::NodeHandle shipped("/shipped");
  ros_layer::TrackingNodeConfig node;
  core::ControllerConfig controller;
  core::ScanObstacleConfig scan;
  std::vector<core::VirtualObstacle> list;
  ASSERT_TRUE(shipped.hasParam("control_rate"));
  EXPECT_EQ(ros_layer::loadNodeConfig(shipped, &node), "");
  EXPECT_EQ(ros_layer::loadControllerConfig(shipped, node, &controller), "");
  EXPECT_EQ(ros_layer::loadScanObstacleConfig(shipped, &scan), "");
  EXPECT_EQ(ros_layer::loadVirtualObstacles(shipped, &list), "");
  EXPECT_FALSE(node.autostart);
  EXPECT_GT(scan.max_range, 1e6);
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0].id, "box");
  EXPECT_DOUBLE_EQ(controller.k_d, 0.15);  // controller_experiment.yaml: Section 5.3
  EXPECT_DOUBLE_EQ(controller.v_max, 0.3);
}

// config/controller_sim.yaml (Table 1) loads over tracking.yaml and gives Table 1's values.
TEST(TrackingParams, ShippedSimControllerLoads) {
  ros::NodeHandle shipped("/shipped_sim");
  ros_layer::TrackingNodeConfig node;
  core::ControllerConfig controller;
  ASSERT_TRUE(shipped.hasParam("k_d"));
  EXPECT_EQ(ros_layer::loadNodeConfig(shipped, &node), "");
  // Refused on the AmigoBot's file (Table 1's diamond is 17x wider); loads on a robot file that holds it.
  EXPECT_NE(ros_layer::loadControllerConfig(shipped, node, &controller).find("v_max: must be <= the robot's v_max 0.3"),
            std::string::npos);
  node.description.v_max = node.description.w_max = node.description.dynamics.max_velocity = 5.0;
  controller = core::ControllerConfig();
  EXPECT_EQ(ros_layer::loadControllerConfig(shipped, node, &controller), "");
  EXPECT_DOUBLE_EQ(controller.k_d, 3.0);
  EXPECT_DOUBLE_EQ(controller.v_max, 5.0);
  EXPECT_DOUBLE_EQ(controller.delta, 0.4);  // Table 1's 0.016 m is crossed in one 20 Hz period (1.5x jitter)
  EXPECT_DOUBLE_EQ(controller.rho_0, 1.84);
}

// The robot's limits live in its robot file: tracking's diamond defaults to it, a smaller
// file's diamond is the ceiling, and the old ~robot_v_max is refused naming the file.
TEST(TrackingParams, TheRobotFilesDiamondIsTrackingsDefaultAndCeiling) {
  ros::NodeHandle pnh("~robot_file");
  const std::string file = "/tmp/amigobot_tracking_slow_" + std::to_string(::getpid()) + ".yaml";
  std::ofstream(file) << "v_max: 0.2\nw_max: 0.5\n";
  pnh.setParam("robot_params", file);
  ros_layer::TrackingNodeConfig node;
  ASSERT_EQ(ros_layer::loadNodeConfig(pnh, &node), "");
  core::ControllerConfig controller;
  ASSERT_EQ(ros_layer::loadControllerConfig(pnh, node, &controller), "");
  EXPECT_DOUBLE_EQ(controller.v_max, 0.2);
  EXPECT_DOUBLE_EQ(controller.w_max, 0.5);
  pnh.setParam("v_max", 0.3);  // the old default: wider than this robot's diamond
  controller = core::ControllerConfig();
  EXPECT_EQ(ros_layer::loadControllerConfig(pnh, node, &controller),
            "parameter ~v_max: must be <= the robot's v_max 0.2 m/s (" + file + "), got 0.3");
  pnh.setParam("robot_v_max", 1.0);
  node = ros_layer::TrackingNodeConfig();
  const std::string retired = ros_layer::loadNodeConfig(pnh, &node);
  EXPECT_NE(retired.find("~robot_v_max: no longer a parameter"), std::string::npos) << retired;
  EXPECT_NE(retired.find(file), std::string::npos) << retired;
  for (const char* key : {"robot_params", "v_max", "robot_v_max"}) pnh.deleteParam(key);
  std::remove(file.c_str());
}

}  // namespace tracking_param_loading_test

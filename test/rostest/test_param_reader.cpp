// rostest: the ROS parameter reader over the controller table: an int is accepted for a
// real, a wrong type and a bound violation are errors naming the parameter, nested keys are
// namespaces, and unset parameters keep the struct's defaults.
#include <gtest/gtest.h>

#include <ros/ros.h>

#include "amigobot_tracking/core/obstacle_tracker.h"
#include "amigobot_tracking/ros/param_reader.h"
#include "amigobot_tracking/ros/tracking_params.h"

using namespace amigobot_tracking;

namespace {

// A fresh private namespace per case, so the cases do not see each other's parameters.
ros::NodeHandle freshNamespace(const std::string& name) {
  ros::NodeHandle pnh("~" + name);
  pnh.deleteParam("");
  return pnh;
}

}  // namespace

TEST(ParamReader, IntegerForARealAndNestedNamespaces) {
  ros::NodeHandle pnh = freshNamespace("ints");
  pnh.setParam("k_d", 2);
  pnh.setParam("estimator/a1", 3.5);
  pnh.setParam("body_safe", false);
  core::ControllerConfig c;
  EXPECT_EQ(ros_layer::readParams(pnh, core::controllerFields(), &c), "");
  EXPECT_EQ(c.k_d, 2.0);
  EXPECT_EQ(c.estimator.a1, 3.5);
  EXPECT_FALSE(c.body_safe);
  EXPECT_EQ(c.k_o, core::ControllerConfig().k_o) << "unset: the default";
}

TEST(ParamReader, WrongTypeIsAnErrorNamingTheParameter) {
  ros::NodeHandle pnh = freshNamespace("types");
  pnh.setParam("k_d", std::string("fast"));
  core::ControllerConfig c;
  EXPECT_EQ(ros_layer::readParams(pnh, core::controllerFields(), &c), "~k_d: must be a number, got a string");
  pnh.deleteParam("k_d");
  pnh.setParam("body_safe", 1);
  EXPECT_EQ(ros_layer::readParams(pnh, core::controllerFields(), &c), "~body_safe: must be true or false, got an integer");
  ros::NodeHandle tracker = freshNamespace("tracker");
  tracker.setParam("obstacle_tracker/min_hits", 2.5);
  core::ObstacleTrackerConfig t;
  EXPECT_EQ(ros_layer::readParams(tracker, core::obstacleTrackerFields(), &t, "obstacle_tracker/"),
            "~obstacle_tracker/min_hits: must be an integer, got a number");
}

TEST(ParamReader, BoundsAndCrossFieldRulesNameTheParameter) {
  ros::NodeHandle pnh = freshNamespace("bounds");
  pnh.setParam("k_d", -1);
  core::ControllerConfig c;
  EXPECT_EQ(ros_layer::readParams(pnh, core::controllerFields(), &c), "~k_d: must be a finite number > 0, got -1");
  pnh.deleteParam("k_d");
  pnh.setParam("rho_0", 0.05);
  const std::string error = ros_layer::readParams(pnh, core::controllerFields(), &c);
  EXPECT_EQ(error.rfind("~rho_0: must be > rho_inf", 0), 0u) << error;
  ros::NodeHandle node = freshNamespace("node");
  node.setParam("control_rate", 0.0);
  ros_layer::TrackingNodeConfig n;
  EXPECT_EQ(ros_layer::loadNodeConfig(node, &n), "~control_rate: must be a finite number in (0, 1000], got 0");
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_param_reader");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}

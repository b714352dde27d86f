// rostest: the ROS parameter reader over the controller table: an int is accepted for a
// real, a wrong type and a bound violation are errors naming the parameter, nested keys are
// namespaces, and unset parameters keep the struct's defaults; RosAria's names are aliases of
// the driver's; a parameter no reader asks for is warned on /rosout with the nearest key.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>

#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>

#include "amigobot_tracking/core/obstacle_tracker.h"
#include "amigobot_tracking/ros/driver.h"
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
  EXPECT_EQ(ros_layer::loadNodeConfig(node, &n), "~control_rate: must be a finite number in [1, 1000], got 0");
}

TEST(ParamReader, RosAriaNamesAreAliasesOfTheDriversOwn) {
  ros::NodeHandle pnh = freshNamespace("rosaria");
  pnh.setParam("TicksMM", 130);
  pnh.setParam("DriftFactor", -20);
  pnh.setParam("RevCount", 32000);
  pnh.setParam("base_link_frame", std::string("r1/base_link"));
  pnh.setParam("odom_frame", std::string("r1/odom"));
  const ros_layer::DriverParams p = ros_layer::loadDriverParams(pnh);
  EXPECT_EQ(p.client.ticks_mm, 130);
  EXPECT_EQ(p.client.drift_factor, -20);
  EXPECT_EQ(p.client.rev_count, 32000);
  EXPECT_EQ(p.base_frame, "r1/base_link");
  EXPECT_EQ(p.odom_frame, "r1/odom");
  EXPECT_TRUE(ros_layer::unknownParams(pnh).empty()) << "an alias read is a known key";

  ros::NodeHandle both = freshNamespace("both");
  both.setParam("ticks_mm", 120);
  both.setParam("TicksMM", 130);
  EXPECT_EQ(ros_layer::loadDriverParams(both).client.ticks_mm, 120) << "the driver's own name wins";

  ros::NodeHandle bad = freshNamespace("bad_alias");
  bad.setParam("RevCount", std::string("many"));
  try {
    ros_layer::loadDriverParams(bad);
    ADD_FAILURE() << "a string RevCount was accepted";
  } catch (const std::exception& e) {
    EXPECT_STREQ(e.what(), "~RevCount: must be an integer, got a string");
  }
  bad.setParam("RevCount", 70000);
  try {
    ros_layer::loadDriverParams(bad);
    ADD_FAILURE() << "RevCount 70000 was accepted";
  } catch (const std::exception& e) {
    EXPECT_EQ(std::string(e.what()).rfind("~RevCount: must be in [0, 65535]", 0), 0u) << e.what();
  }
}

TEST(ParamReader, UnknownParametersAreWarnedByNameWithTheNearestKey) {
  std::mutex mutex;
  std::vector<std::string> warnings;
  ros::NodeHandle nh;
  ros::Subscriber rosout = nh.subscribe<rosgraph_msgs::Log>("/rosout", 100, [&](const rosgraph_msgs::Log::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex);
    if (m->level == rosgraph_msgs::Log::WARN) warnings.push_back(m->msg);
  });
  ros::NodeHandle pnh = freshNamespace("typos");
  pnh.setParam("k_d", 2.0);
  pnh.setParam("k_dd", 3.0);
  pnh.setParam("enable_button", 5);
  pnh.setParam("estimator/a1", 3.5);
  core::ControllerConfig c;
  ASSERT_EQ(ros_layer::readParams(pnh, core::controllerFields(), &c), "");
  const std::vector<core::UnknownKey> unknown = ros_layer::unknownParams(pnh);
  ASSERT_EQ(unknown.size(), 2u);
  EXPECT_EQ(unknown[0].key, "enable_button");
  EXPECT_EQ(unknown[0].nearest, "");
  EXPECT_EQ(unknown[1].key, "k_dd");
  EXPECT_EQ(unknown[1].nearest, "k_d");
  // The start-up warning, about a second after the first read.
  const std::string ns = pnh.getNamespace();
  const std::string expected = "~k_dd (" + ns + "/k_dd) is not a parameter of " + ns;
  bool seen_typo = false, seen_button = false;
  for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(5.0); ros::WallTime::now() < end;) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      for (const std::string& w : warnings) {
        seen_typo = seen_typo || (w.rfind(expected, 0) == 0 && w.find("did you mean ~k_d?") != std::string::npos);
        seen_button = seen_button || w.rfind("~enable_button (", 0) == 0;
      }
    }
    if (seen_typo && seen_button) break;
    ros::WallDuration(0.05).sleep();
  }
  EXPECT_TRUE(seen_typo) << "no warning '" << expected << "...; did you mean ~k_d?'";
  EXPECT_TRUE(seen_button);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_param_reader");
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(1);  // the unknown-parameter check's timer and the /rosout subscriber
  spinner.start();
  return RUN_ALL_TESTS();
}

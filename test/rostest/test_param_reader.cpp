// rostest: the ROS parameter reader over the controller table: an int is accepted for a
// real, a wrong type and a bound violation are errors naming the parameter, nested keys are
// namespaces, and unset parameters keep the struct's defaults; RosAria's names are aliases of
// the driver's; a parameter no reader asks for is warned on /rosout with the nearest key. A
// lab's urg_node, rplidar_ros, sick_tim, amcl and slam_toolbox configs (lab_configs.yaml,
// loaded by param_reader.test) are read through their aliases, each with an INFO line.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>

#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>

#include "amigobot_tracking/core/perception/obstacle_tracker.h"
#include "amigobot_tracking/ros/driver.h"
#include "amigobot_tracking/ros/laser_scan.h"
#include "amigobot_tracking/ros/localization_node.h"
#include "amigobot_tracking/ros/param_reader.h"
#include "amigobot_tracking/ros/tracking_params.h"

namespace param_reader_test {

using namespace amigobot_tracking;

namespace {

// A fresh private namespace per case, so the cases do not see each other's parameters.
ros::NodeHandle freshNamespace(const std::string& name) {
  ros::NodeHandle pnh("~" + name);
  pnh.deleteParam("");
  return pnh;
}

// The /rosout lines of one level, from the test's start.
class RosoutLines {
 public:
  explicit RosoutLines(std::uint8_t level) {
    sub_ = ros::NodeHandle().subscribe<rosgraph_msgs::Log>("/rosout", 200, [this, level](const rosgraph_msgs::Log::ConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (m->level == level) lines_.push_back(m->msg);
    });
    // Lines logged before /rosout reaches the subscriber would be missed.
    for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(5.0);
         sub_.getNumPublishers() == 0 && ros::WallTime::now() < end;)
      ros::WallDuration(0.02).sleep();
  }
  // Waits up to 5 s for a line containing `text`.
  bool saw(const std::string& text) {
    for (const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(5.0); ros::WallTime::now() < end;) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const std::string& line : lines_)
          if (line.find(text) != std::string::npos) return true;
      }
      ros::WallDuration(0.05).sleep();
    }
    return false;
  }

 private:
  std::mutex mutex_;
  std::vector<std::string> lines_;
  ros::Subscriber sub_;
};

std::vector<std::string> unknownKeys(const ros::NodeHandle& pnh) {
  std::vector<std::string> keys;
  for (const core::UnknownKey& u : ros_layer::unknownParams(pnh)) keys.push_back(u.key);
  return keys;
}

using Keys = std::vector<std::string>;

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

TEST(LabConfigs, UrgNodeNamesAreTheLasersOwn) {
  RosoutLines info(rosgraph_msgs::Log::INFO);
  const ros::NodeHandle ethernet("/lab_configs/urg_node");
  const ros_layer::LaserParams p = ros_layer::loadLaserParams(ethernet);
  EXPECT_EQ(p.driver.port, "192.168.0.10:10940") << "ip_address + ip_port";
  EXPECT_EQ(p.frame_id, "hokuyo_link");
  EXPECT_DOUBLE_EQ(p.angle_min, -1.5707963);
  EXPECT_DOUBLE_EQ(p.time_offset, 0.02);
  EXPECT_EQ(unknownKeys(ethernet), (Keys{"calibrate_time", "publish_intensity"})) << "not carried: warned";
  EXPECT_TRUE(info.saw("/lab_configs/urg_node/port = 192.168.0.10:10940 (from urg_node's ~ip_address and ~ip_port)"));
  const ros::NodeHandle serial("/lab_configs/urg_node_serial");
  EXPECT_EQ(ros_layer::loadLaserParams(serial).driver.port, "/dev/ttyACM1");
  EXPECT_TRUE(info.saw("~serial_port read as ~port (its name in urg_node and rplidar_ros)"));
  EXPECT_EQ(unknownKeys(serial), (Keys{"serial_baud"}));
}

TEST(LabConfigs, RplidarRosAndSickTimNamesAreTheLasersOwn) {
  const ros::NodeHandle rplidar("/lab_configs/rplidar_ros");
  const ros_layer::LaserParams r = ros_layer::loadLaserParams(rplidar);
  EXPECT_EQ(r.driver.port, "/dev/ttyUSB1");
  EXPECT_EQ(r.driver.baud, 256000);
  EXPECT_TRUE(r.upside_down) << "inverted";
  EXPECT_EQ(unknownKeys(rplidar), (Keys{"angle_compensate"}));
  const ros::NodeHandle sick("/lab_configs/sick_tim");
  const ros_layer::LaserParams t = ros_layer::loadLaserParams(sick);
  EXPECT_EQ(t.driver.port, "192.168.0.71:2112") << "hostname + sick_tim's port";
  EXPECT_DOUBLE_EQ(t.angle_min, -2.0);
  EXPECT_DOUBLE_EQ(t.angle_max, 2.0);
  EXPECT_DOUBLE_EQ(t.range_min, 0.05);
  EXPECT_TRUE(unknownKeys(sick).empty());
}

TEST(LabConfigs, AmclAndSlamToolboxNamesAreTheLocalisationsOwn) {
  const ros::NodeHandle amcl("/lab_configs/amcl");
  const localization::LocalizationConfig a = ros_layer::loadLocalizationConfig(amcl);
  EXPECT_TRUE(a.use_map_topic);
  EXPECT_DOUBLE_EQ(a.initial_pose.x, 1.5);
  EXPECT_DOUBLE_EQ(a.initial_pose.y, -0.5);
  EXPECT_DOUBLE_EQ(a.initial_pose.theta, 0.3);
  EXPECT_EQ(a.global_frame, "world");
  EXPECT_EQ(a.odom_frame, "r1/odom");
  EXPECT_EQ(a.base_frame, "r1/base_footprint");
  EXPECT_DOUBLE_EQ(a.min_travel, 0.2);
  EXPECT_DOUBLE_EQ(a.min_rotation, 0.5236);
  EXPECT_DOUBLE_EQ(a.transform_tolerance, 0.2);
  EXPECT_EQ(unknownKeys(amcl), (Keys{"laser_max_range"}));
  const ros::NodeHandle slam("/lab_configs/slam_toolbox");
  const localization::LocalizationConfig m = ros_layer::loadLocalizationConfig(slam);
  EXPECT_EQ(m.mode, "mapping");
  EXPECT_EQ(m.global_frame, "slam_map");
  EXPECT_EQ(m.base_frame, "base_link");
  EXPECT_DOUBLE_EQ(m.resolution, 0.04);
  EXPECT_DOUBLE_EQ(m.map_publish_period, 5.0);
  EXPECT_DOUBLE_EQ(m.range_max, 12.0);
  EXPECT_DOUBLE_EQ(m.min_travel, 0.5);
  EXPECT_DOUBLE_EQ(m.min_rotation, 0.4);
  EXPECT_EQ(unknownKeys(slam), (Keys{"scan_topic"}));
}

TEST(LabConfigs, OurOwnNameWinsOverAnAliasAndTheAliasIsWarned) {
  RosoutLines warn(rosgraph_msgs::Log::WARN);
  ros::NodeHandle laser = freshNamespace("both_laser");
  laser.setParam("port", std::string("/dev/ttyACM0"));
  laser.setParam("serial_port", std::string("/dev/ttyACM1"));
  laser.setParam("ip_address", std::string("192.168.0.10"));
  EXPECT_EQ(ros_layer::loadLaserParams(laser).driver.port, "/dev/ttyACM0");
  EXPECT_TRUE(warn.saw("~serial_port (~port's name in urg_node and rplidar_ros) ignored: ~port is set too"));
  EXPECT_TRUE(warn.saw("~ip_address (urg_node's ~ip_address and ~ip_port) ignored: ~port is set too"));
  ros::NodeHandle loc = freshNamespace("both_localization");
  loc.setParam("map_file", std::string("/tmp/none.yaml"));
  loc.setParam("mode", std::string("mapping"));
  loc.setParam("initial_pose/x", 2.0);
  loc.setParam("initial_pose_x", 3.0);
  EXPECT_DOUBLE_EQ(ros_layer::loadLocalizationConfig(loc).initial_pose.x, 2.0);
  EXPECT_TRUE(warn.saw("~initial_pose_x (~initial_pose/x's name in amcl) ignored: ~initial_pose/x is set too"));
  ros::NodeHandle bad = freshNamespace("bad_laser_alias");
  bad.setParam("model", std::string("rplidar"));
  bad.setParam("serial_baudrate", 9600);
  try {
    ros_layer::loadLaserParams(bad);
    ADD_FAILURE() << "serial_baudrate 9600 was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("baud: rplidar runs at 115200 or 256000, got 9600"), std::string::npos) << e.what();
  }
}

}  // namespace param_reader_test

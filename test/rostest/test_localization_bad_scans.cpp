// rostest, issue 24 item 4: bad LaserScans at the Localization nodelet's scan topic (mapping
// mode on the synthetic room): angle_increment 0, NaN angle_min, range_min > range_max, only
// NaN ranges, 100,000 ranges under a 360-beam header. Each is refused by an ERROR naming the
// field; the nodelet stays up, map -> odom stays finite and keeps coming, and good scans
// are matched again afterwards (map -> odom still published).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <nodelet/loader.h>
#include <rosgraph_msgs/Log.h>
#include <tf2_msgs/TFMessage.h>

#include "one_turn_scan.h"
#include "rosout_log.h"
#include "synthetic_robot.h"

namespace localization_bad_scans_test {

using namespace amigobot_test;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

}  // namespace

TEST(LocalizationBadScans, RefusedByNameAndThePoseStaysFinite) {
  ros::NodeHandle nh;
  std::atomic<int> map_to_odom{0}, not_finite{0};
  ros::Subscriber tf_sub = nh.subscribe<tf2_msgs::TFMessage>("/tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr& msg) {
    for (const auto& t : msg->transforms) {
      if (t.header.frame_id != "map") continue;
      ++map_to_odom;
      const auto& p = t.transform;
      not_finite += !(std::isfinite(p.translation.x) && std::isfinite(p.translation.y) && std::isfinite(p.rotation.z) &&
                      std::isfinite(p.rotation.w));
    }
  });
  e2e::RosoutLog errors(nh, rosgraph_msgs::Log::ERROR);
  ASSERT_TRUE(errors.connected(1, 10.0));
  ros::param::set("/localization/mode", "mapping");
  ros::param::set("/localization/initial_pose/x", kLoopStart.x);
  ros::param::set("/localization/initial_pose/y", kLoopStart.y);
  ros::param::set("/localization/initial_pose/yaw", kLoopStart.theta);
  SyntheticRobot robot(kLoopStart, Pose2{});
  nodelet::Loader loader(false);
  ASSERT_TRUE(loader.load("/localization", "amigobot_tracking/Localization", {}, {}));
  const ros::WallTime started = ros::WallTime::now();
  while (map_to_odom == 0 && (ros::WallTime::now() - started).toSec() < 20.0) ros::WallDuration(0.05).sleep();
  ASSERT_GT(map_to_odom.load(), 0) << "the nodelet never published map -> odom";

  ros::Publisher scans = nh.advertise<sensor_msgs::LaserScan>("scan", 5);
  struct Bad {
    std::function<void(sensor_msgs::LaserScan&)> spoil;
    std::string field;
  };
  const std::vector<Bad> bad = {
      {[](sensor_msgs::LaserScan& s) { s.angle_increment = 0.0f; }, "angle_increment:"},
      {[](sensor_msgs::LaserScan& s) { s.angle_min = kNaN; }, "angle_min:"},
      {[](sensor_msgs::LaserScan& s) { s.range_min = 10.0f; }, "range_max:"},
      {[](sensor_msgs::LaserScan& s) { s.ranges.assign(360, kNaN); }, "(360 NaN"},
      {[](sensor_msgs::LaserScan& s) { s.ranges.assign(100000, 2.0f); }, "ranges: 100000 beams"},
  };
  robot.scans(false);  // the test is the only scan source while it sends bad ones
  for (const Bad& b : bad) {
    const std::size_t since = errors.count();
    sensor_msgs::LaserScan s = oneTurnScan(2.0f);  // walls 2 m around
    b.spoil(s);
    for (int i = 0; i < 10; ++i) {  // 1 s at 10 Hz
      s.header.stamp = ros::Time::now();
      scans.publish(s);
      ros::WallDuration(0.1).sleep();
    }
    EXPECT_TRUE(errors.waitForMentionOfAll({"localization: scan refused", b.field}, 2.0, since))
        << "no ERROR naming '" << b.field << "'";
  }
  robot.scans(true);
  const int before = map_to_odom;
  ros::WallDuration(2.0).sleep();
  EXPECT_GT(map_to_odom - before, 10) << "map -> odom no longer published after the bad scans";
  EXPECT_EQ(not_finite.load(), 0) << "a map -> odom that is not finite";
  EXPECT_TRUE(loader.unload("/localization"));
}

}  // namespace localization_bad_scans_test

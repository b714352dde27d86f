// rostest: with a bad parameter (tracking_bad_param.test: k_d < 0 and autostart true) the
// nodelet starts nothing: no enable service, no state, no command, even with fresh tf.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include "amigobot_tracking/TrackingState.h"

namespace tracking_bad_param_test {

namespace {

geometry_msgs::TransformStamped transform(const std::string& child, double x) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time::now();
  t.header.frame_id = "map";
  t.child_frame_id = child;
  t.transform.translation.x = x;
  t.transform.rotation.w = 1.0;
  return t;
}

}  // namespace

TEST(TrackingBadParam, NothingStartsAndNothingMoves) {
  ros::NodeHandle nh;
  std::atomic<int> commands{0}, states{0};
  ros::Subscriber cmd = nh.subscribe<geometry_msgs::Twist>("cmd_vel", 10, [&](const geometry_msgs::Twist::ConstPtr&) { ++commands; });
  ros::Subscriber state = nh.subscribe<amigobot_tracking::TrackingState>(
      "tracking/state", 10, [&](const amigobot_tracking::TrackingState::ConstPtr&) { ++states; });
  // The nodelet is loaded once the manager answers its load call; give it ample time.
  ASSERT_TRUE(ros::service::waitForService("manager/list", ros::Duration(30.0)));
  tf2_ros::TransformBroadcaster tf;
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(8.0);
  while (ros::WallTime::now() < end) {  // fresh robot and target: everything but the parameter is fine
    tf.sendTransform(transform("base_link", 0.0));
    tf.sendTransform(transform("target", 2.0));
    ros::WallDuration(0.05).sleep();
  }
  EXPECT_FALSE(ros::service::exists("tracking/enable", false));
  EXPECT_EQ(commands.load(), 0);
  EXPECT_EQ(states.load(), 0);
}

}  // namespace tracking_bad_param_test

// ground_truth_localization: asks the emulator's status socket for the true pose of the
// robot and broadcasts map -> odom so that map -> base_link is that pose (REP 105), and
// publishes the true pose as `ground_truth` (nav_msgs/Odometry in map) for recording, and
// beside it `ground_truth_clock` (sensor_msgs/TimeReference, same stamp): the emulator's
// clock at that ROS time, on which the world file's people move (world/world.h), so sim_laser,
// world_markers and run_report place a person where the emulators see it.
// With publish_tf false it only publishes `ground_truth`: the judge of a run that localises
// itself (sim.launch localization:=map|slam).
// When the socket goes away it says so, stops broadcasting (consumers see the pose age
// and stop the robot) and reconnects every reconnect_period (aria::StatusClient).
// Parameters: ros/ground_truth.h (GroundTruthConfig).
#include <algorithm>
#include <optional>

#include <nav_msgs/Odometry.h>
#include <sensor_msgs/TimeReference.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "amigobot_tracking/aria/emulator_status.h"
#include "amigobot_tracking/ros/conversions.h"
#include "amigobot_tracking/ros/ground_truth.h"
#include "amigobot_tracking/ros/master_watch.h"
#include "amigobot_tracking/ros/node_command_line.h"

using namespace amigobot_tracking;

const ros_layer::NodeHelp kHelp{
    "Broadcasts map -> odom from the emulator's ground truth (status socket) and "
    "publishes it as `ground_truth`.",
    "include/amigobot_tracking/ros/ground_truth.h (GroundTruthConfig)."};

int main(int argc, char** argv) {
  ros_layer::initNode(argc, argv, "ground_truth_localization", kHelp);
  ros::NodeHandle nh, pnh("~");
  // A restarted master learns this node's topics again, as the nodelets' (ros/master_watch.h).
  const auto master_watch = ros_layer::MasterWatch::shared();
  ros_layer::GroundTruthConfig config;
  const std::string error = ros_layer::loadGroundTruthConfig(pnh, &config);
  if (!ros_layer::configLoaded("ground_truth_localization", error)) return 1;
  tf2_ros::Buffer tf;
  tf2_ros::TransformListener listener(tf);
  tf2_ros::TransformBroadcaster broadcaster;
  ros::Publisher truth_pub = nh.advertise<nav_msgs::Odometry>("ground_truth", 10);
  ros::Publisher clock_pub = nh.advertise<sensor_msgs::TimeReference>("ground_truth_clock", 10);
  aria::StatusClient client(config.host, config.port, config.socket_timeout, config.reconnect_period);

  ros::Rate rate(config.rate);
  bool was_up = false;
  ros_layer::TruthPairing pairing;
  std::optional<core::Pose2> correction;  // the last map -> odom
  while (ros::ok()) {
    rate.sleep();
    aria::EmulatorStatus status;
    const std::string problem = client.query(&status);
    if (!problem.empty()) {
      if (was_up) ROS_ERROR_STREAM("ground_truth_localization: lost the emulator: " << problem << "; map -> odom stops");
      else ROS_ERROR_STREAM_THROTTLE(10.0, "ground_truth_localization: " << problem << " (retrying every "
                                                                          << config.reconnect_period << " s)");
      was_up = false;
      correction.reset();  // a restarted emulator or driver is paired afresh before anything is broadcast
      continue;
    }
    if (!was_up) ROS_INFO_STREAM("ground_truth_localization: connected to " << config.host << ":" << config.port);
    was_up = true;
    const ros::Time now = ros::Time::now();
    sensor_msgs::TimeReference clock;  // first: a reader pairing by stamp has it before the pose
    clock.header.stamp = now;
    clock.time_ref = ros::Time(std::max(0.0, status.t));
    clock.source = "amigobot_emulator";
    clock_pub.publish(clock);
    nav_msgs::Odometry truth;
    truth.header.stamp = now;
    truth.header.frame_id = config.global_frame;
    truth.child_frame_id = config.base_frame;
    truth.pose.pose.position.x = status.pose.x;
    truth.pose.pose.position.y = status.pose.y;
    truth.pose.pose.orientation = ros_layer::toQuaternion(status.pose.theta);
    truth.twist.twist.linear.x = status.v;
    truth.twist.twist.angular.z = status.w;
    truth_pub.publish(truth);
    if (!config.publish_tf) continue;

    // Paired with the odometry of the same instant (ros/ground_truth.h, TruthPairing); between
    // pairs the last correction is broadcast again, freshly stamped.
    pairing.add(now.toSec(), status.pose);
    const std::optional<core::Pose2> paired = pairing.correction([&](double stamp, core::Pose2* odom_base) {
      try {
        *odom_base = ros_layer::toPose2(
            tf.lookupTransform(config.odom_frame, config.base_frame, ros::Time().fromSec(stamp)).transform);
        return true;
      } catch (const tf2::TransformException&) {
        return false;  // odometry does not reach the stamp yet (or no more)
      }
    });
    if (paired) correction = paired;
    if (!correction) {
      ROS_WARN_THROTTLE(5.0, "ground_truth_localization: no %s -> %s from the driver at the truth's time yet",
                        config.odom_frame.c_str(), config.base_frame.c_str());
      continue;
    }
    broadcaster.sendTransform(ros_layer::toTransform(config.global_frame, config.odom_frame, *correction,
                                                     now + ros::Duration(config.transform_tolerance)));
  }
  return 0;
}

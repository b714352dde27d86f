// trail_publisher: the recent path of one tf frame in global_frame as nav_msgs/Path on
// `trail`, for rviz (robot and target trails). Parameters (private): frame (base_link),
// global_frame (map), rate [Hz] (5), min_distance [m] (0.02), max_poses (3000).
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "amigobot_tracking/ros/param_reader.h"
#include "amigobot_tracking/ros/trail.h"
#include "amigobot_tracking/ros/master_watch.h"
#include "amigobot_tracking/ros/node_command_line.h"

using namespace amigobot_tracking;

const ros_layer::NodeHelp kHelp{
    "The recent path of one tf frame in global_frame as nav_msgs/Path on `trail`, for rviz.",
    "frame (base_link), global_frame (map), rate [Hz] (5), min_distance [m] (0.02), max_poses (3000)."};

int main(int argc, char** argv) {
  ros_layer::initNode(argc, argv, "trail_publisher", kHelp);
  ros::NodeHandle nh, pnh("~");
  // A restarted master learns this node's topics again, as the nodelets' (ros/master_watch.h).
  const auto master_watch = ros_layer::MasterWatch::shared();
  ros_layer::TrailNodeConfig params;
  const std::string error = ros_layer::readParams(pnh, ros_layer::trailNodeFields(), &params);
  if (!ros_layer::configLoaded("trail_publisher", error)) return 1;
  const std::string &frame = params.frame, &global_frame = params.global_frame;
  const ros_layer::TrailConfig& config = params.trail;
  const double rate = params.rate;
  tf2_ros::Buffer tf;
  tf2_ros::TransformListener listener(tf);
  ros::Publisher pub = nh.advertise<nav_msgs::Path>("trail", 1, true);
  nav_msgs::Path path;
  path.header.frame_id = global_frame;
  ros::Rate r(rate);
  while (ros::ok()) {
    r.sleep();
    geometry_msgs::TransformStamped t;
    try {
      t = tf.lookupTransform(global_frame, frame, ros::Time(0));
    } catch (const tf2::TransformException& e) {
      ROS_WARN_THROTTLE(10.0, "trail_publisher: no %s in %s yet: %s", frame.c_str(), global_frame.c_str(), e.what());
      continue;
    }
    geometry_msgs::PoseStamped pose;
    pose.header = t.header;
    pose.pose.position.x = t.transform.translation.x;
    pose.pose.position.y = t.transform.translation.y;
    pose.pose.position.z = t.transform.translation.z;
    pose.pose.orientation = t.transform.rotation;
    if (!ros_layer::appendToTrail(config, pose, &path)) continue;
    path.header.stamp = t.header.stamp;
    pub.publish(path);
  }
  return 0;
}

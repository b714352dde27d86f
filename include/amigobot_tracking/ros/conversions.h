// Conversions between ROS messages and the core's plain types (REP 103: x forward, yaw
// about z, counter-clockwise).
#pragma once

#include <Eigen/Geometry>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <sensor_msgs/LaserScan.h>

#include "amigobot_tracking/TrackingState.h"
#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/core/perception/scan_obstacles.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace ros_layer {

// Planar pose of a transform: x, y and the yaw of its rotation.
core::Pose2 toPose2(const geometry_msgs::Transform& transform);
// The planar part of a 3-D transform: top-left 2x2 of the rotation (a reflection for a
// laser mounted upside down) and the x, y translation.
Eigen::Affine2d toAffine2d(const geometry_msgs::Transform& transform);
core::ScanGeometry toScanGeometry(const sensor_msgs::LaserScan& scan);
geometry_msgs::Twist toTwist(const core::Twist2& u);
// parent -> child transform placing `pose` (x, y, yaw) in the parent frame.
geometry_msgs::TransformStamped toTransform(const std::string& parent, const std::string& child,
                                            const core::Pose2& pose, const ros::Time& stamp);
// Rotation by `yaw` about z.
geometry_msgs::Quaternion toQuaternion(double yaw);
// Fills the controller part of the state message (the node adds status, ages, flags).
void fillState(const core::ControllerOutput& out, TrackingState* state);

}  // namespace ros_layer
}  // namespace amigobot_tracking

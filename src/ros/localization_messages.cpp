#include "amigobot_tracking/ros/localization_messages.h"

#include <cmath>

#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>

namespace amigobot_tracking {
namespace ros_layer {

namespace {

double yawOf(double x, double y, double z, double w) {
  double roll = 0.0, pitch = 0.0, yaw = 0.0;
  tf2::Matrix3x3(tf2::Quaternion(x, y, z, w)).getRPY(roll, pitch, yaw);
  return yaw;
}

geometry_msgs::Quaternion yawQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(0.5 * yaw);
  q.w = std::cos(0.5 * yaw);
  return q;
}

}  // namespace

localization::RangeScan toRangeScan(const sensor_msgs::LaserScan& scan, const core::Pose2& mount) {
  localization::RangeScan out;
  out.angle_min = scan.angle_min;
  out.angle_increment = scan.angle_increment;
  out.range_min = scan.range_min;
  out.range_max = scan.range_max;
  out.ranges = scan.ranges;
  out.mount = mount;
  out.stamp = scan.header.stamp.toSec();
  return out;
}

core::Pose2 toPose2(const geometry_msgs::Transform& t) {
  return core::Pose2{t.translation.x, t.translation.y, yawOf(t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w)};
}

core::Pose2 toPose2(const geometry_msgs::Pose& p) {
  return core::Pose2{p.position.x, p.position.y, yawOf(p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w)};
}

geometry_msgs::Transform toTransform(const core::Pose2& pose) {
  geometry_msgs::Transform t;
  t.translation.x = pose.x;
  t.translation.y = pose.y;
  t.rotation = yawQuaternion(pose.theta);
  return t;
}

void toOccupancyGrid(const localization::OccupancyMap& map, nav_msgs::OccupancyGrid* out) {
  out->info.resolution = static_cast<float>(map.resolution);
  out->info.width = static_cast<std::uint32_t>(map.width);
  out->info.height = static_cast<std::uint32_t>(map.height);
  out->info.origin = geometry_msgs::Pose();
  out->info.origin.position.x = map.origin_x;
  out->info.origin.position.y = map.origin_y;
  out->info.origin.orientation.w = 1.0;
  out->data.assign(map.cells.begin(), map.cells.end());
}

geometry_msgs::PoseWithCovariance toPoseWithCovariance(const core::Pose2& pose, const Eigen::Matrix3d& covariance) {
  geometry_msgs::PoseWithCovariance out;
  out.pose.position.x = pose.x;
  out.pose.position.y = pose.y;
  out.pose.orientation = yawQuaternion(pose.theta);
  const int index[3] = {0, 1, 5};  // x, y, yaw among (x, y, z, roll, pitch, yaw)
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.covariance[static_cast<std::size_t>(index[r] * 6 + index[c])] = covariance(r, c);
  return out;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

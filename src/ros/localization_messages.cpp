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

std::string fromOccupancyGrid(const nav_msgs::OccupancyGrid& grid, localization::OccupancyMap* out) {
  const nav_msgs::MapMetaData& info = grid.info;
  if (info.width == 0 || info.height == 0) return "empty map (" + std::to_string(info.width) + " x " + std::to_string(info.height) + " cells)";
  if (grid.data.size() != static_cast<std::size_t>(info.width) * info.height)
    return std::to_string(grid.data.size()) + " cells for " + std::to_string(info.width) + " x " + std::to_string(info.height);
  if (!(info.resolution > 0.0f) || !std::isfinite(info.resolution)) return "resolution must be > 0 m, got " + std::to_string(info.resolution);
  const geometry_msgs::Pose& origin = info.origin;
  if (!std::isfinite(origin.position.x) || !std::isfinite(origin.position.y)) return "origin must be finite";
  const double yaw = yawOf(origin.orientation.x, origin.orientation.y, origin.orientation.z, origin.orientation.w);
  if (!std::isfinite(yaw) || std::abs(yaw) > 1e-6) return "a rotated map (origin yaw " + std::to_string(yaw) + " rad) is not supported";
  for (std::int8_t v : grid.data)
    if (v < -1 || v > 100) return "cell value " + std::to_string(v) + " outside -1 .. 100";
  *out = localization::makeMap(info.resolution, origin.position.x, origin.position.y, static_cast<int>(info.width),
                               static_cast<int>(info.height));
  out->cells.assign(grid.data.begin(), grid.data.end());
  return "";
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

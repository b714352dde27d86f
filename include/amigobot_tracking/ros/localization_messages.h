// Conversions between the localisation layer and ROS messages: LaserScan -> RangeScan,
// OccupancyMap -> nav_msgs/OccupancyGrid, tf <-> Pose2, the estimate -> PoseWithCovariance.
#pragma once

#include <string>

#include <Eigen/Core>
#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseWithCovariance.h>
#include <geometry_msgs/Transform.h>
#include <nav_msgs/OccupancyGrid.h>
#include <sensor_msgs/LaserScan.h>

#include "amigobot_tracking/core/support/types.h"
#include "amigobot_tracking/localization/occupancy_map.h"
#include "amigobot_tracking/localization/range_scan.h"

namespace amigobot_tracking {
namespace ros_layer {

// The scan with its mount pose base -> laser (REP 117 ranges kept as they are).
localization::RangeScan toRangeScan(const sensor_msgs::LaserScan& scan, const core::Pose2& mount);
// Planar part of a transform or pose (yaw from the quaternion).
core::Pose2 toPose2(const geometry_msgs::Transform& transform);
core::Pose2 toPose2(const geometry_msgs::Pose& pose);
geometry_msgs::Transform toTransform(const core::Pose2& pose);
// Grid data and metadata; the header is the caller's.
void toOccupancyGrid(const localization::OccupancyMap& map, nav_msgs::OccupancyGrid* out);
// A received grid (a map_server's): "" and *out, or what is wrong with it (size, resolution,
// a rotated origin, a cell outside -1 .. 100).
std::string fromOccupancyGrid(const nav_msgs::OccupancyGrid& grid, localization::OccupancyMap* out);
// (x, y, yaw) covariance into the 6 x 6 row-major one of (x, y, z, roll, pitch, yaw).
geometry_msgs::PoseWithCovariance toPoseWithCovariance(const core::Pose2& pose, const Eigen::Matrix3d& covariance);

}  // namespace ros_layer
}  // namespace amigobot_tracking

#include "amigobot_tracking/ros/trail.h"

#include <cmath>
#include <string>

namespace amigobot_tracking {
namespace ros_layer {

std::string TrailConfig::validate() const {
  if (!(std::isfinite(min_distance) && min_distance >= 0.0)) return "min_distance must be >= 0";
  if (max_poses < 2) return "max_poses must be >= 2, got " + std::to_string(max_poses);
  return "";
}

bool appendToTrail(const TrailConfig& config, const geometry_msgs::PoseStamped& pose, nav_msgs::Path* path) {
  if (!path->poses.empty()) {
    const auto& last = path->poses.back().pose.position;
    const double d = std::hypot(pose.pose.position.x - last.x, pose.pose.position.y - last.y);
    if (d < config.min_distance) return false;
  }
  path->poses.push_back(pose);
  const std::size_t cap = static_cast<std::size_t>(config.max_poses);
  if (path->poses.size() > cap) path->poses.erase(path->poses.begin(), path->poses.end() - cap);
  return true;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

#include "amigobot_tracking/ros/trail.h"

#include <cmath>
#include <string>

namespace amigobot_tracking {
namespace ros_layer {

const core::FieldTable<TrailConfig>& trailFields() {
  static const core::FieldTable<TrailConfig> table = {
      core::field("min_distance", &TrailConfig::min_distance, "m", "a pose closer than this to the last is not added",
                  core::nonNegative()),
      core::field("max_poses", &TrailConfig::max_poses, "-", "oldest poses dropped beyond this", core::atLeast(2)),
  };
  return table;
}

std::string TrailConfig::validate() const { return core::checkFields(trailFields(), *this); }

const core::FieldTable<TrailNodeConfig>& trailNodeFields() {
  static const core::FieldTable<TrailNodeConfig> table = [] {
    using T = TrailNodeConfig;
    core::FieldTable<T> t = {
        core::field("frame", &T::frame, "-", "the frame whose path is drawn"),
        core::field("global_frame", &T::global_frame, "-", "the path's frame"),
        core::field("rate", &T::rate, "Hz", "tf lookups per second", core::positive()),
    };
    core::include(&t, "", &T::trail, trailFields());
    return t;
  }();
  return table;
}

std::string TrailNodeConfig::validate() const { return core::checkFields(trailNodeFields(), *this); }

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

// A frame's recent path for rviz (nav_msgs/Path): poses at least min_distance apart, the
// oldest dropped beyond max_poses.
#pragma once

#include <cstddef>

#include <string>

#include <nav_msgs/Path.h>

#include "amigobot_tracking/core/support/field_table.h"

namespace amigobot_tracking {
namespace ros_layer {

struct TrailConfig {
  double min_distance = 0.02;  // [m] a pose closer than this to the last one is not added
  int max_poses = 3000;        // [-] oldest poses dropped beyond this (>= 2)
  std::string validate() const;  // "" or "key: reason"
};

const core::FieldTable<TrailConfig>& trailFields();

// The trail_publisher node's parameters: which frame, in which frame, how often.
struct TrailNodeConfig {
  std::string frame = "base_link";
  std::string global_frame = "map";
  double rate = 5.0;  // [Hz]
  TrailConfig trail;
  std::string validate() const;  // "" or "key: reason"
};

const core::FieldTable<TrailNodeConfig>& trailNodeFields();

// Appends `pose` to `path` unless it is within min_distance of the last pose; returns
// whether it was appended.
bool appendToTrail(const TrailConfig& config, const geometry_msgs::PoseStamped& pose, nav_msgs::Path* path);

}  // namespace ros_layer
}  // namespace amigobot_tracking

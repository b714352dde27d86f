// The one estimate of the localisation layer: what the Localizer, the Mapper and every
// Engine (engine.h) hand out after a scan, and what the ROS node publishes from.
#pragma once

#include <string>

#include <Eigen/Core>

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace localization {

struct PoseEstimate {
  core::Pose2 pose;         // map -> base
  core::Pose2 map_to_odom;  // the correction published as tf
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  // [m^2, rad^2] of (x, y, yaw)
  int scans = 0;             // scans processed
  // On a known map (mapping: 0 / true / 0 / false, its map is made of its own scans).
  double match = 0.0;        // fraction of the scan's beams on the map, [0, 1]
  double icp_goodness = 0.0;  // MRPT's fraction of paired points in the last ICP, [0, 1]
  bool matched = true;       // this scan was aligned (else: odometry only)
  double correction = 0.0, correction_angle = 0.0;  // [m], [rad] how far this scan's match moved the pose
  bool lost = false;         // match < min_match
  // The verdict (localization_verdict.h): the match and the pose agree (mapping: always).
  bool localized = true;
  std::string not_localized;  // why not
};

// A search of the whole map for the robot (a kidnapped robot, global_localization).
struct GlobalSearch {
  bool found = false;
  core::Pose2 pose;    // map -> base of the best candidate
  double match = 0.0;  // its fraction of beams on the map
  int candidates = 0;  // coarse poses scored
};

}  // namespace localization
}  // namespace amigobot_tracking

// Is an operator's initial pose (/initialpose, rviz's "2D Pose Estimate") usable? Refused, by
// name, when it is in another frame than the map's, has a NaN/inf coordinate, a rotation that
// is not a unit quaternion (a hand-written message's all-zero default; within 1e-3 of unit it
// is normalised, core/supervision/transform_check.h), or lies far outside the map: beyond its bounds by
// more than kInitialPoseMapMargin (a click just past the edge is a robot at the door). The
// localisation keeps its current pose then. An empty frame is taken as the map's (rostopic
// pub leaves it empty).
#pragma once

#include <string>

#include "amigobot_tracking/core/supervision/transform_check.h"
#include "amigobot_tracking/localization/occupancy_map.h"

namespace amigobot_tracking {
namespace localization {

constexpr double kInitialPoseMapMargin = 1.0;  // [m]

// "" when usable, else why not ("frame 'odom' is not 'map'", "position x is nan", ...).
// `map` empty (mapping): no bounds to check.
std::string initialPoseProblem(const std::string& frame, const std::string& map_frame, const core::Translation3& position,
                               const core::Quaternion4& orientation, const OccupancyMap& map);

}  // namespace localization
}  // namespace amigobot_tracking

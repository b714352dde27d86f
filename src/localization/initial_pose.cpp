#include "amigobot_tracking/localization/initial_pose.h"

#include <cstdio>

namespace amigobot_tracking {
namespace localization {

std::string initialPoseProblem(const std::string& frame, const std::string& map_frame, const core::Translation3& position,
                               const core::Quaternion4& orientation, const OccupancyMap& map) {
  if (!frame.empty() && frame != map_frame) return "frame '" + frame + "' is not '" + map_frame + "'";
  std::string problem = core::transformProblem(position, orientation);
  if (!problem.empty()) {
    if (problem.rfind("translation", 0) == 0) problem.replace(0, 11, "position");
    if (problem.rfind("rotation", 0) == 0) problem.replace(0, 8, "orientation");
    return problem;
  }
  if (map.empty()) return "";
  const double min_x = map.origin_x, min_y = map.origin_y;
  const double max_x = min_x + map.width * map.resolution, max_y = min_y + map.height * map.resolution;
  const double m = kInitialPoseMapMargin;
  if (position.x < min_x - m || position.x > max_x + m || position.y < min_y - m || position.y > max_y + m) {
    char why[200];
    std::snprintf(why, sizeof why, "(%.2f, %.2f) is more than %.1f m outside the map ([%.2f, %.2f] x [%.2f, %.2f] m)",
                  position.x, position.y, m, min_x, max_x, min_y, max_y);
    return why;
  }
  return "";
}

}  // namespace localization
}  // namespace amigobot_tracking

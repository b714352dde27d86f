// A recorded log played through the localisation layer offline, as fast as the CPU allows, and
// scored against the log's reference poses: mapping (the Mapper, either method) from the first
// scan's reference pose, or localisation (the Localizer) on a map drawn from the reference
// poses. The tool log_replay and the real-data test call these.
#pragma once

#include <cmath>

#include "amigobot_tracking/localization/carmen_log.h"
#include "amigobot_tracking/localization/localization_config.h"
#include "amigobot_tracking/localization/occupancy_map.h"
#include "amigobot_tracking/localization/trajectory_error.h"

namespace amigobot_tracking {
namespace localization {

struct ReplayResult {
  std::vector<core::Pose2> estimate, reference;  // one per scan
  AbsoluteError ate;
  RelativeError relative;
  AbsoluteError odometry_ate;  // the odometry alone, for scale
  int loop_closures = 0;
  double seconds = 0.0;        // CPU time of the replay
  OccupancyMap map;            // mapping: the map built
};

// Odometry made from the reference poses, for corrected logs whose ODOM lines are corrected
// too (GMapping's *.gfs.log): each step's travel scaled by `scale` and its heading turned by
// `heading_per_metre` [rad/m] of travel, a wheel-radius and a wheel-base error.
struct OdometryDrift {
  double scale = 1.02;
  double heading_per_metre = 1.5 * M_PI / 180.0;
};
void driftOdometry(CarmenLog* log, const OdometryDrift& drift);

// `relations` empty: consecutive reference poses. config.mode is set by each call.
ReplayResult replayMapping(const CarmenLog& log, LocalizationConfig config, const Relations& relations = {});
ReplayResult replayLocalization(const CarmenLog& log, LocalizationConfig config, const OccupancyMap& map,
                                const Relations& relations = {});
// The map a surveyor would draw: every scan inserted at its reference pose.
OccupancyMap referenceMap(const CarmenLog& log, double resolution, double range_cap);

}  // namespace localization
}  // namespace amigobot_tracking

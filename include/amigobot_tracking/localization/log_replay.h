// A recorded log played through the localisation layer offline and scored against the log's
// reference poses: mapping (the Mapper, either method) from the first scan's reference pose,
// or localisation (the Localizer) on a map drawn from the reference poses or on the map a
// mapping run saved. Mapping is scored twice: the online pose (what the node publishes at each
// scan while the robot drives, at the log's real rate) and the final smoothed trajectory (every
// scan's pose as optimised at the end, which the robot never had). The tool log_replay and the
// real-data test call these.
#pragma once

#include <cmath>

#include "amigobot_tracking/localization/carmen_log.h"
#include "amigobot_tracking/localization/localization_config.h"
#include "amigobot_tracking/localization/occupancy_map.h"
#include "amigobot_tracking/localization/trajectory_error.h"

namespace amigobot_tracking {
namespace localization {

struct ReplayResult {
  // Mapping: the final smoothed trajectory; localisation: the pose at each scan.
  std::vector<core::Pose2> estimate, reference;  // one per scan
  AbsoluteError ate;
  RelativeError relative;
  // Mapping: the pose published at each scan's stamp, with the node's worker (newest scan
  // only, the others dropped while it is busy) timed by each update's CPU time.
  std::vector<core::Pose2> online;
  AbsoluteError online_ate;
  RelativeError online_relative;
  int dropped = 0;             // scans the worker was too busy for
  double max_update = 0.0;     // [s] CPU time of the slowest update
  AbsoluteError odometry_ate;  // the odometry alone, for scale
  int loop_closures = 0;
  double seconds = 0.0;        // CPU time of the replay
  OccupancyMap map;            // mapping: the map built
};

// Odometry made from the reference poses, for corrected logs whose ODOM lines are corrected
// too (GMapping's *.gfs.log): each step's travel scaled by `scale` and its heading turned by
// `heading_per_metre` [rad/m] of travel, a wheel-radius and a wheel-base error; with `noise`
// > 0, each step's travel is also scaled by 1 + N(0, noise) and turned by N(0, noise) rad per
// metre of it (Gaussian, drawn from `seed`): wheel slip that no calibration removes.
struct OdometryDrift {
  double scale = 1.02;
  double heading_per_metre = 1.5 * M_PI / 180.0;
  double noise = 0.0;  // [-, rad/m] standard deviation
  unsigned seed = 1;
};
void driftOdometry(CarmenLog* log, const OdometryDrift& drift);

// `relations` empty: consecutive reference poses. config.mode is set by each call.
ReplayResult replayMapping(const CarmenLog& log, LocalizationConfig config, const Relations& relations = {});
// Localisation on `map` (a reference map, or a mapping run's map: the map's quality) from the
// first scan's reference pose.
ReplayResult replayLocalization(const CarmenLog& log, LocalizationConfig config, const OccupancyMap& map,
                                const Relations& relations = {});
// The map a surveyor would draw: every scan inserted at its reference pose.
OccupancyMap referenceMap(const CarmenLog& log, double resolution, double range_cap);

}  // namespace localization
}  // namespace amigobot_tracking

// One planar scan as the localisation uses it: the device's beam angles (first angle and
// step, REP 117 ranges: +-inf and NaN are no echo), the mount pose base -> laser, and its
// conversions to scan points in the base frame and to MRPT's observation.
#pragma once

#include <vector>

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace localization {

struct RangeScan {
  double angle_min = 0.0;        // [rad] first beam, laser frame
  double angle_increment = 0.0;  // [rad] > 0
  double range_min = 0.0, range_max = 0.0;  // [m]
  std::vector<float> ranges;                 // [m]
  core::Pose2 mount;                         // base -> laser
  double stamp = 0.0;                        // [s] when it was taken (the mapper's clock)

  bool valid(int beam, double range_cap) const;  // an echo within [range_min, min(range_max, cap)]
};

// Base-frame points of the valid echoes, at most max_points (evenly decimated).
std::vector<Eigen::Vector2d> scanPoints(const RangeScan& scan, double range_cap, int max_points);
// The same points as an MRPT points map.
void toPointsMap(const std::vector<Eigen::Vector2d>& points, mrpt::maps::CSimplePointsMap* out);
// MRPT's observation of the scan: MRPT spreads the beams symmetrically over `aperture`, so the
// device's first angle becomes a turn of the sensor pose about z.
mrpt::obs::CObservation2DRangeScan::Ptr toObservation(const RangeScan& scan, double range_cap);

}  // namespace localization
}  // namespace amigobot_tracking

// Occupancy grids drawn from scans at known poses (MRPT's COccupancyGridMap2D, its Bayesian
// ray casting), in the trinary form of map_server: occupied >= 60 %, free <= 40 %, else unknown.
#pragma once

#include <vector>

#include "amigobot_tracking/localization/occupancy_map.h"
#include "amigobot_tracking/localization/range_scan.h"

namespace mrpt::maps {
class COccupancyGridMap2D;
}

namespace amigobot_tracking {
namespace localization {

OccupancyMap toOccupancyMap(const mrpt::maps::COccupancyGridMap2D& grid);
// scans[i] taken at poses[i] (map -> base); echoes beyond range_cap [m] are left out.
OccupancyMap drawMap(const std::vector<const RangeScan*>& scans, const std::vector<core::Pose2>& poses, double resolution,
                     double range_cap);

}  // namespace localization
}  // namespace amigobot_tracking

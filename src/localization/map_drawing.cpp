#include "amigobot_tracking/localization/map_drawing.h"

#include <stdexcept>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose3D.h>

namespace amigobot_tracking {
namespace localization {

OccupancyMap toOccupancyMap(const mrpt::maps::COccupancyGridMap2D& grid) {
  OccupancyMap out = makeMap(grid.getResolution(), grid.getXMin(), grid.getYMin(), static_cast<int>(grid.getSizeX()),
                             static_cast<int>(grid.getSizeY()));
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      const float occupancy = 1.0f - grid.getCell(x, y);  // MRPT stores how free a cell is
      out.at(x, y) = occupancy >= 0.6f ? OccupancyMap::kOccupied : occupancy <= 0.4f ? OccupancyMap::kFree : OccupancyMap::kUnknown;
    }
  }
  return out;
}

OccupancyMap drawMap(const std::vector<const RangeScan*>& scans, const std::vector<core::Pose2>& poses, double resolution,
                     double range_cap) {
  if (scans.size() != poses.size()) throw std::invalid_argument("drawMap: one pose per scan");
  if (scans.empty()) return OccupancyMap();
  mrpt::maps::COccupancyGridMap2D grid(-5.0f, 5.0f, -5.0f, 5.0f, static_cast<float>(resolution));  // grows as needed
  grid.insertionOptions.maxDistanceInsertion = static_cast<float>(range_cap);
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const auto observation = toObservation(*scans[i], range_cap);
    const mrpt::poses::CPose3D robot(poses[i].x, poses[i].y, 0.0, poses[i].theta, 0.0, 0.0);
    grid.insertObservation(*observation, robot);
  }
  return toOccupancyMap(grid);
}

}  // namespace localization
}  // namespace amigobot_tracking

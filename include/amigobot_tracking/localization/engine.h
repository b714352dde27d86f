// Mapping and localisation behind one interface (the slam_toolbox pattern): the ROS node
// holds an Engine made from the configuration's mode and never asks which one it is. Each
// call returns the one PoseEstimate; what a mode cannot do (a pose or a global search while
// mapping, saving a map while localising) is refused with the reason, not an exception.
// Not thread-safe: one caller at a time (the node serialises its worker and services).
#pragma once

#include <memory>
#include <string>

#include "amigobot_tracking/localization/localization_config.h"
#include "amigobot_tracking/localization/occupancy_map.h"
#include "amigobot_tracking/localization/pose_estimate.h"
#include "amigobot_tracking/localization/range_scan.h"

namespace amigobot_tracking {
namespace localization {


class Engine {
 public:
  virtual ~Engine() = default;
  // One scan taken when odometry said odom_base.
  virtual const PoseEstimate& update(const RangeScan& scan, const core::Pose2& odom_base) = 0;
  virtual const PoseEstimate& estimate() const = 0;
  // The robot is at map_base (/initialpose): "" when taken, else why not.
  virtual std::string setPose(const core::Pose2& map_base, const core::Pose2& odom_base) = 0;
  // A search of the whole map from one scan: "" when it ran (found or not), else why not.
  virtual std::string globalSearch(const RangeScan& scan, const core::Pose2& odom_base, GlobalSearch* result) = 0;
  // The map to publish: a known map once, a growing one every map_publish_period.
  virtual OccupancyMap map() const = 0;
  virtual bool mapGrows() const = 0;
  // The map ~save_map writes: "" and *map, else why there is none.
  virtual std::string mapToSave(OccupancyMap* map) const = 0;
  // Whether the estimate's match and ICP goodness mean anything (a known map).
  virtual bool measuresMatch() const = 0;
};

// The engine of config.mode: "localization" on config.map_file (throws std::runtime_error
// "parameter ~map_file: ..." for a bad file), "mapping" (ICP-SLAM or graph).
std::unique_ptr<Engine> makeEngine(const LocalizationConfig& config);
// Localisation on a map received rather than read (use_map_topic); throws std::runtime_error
// for an empty map.
std::unique_ptr<Engine> makeEngine(const LocalizationConfig& config, const OccupancyMap& map);

}  // namespace localization
}  // namespace amigobot_tracking

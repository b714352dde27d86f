#include "amigobot_tracking/ros/sim_laser.h"

#include <cmath>

#include <ros/console.h>

#include "amigobot_tracking/ros/param_reader.h"

#include "amigobot_tracking/world/raycast.h"
#include "amigobot_tracking/core/perception/scan_obstacles.h"

namespace amigobot_tracking {
namespace ros_layer {

const core::FieldTable<SimLaserConfig>& simLaserFields() {
  using S = SimLaserConfig;
  using core::field;
  static const core::FieldTable<S> table = {
      field("world_file", &S::world_file, "-", "world YAML (obstacles, walls, polygons); required"),
      field("global_frame", &S::global_frame, "-", "frame of the world"),
      field("laser_frame", &S::laser_frame, "-", "frame of the scans"),
      field("beams", &S::beams, "-", "beams per scan", core::atLeast(2)),
      field("angle_min", &S::angle_min, "rad", "first beam, laser frame", core::anyValue()),
      field("angle_max", &S::angle_max, "rad", "last beam (> angle_min)", core::anyValue()),
      field("range_min", &S::range_min, "m", "closer returns are -inf", core::nonNegative()),
      field("range_max", &S::range_max, "m", "no return beyond (> range_min)", core::nonNegative()),
      field("rate", &S::rate, "Hz", "scans per second", core::positive()),
      field("noise_std", &S::noise_std, "m", "Gaussian range noise (0: exact)", core::nonNegative()),
      field("seed", &S::seed, "-", "noise seed"),
  };
  return table;
}

std::string SimLaserConfig::validate() const {
  const std::string bad = core::checkFields(simLaserFields(), *this);
  if (!bad.empty()) return bad;
  if (world_file.empty()) return "world_file: must name a world YAML";
  if (global_frame.empty()) return "global_frame: must not be empty";
  if (laser_frame.empty()) return "laser_frame: must not be empty";
  if (!(angle_max > angle_min)) return "angle_max: must be > angle_min";
  if (!(range_max > range_min)) return "range_max: must be > range_min";
  return "";
}

std::string loadSimLaserConfig(const ros::NodeHandle& pnh, SimLaserConfig* config) {
  return readParams(pnh, simLaserFields(), config);
}

sensor_msgs::LaserScan simulateScan(const core::Pose2& laser, const world::World& world,
                                    const SimLaserConfig& config, std::mt19937* rng) {
  core::ScanGeometry geometry;
  geometry.angle_min = config.angle_min;
  geometry.angle_increment = (config.angle_max - config.angle_min) / (config.beams - 1);
  geometry.range_min = config.range_min;
  geometry.range_max = config.range_max;
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = config.laser_frame;
  scan.angle_min = static_cast<float>(geometry.angle_min);
  scan.angle_max = static_cast<float>(config.angle_max);
  scan.angle_increment = static_cast<float>(geometry.angle_increment);
  scan.range_min = static_cast<float>(config.range_min);
  scan.range_max = static_cast<float>(config.range_max);
  scan.scan_time = static_cast<float>(1.0 / config.rate);
  scan.time_increment = 0.0f;  // all beams at the stamp: the ray cast is instantaneous
  scan.ranges = world::raycastScan(laser, world, geometry, config.beams);
  if (config.noise_std > 0.0 && rng != nullptr) {
    std::normal_distribution<double> noise(0.0, config.noise_std);
    for (float& r : scan.ranges) {
      if (!std::isfinite(r)) continue;
      const double noisy = r + noise(*rng);
      r = static_cast<float>(std::min(config.range_max, std::max(config.range_min, noisy)));
    }
  }
  return scan;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

#include "amigobot_tracking/ros/sim_laser.h"

#include <cmath>

#include <ros/console.h>

#include "amigobot_tracking/ros/logged_param.h"

#include "amigobot_tracking/world/raycast.h"
#include "amigobot_tracking/core/scan_obstacles.h"

namespace amigobot_tracking {
namespace ros_layer {

std::string SimLaserConfig::validate() const {
  if (world_file.empty()) return "world_file must name a world YAML";
  if (global_frame.empty()) return "global_frame must not be empty";
  if (laser_frame.empty()) return "laser_frame must not be empty";
  if (beams < 2) return "beams must be >= 2, got " + std::to_string(beams);
  if (!std::isfinite(angle_min) || !std::isfinite(angle_max) || !(angle_max > angle_min)) {
    return "angle_max must be > angle_min (finite)";
  }
  if (!(std::isfinite(range_min) && range_min >= 0.0)) return "range_min must be >= 0";
  if (!(std::isfinite(range_max) && range_max > range_min)) return "range_max must be > range_min";
  if (!(std::isfinite(rate) && rate > 0.0)) return "rate must be > 0";
  if (!(std::isfinite(noise_std) && noise_std >= 0.0)) return "noise_std must be >= 0";
  return "";
}

std::string loadSimLaserConfig(const ros::NodeHandle& pnh, SimLaserConfig* config) {
  loggedParam(pnh, "world_file", &config->world_file);
  loggedParam(pnh, "global_frame", &config->global_frame);
  loggedParam(pnh, "laser_frame", &config->laser_frame);
  loggedParam(pnh, "beams", &config->beams);
  loggedParam(pnh, "angle_min", &config->angle_min);
  loggedParam(pnh, "angle_max", &config->angle_max);
  loggedParam(pnh, "range_min", &config->range_min);
  loggedParam(pnh, "range_max", &config->range_max);
  loggedParam(pnh, "rate", &config->rate);
  loggedParam(pnh, "noise_std", &config->noise_std);
  loggedParam(pnh, "seed", &config->seed);
  const std::string error = config->validate();
  return error.empty() ? "" : "parameter " + pnh.getNamespace() + "/" + error;
}

sensor_msgs::LaserScan simulateScan(const core::Pose2& laser, const std::vector<core::Disk>& disks,
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
  scan.ranges = world::raycastScan(laser, disks, geometry, config.beams);
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

// Simulated planar laser for the emulated robot: ray casts the emulator's world (disks, walls
// and polygons of a world YAML, world/world.h) from the laser frame's pose in the global frame into a
// sensor_msgs/LaserScan (REP 117: +inf no return, -inf closer than range_min).
#pragma once

#include <random>
#include <string>
#include <vector>

#include <ros/node_handle.h>
#include <sensor_msgs/LaserScan.h>

#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/core/support/types.h"
#include "amigobot_tracking/world/world.h"

namespace amigobot_tracking {
namespace ros_layer {

struct SimLaserConfig {
  std::string world_file;          // world YAML (world/world.h: obstacles, walls, polygons); required
  std::string global_frame = "map";
  std::string laser_frame = "laser";
  int beams = 360;                 // [-] beams per scan, >= 2
  double angle_min = -3.14159265358979;  // [rad] first beam, laser frame
  double angle_max = 3.14159265358979;   // [rad] last beam (> angle_min)
  double range_min = 0.05;         // [m]
  double range_max = 8.0;          // [m] > range_min
  double rate = 10.0;              // [Hz] scans per second
  double noise_std = 0.005;        // [m] Gaussian range noise (0: exact)
  int seed = 1;                    // noise seed

  // Empty when valid, else "key: reason".
  std::string validate() const;
};

const core::FieldTable<SimLaserConfig>& simLaserFields();

// Reads the private parameters (param_reader.h). "" or "~key: reason".
std::string loadSimLaserConfig(const ros::NodeHandle& pnh, SimLaserConfig* config);

// One scan of `world` seen from `laser` (pose of the laser frame in the global frame).
// Noise is added to finite ranges only and clamped into [range_min, range_max].
sensor_msgs::LaserScan simulateScan(const core::Pose2& laser, const world::World& world,
                                    const SimLaserConfig& config, std::mt19937* rng);

}  // namespace ros_layer
}  // namespace amigobot_tracking

// What the emulated laser sees: a ray-cast scan of the world (disks, walls, polygons) from the laser's mount
// pose on the robot, with optional Gaussian range noise and dropouts.
// A RPLIDAR's scan is one revolution of samples at its own, uneven angles (EmulatedScan::angles).
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "amigobot_tracking/core/support/types.h"
#include "amigobot_tracking/sensors/laser_model.h"
#include "amigobot_tracking/sensors/laser_session.h"
#include "amigobot_tracking/world/world.h"

namespace amigobot_tracking {
namespace sensors {

struct ScanSourceOptions {
  core::Pose2 mount;          // [m, m, rad] laser in base_link
  bool upside_down = false;   // mounted upside down: the beams sweep clockwise in base_link
  double range_noise = 0.0;   // [m] std-dev added to every hit
  double dropout = 0.0;       // probability that a beam reports no measurement
  std::uint32_t seed = 1;

  void validate() const;  // throws std::invalid_argument naming the bad option
};

class ScanSource {
 public:
  ScanSource(LaserModel model, world::World world, ScanSourceOptions options);
  // The scan of the robot at `base` (base_link in the world) at emulator time t [s]: the
  // world's people (world::worldAt) stand where they are at t.
  EmulatedScan cast(const core::Pose2& base, double t);
  // The sensor pose in the world for a robot at `base`.
  core::Pose2 sensorPose(const core::Pose2& base) const;

 private:
  std::vector<float> revolution(const core::Pose2& sensor, const world::World& room, const core::ScanGeometry& grid,
                                std::vector<float>* angles);

  LaserModel model_;
  world::World world_;
  world::World snapshot_;  // world_ at the last scan's time (when it has people)
  ScanSourceOptions options_;
  std::mt19937 random_;
  std::uint64_t index_ = 0;
  double phase_ = 0.0;  // samplesAsItTurns: where the next sample falls (LaserProtocol::revolutionAngles)
};

}  // namespace sensors
}  // namespace amigobot_tracking

// RobotEmulator's sensing: sonar ranges from the world (disks, walls, polygons) and the SIP
// it sends each cycle (odometry in firmware units, the transducers fired in the POLLING order).
#include <algorithm>
#include <cmath>

#include <mrpt/poses/CPose2D.h>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/aria/emulator.h"
#include "amigobot_tracking/world/geometry.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

long wrapUnits(double value, long modulus) {
  const long units = std::lround(value);
  return ((units % modulus) + modulus) % modulus;
}

}  // namespace

std::vector<double> RobotEmulator::sonarRanges() const {
  std::vector<double> ranges;
  // People stand where they are at the emulator's last step (the clock of the status line).
  const world::World* room = &options_.world;
  world::World now;
  if (!options_.world.people.empty()) {
    now = world::worldAt(options_.world, std::max(0.0, last_time_));
    room = &now;
  }
  const mrpt::poses::CPose2D robot(pose_.x, pose_.y, pose_.theta);
  for (const SonarPose& s : options_.robot.sonars) {
    const mrpt::poses::CPose2D sensor = robot + mrpt::poses::CPose2D(s.x, s.y, s.yaw);
    const core::Pose2 axis{sensor.x(), sensor.y(), sensor.phi()};
    ranges.push_back(std::min(options_.sonar_max_range, world::coneRange(*room, axis, options_.sonar_half_cone)));
  }
  return ranges;
}

std::vector<std::uint8_t> RobotEmulator::makeSip() {
  const RobotParams& p = options_.robot;
  const double b = p.halfTrack();
  Sip sip;
  const bool moving = std::abs(v_) > 1e-4 || std::abs(w_) > 1e-4;
  sip.type = options_.simulator_mode || !moving ? kSipStopped : kSipMoving;
  sip.x = static_cast<std::uint16_t>(wrapUnits(odo_x_mm_ / p.dist_conv_factor, 0x8000));
  sip.y = static_cast<std::uint16_t>(wrapUnits(odo_y_mm_ / p.dist_conv_factor, 0x8000));
  sip.theta = static_cast<std::int16_t>(wrapUnits(odo_th_ / p.angle_conv_factor, p.angle_units_per_turn));
  sip.left_vel = static_cast<std::int16_t>(std::lround((v_ - b * w_) * 1e3 / p.vel_conv_factor));
  sip.right_vel = static_cast<std::int16_t>(std::lround((v_ + b * w_) * 1e3 / p.vel_conv_factor));
  sip.battery = static_cast<std::uint8_t>(std::lround(options_.battery_voltage * 10));
  sip.control = sip.theta;
  sip.flags = (motors_ ? kFlagMotorsEnabled : 0) | (sonar_on_ ? kFlagSonarArrays : 0);
  if (sonar_on_ && !p.sonars.empty()) {
    const std::vector<double> ranges = sonarRanges();
    // The firmware reports the transducers fired since the last SIP: half the ring per cycle.
    const std::size_t cycle = polling_.empty() ? ranges.size() : polling_.size();
    const std::size_t per_sip = std::min(cycle, options_.simulator_mode ? ranges.size() : std::max<std::size_t>(1, ranges.size() / 2));
    for (std::size_t k = 0; k < per_sip; ++k) {
      const std::size_t step = (next_sonar_ + k) % cycle;
      const std::size_t i = polling_.empty() ? step : polling_[step];
      sip.sonars.push_back({static_cast<std::uint8_t>(i),
                            static_cast<std::uint16_t>(std::lround(ranges[i] * 1e3 / p.range_conv_factor))});
    }
    next_sonar_ = (next_sonar_ + per_sip) % cycle;
  }
  sip.grip_state = 0;
  sip.battery_x10 = static_cast<std::uint16_t>(std::lround(options_.battery_voltage * 10));
  sip.rot_vel = static_cast<std::int16_t>(std::lround(w_ / kDegToRad * 10));
  sip.temperature = -127;
  // Tail length: AmigOS ends at DIGOUT, AmigoSH adds BATTERYX10 + CHARGESTATE, the simulator
  // sends everything up to the state of charge.
  const int tail = options_.simulator_mode ? 12 : (p.model == "amigo-sh" ? 7 : 5);
  return encodeSip(sip, tail);
}

}  // namespace aria
}  // namespace amigobot_tracking

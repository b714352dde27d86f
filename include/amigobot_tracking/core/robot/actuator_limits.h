// What the robot's base can do to a velocity command, in SI: the firmware's ramps, its cycle
// and the delay before a command takes effect, and the speed ceilings of the wheels and the
// body. One struct, the single home of these numbers: the robot description (config/robots/
// <model>.yaml) holds one, the robot emulator and the offline simulator drive their bodies
// through the actuator model built from it, and the safety filter plans its braking with it.
// Defaults: the AmigoBot (MobileSim's amigo model, ARIA without a CONFIGpac, AmigOS 100 ms
// SIP cycle).
#pragma once

namespace amigobot_tracking {
namespace core {

struct ActuatorLimits {
  double trans_accel = 0.3;       // [m/s^2] |v| growing (TransAccel)
  double trans_decel = 0.75;      // [m/s^2] |v| shrinking (TransDecel)
  double rot_accel = 1.745;       // [rad/s^2] |w| growing (RotAccel, 100 deg/s^2)
  double rot_decel = 1.745;       // [rad/s^2] |w| shrinking (RotDecel)
  double max_velocity = 1.0;      // [m/s] body and wheel speed ceiling (MaxVelocity)
  double max_rot_velocity = 5.236;  // [rad/s] body rotation ceiling (MaxRVelocity, 300 deg/s)
  double cycle = 0.1;             // [s] firmware control cycle: a command is sampled once per cycle
  double latency = 0.1;           // [s] from a command's arrival to its first effect on the wheels
};

}  // namespace core
}  // namespace amigobot_tracking

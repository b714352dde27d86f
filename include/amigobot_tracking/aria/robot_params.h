// One robot model's parameters (AriaCoda params/<model>.p plus the firmware defaults the
// emulator needs). Conversion factors stay in ARIA units because they are applied only at
// the driver's edge; everything else is SI. Loaded from config/robots/<model>.yaml.
#pragma once

#include <string>
#include <vector>

namespace amigobot_tracking {
namespace aria {

struct SonarPose {
  double x = 0.0;    // [m] in base_link
  double y = 0.0;    // [m]
  double yaw = 0.0;  // [rad]
};

struct RobotParams {
  std::string model = "amigo";       // SYNC2 subclass this set belongs to
  // Geometry.
  double robot_radius = 0.18;        // [m]
  double robot_width = 0.279;        // [m]
  double robot_length = 0.33;        // [m]
  // Conversion factors (ARIA units).
  double angle_conv_factor = 0.001534;  // [rad/unit] THPOS; 2*pi/4096
  int angle_units_per_turn = 4096;      // [units] THPOS wraps modulo this (360 for the manual's degree reading)
  double dist_conv_factor = 0.5083;     // [mm/unit] XPOS/YPOS
  double vel_conv_factor = 0.6154;      // [(mm/s)/unit] L/R VEL
  double range_conv_factor = 1.0;       // [mm/unit] sonar ranges
  double diff_conv_factor = 0.011;      // [1/mm] w = (R - L)/2 * DiffConv
  double vel2_divisor = 20.0;           // [(mm/s)/unit] VEL2 wheel units
  // Limits (SI).
  double max_velocity = 1.0;            // [m/s] ARIA MaxVelocity, also the wheel speed limit
  double max_rot_velocity = 5.236;      // [rad/s] ARIA MaxRVelocity 300 deg/s
  double trans_accel = 0.3;             // [m/s^2]
  double trans_decel = 0.75;            // [m/s^2]
  double rot_accel = 1.745;             // [rad/s^2] 100 deg/s^2
  double rot_decel = 1.745;             // [rad/s^2]
  // Firmware.
  double sip_cycle = 0.1;               // [s]
  double watchdog = 2.0;                // [s]
  int switch_to_baud = 38400;           // [baud]
  std::vector<SonarPose> sonars;
  double sonar_max_range = 4.335;       // [m] farthest echo a transducer reports (amigo.p: 4335 mm)
  std::vector<int> sonar_polling;       // POLLING firing order (transducer numbers); empty: the
                                        // firmware's own order (ARIA sends no POLLING)

  // Half the wheel separation b [m], from DiffConvFactor (w = (R - L) / (2 b)).
  double halfTrack() const { return 1e-3 / diff_conv_factor; }
  // Empty when valid, otherwise "field: reason" naming the first bad field.
  std::string validate() const;

  // Built-in sets matching AriaCoda's params/amigo.p and amigo-sh.p.
  static RobotParams amigo();
  static RobotParams amigoSh();
};

// Loads a YAML parameter file; every key is optional and defaults to the built-in `amigo`
// set. Throws std::runtime_error naming the file and the key on a bad value or an invalid
// set.
RobotParams loadRobotParams(const std::string& path);
// Built-in set by model name ("amigo" | "amigo-sh"); throws std::invalid_argument otherwise.
RobotParams builtinRobotParams(const std::string& model);

}  // namespace aria
}  // namespace amigobot_tracking

// One robot model's parameters (AriaCoda params/<model>.p plus the firmware defaults the
// emulator needs): the robot description of the robot file config/robots/<model>.yaml.
// Conversion factors stay in ARIA units because they are applied only at the driver's edge;
// everything else is SI.
#pragma once

#include <string>
#include <vector>

#include "amigobot_tracking/core/robot/robot_description.h"

namespace amigobot_tracking {
namespace aria {

struct SonarPose {
  double x = 0.0;    // [m] in base_link
  double y = 0.0;    // [m]
  double yaw = 0.0;  // [rad]
};

// The robot description (core/robot/robot_description.h: geometry, dynamics, the diamond) plus
// what only the ARIA driver and the robot emulator need: the protocol's conversion factors,
// the firmware's watchdog and baud, and the sonar table.
struct RobotParams : core::RobotDescription {
  std::string model = "amigo";       // SYNC2 subclass this set belongs to
  // Conversion factors (ARIA units).
  double angle_conv_factor = 0.001534;  // [rad/unit] THPOS; 2*pi/4096
  int angle_units_per_turn = 4096;      // [units] THPOS wraps modulo this (360 for the manual's degree reading)
  double dist_conv_factor = 0.5083;     // [mm/unit] XPOS/YPOS
  double vel_conv_factor = 0.6154;      // [(mm/s)/unit] L/R VEL
  double range_conv_factor = 1.0;       // [mm/unit] sonar ranges
  double diff_conv_factor = 0.011;      // [1/mm] w = (R - L)/2 * DiffConv
  double vel2_divisor = 20.0;           // [(mm/s)/unit] VEL2 wheel units
  // Firmware.
  double watchdog = 2.0;                // [s]
  int switch_to_baud = 38400;           // [baud]
  std::vector<SonarPose> sonars;
  double sonar_max_range = 4.335;       // [m] farthest echo a transducer reports (amigo.p: 4335 mm)
  std::vector<int> sonar_polling;       // POLLING firing order (transducer numbers); empty: the
                                        // firmware's own order (ARIA sends no POLLING)
  std::string file;                     // the robot file this set was loaded from; "" = built in

  // Where the set comes from, for messages: the file, or "built-in amigo set (config/robots/amigo.yaml)".
  std::string origin() const;

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
// The scalar rows of the robot file: the description's, then the ARIA ones (the lists
// `sonars` and `sonar_polling` are read beside them). Drives the loader, validate() and the
// docs' row list.
const core::FieldTable<RobotParams>& robotParamsFields();
// The list keys of the robot file, read beside the table's rows.
const std::vector<std::string>& robotParamsListKeys();
// Built-in set by model name ("amigo" | "amigo-sh"); throws std::invalid_argument otherwise.
RobotParams builtinRobotParams(const std::string& model);

}  // namespace aria
}  // namespace amigobot_tracking

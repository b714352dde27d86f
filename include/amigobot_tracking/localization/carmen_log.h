// CARMEN log files (the Radish / Freiburg 2-D laser data sets): FLASER (front laser, 180 deg,
// pose of the robot and its odometry), ROBOTLASER1 (any laser, its mount, the robot's pose)
// and ODOM lines. Each scan comes with the pose the log states for it (in a corrected log,
// such as GMapping's *.gfs.log, the reference trajectory) and the wheel odometry at its stamp
// (the ODOM lines interpolated; without ODOM lines, the odometry fields of the laser line).
#pragma once

#include <string>
#include <vector>

#include "amigobot_tracking/core/support/types.h"
#include "amigobot_tracking/localization/range_scan.h"

namespace amigobot_tracking {
namespace localization {

struct LogScan {
  RangeScan scan;           // stamp: the line's ipc timestamp [s]
  core::Pose2 reference;    // the robot's pose as the log states it
  core::Pose2 odometry;     // odom -> base at the scan's stamp
};

struct CarmenLog {
  std::vector<LogScan> scans;
  int odom_lines = 0;       // ODOM lines read (0: odometry from the laser lines)
};

// Reads FLASER, ROBOTLASER1 and ODOM lines and skips the others (PARAM, NEFF, comments ...).
// Readings at or beyond `no_echo` [m] are no echo (CARMEN's max-range convention). Throws
// std::runtime_error "FILE:LINE: what is wrong" for a malformed line, "FILE: ..." for a file
// that cannot be read or holds no scan.
CarmenLog readCarmenLog(const std::string& path, double no_echo = 50.0);

}  // namespace localization
}  // namespace amigobot_tracking

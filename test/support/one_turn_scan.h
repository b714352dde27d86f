// A LaserScan as sim_laser sends it (frame laser, 360 beams over one turn, range_min 0.05 m,
// range_max 8 m), every beam at `range` (+inf: nothing within range_max, REP 117): the good
// scan the bad-input tests spoil one field of.
#pragma once

#include <cmath>

#include <sensor_msgs/LaserScan.h>

namespace amigobot_test {

inline sensor_msgs::LaserScan oneTurnScan(float range) {
  sensor_msgs::LaserScan s;
  s.header.frame_id = "laser";
  s.angle_min = static_cast<float>(-M_PI);
  s.angle_max = static_cast<float>(M_PI);
  s.angle_increment = static_cast<float>(2.0 * M_PI / 359.0);
  s.range_min = 0.05f;
  s.range_max = 8.0f;
  s.scan_time = 0.1f;
  s.ranges.assign(360, range);
  return s;
}

}  // namespace amigobot_test

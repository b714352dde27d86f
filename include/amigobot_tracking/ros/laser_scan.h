// The Laser nodelet's parameters and its scan conversion: a device scan (sensors layer, the
// device's own beam angles) -> sensor_msgs/LaserScan per REP 117 (+inf no echo, -inf closer
// than range_min, NaN invalid), cropped, range-clamped and turned for an upside-down mount.
// Not MRPT's ROS1 bridge: it spreads the beams evenly over the aperture, which is not the
// geometry of a SCIP device (first and last step are not symmetric about the front).
#pragma once

#include <string>

#include <ros/node_handle.h>
#include <sensor_msgs/LaserScan.h>

#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/sensors/laser_driver.h"

namespace amigobot_tracking {
namespace ros_layer {

struct LaserParams {
  sensors::LaserDriverConfig driver;  // model, port, reconnect_period, stall_timeout
  std::string frame_id = "laser";
  double angle_min = -M_PI, angle_max = M_PI;  // [rad] crop; wider than the device: no crop
  double range_min = 0.0, range_max = 0.0;     // [m] override; 0: the device's own
  bool upside_down = false;                    // mounted upside down (z down): mirror the scan
  double time_offset = 0.0;                    // [s] added to every stamp
  double expected_rate = 0.0;                  // [Hz] diagnostics; 0: the model's nominal rate
  // rplidar: "device" (angle 0 = the device's 0 deg mark, counter-clockwise) or "rplidar_ros"
  // (rplidar_ros's pi - theta: a mount copied from rplidar_ros).
  std::string angle_convention = "device";

  // Empty when valid, else "name: what is wrong".
  std::string validate() const;
};

// The one description of the parameters (config/laser.yaml, the table in docs/ros_api.md).
const core::FieldTable<LaserParams>& laserFields();
// Reads the private parameters; throws std::runtime_error naming the bad one.
LaserParams loadLaserParams(const ros::NodeHandle& pnh);

// False when the crop keeps no beam.
bool toLaserScan(const sensors::LaserScanData& scan, const LaserParams& params, sensor_msgs::LaserScan* out);

}  // namespace ros_layer
}  // namespace amigobot_tracking

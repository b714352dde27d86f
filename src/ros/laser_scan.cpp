#include "amigobot_tracking/ros/laser_scan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "amigobot_tracking/ros/logged_param.h"

namespace amigobot_tracking {
namespace ros_layer {

std::string LaserParams::validate() const {
  try {
    driver.validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  if (frame_id.empty()) return "frame_id: empty";
  if (!(std::isfinite(angle_min) && std::isfinite(angle_max) && angle_max > angle_min)) {
    return "angle_max: must be > angle_min (both finite)";
  }
  if (!(std::isfinite(range_min) && range_min >= 0.0)) return "range_min: must be >= 0 (0: the device's)";
  if (!(std::isfinite(range_max) && range_max >= 0.0)) return "range_max: must be >= 0 (0: the device's)";
  if (range_max > 0.0 && !(range_max > range_min)) return "range_max: must be > range_min";
  if (!(std::isfinite(time_offset) && std::abs(time_offset) < 1.0)) return "time_offset: must be within (-1, 1) s";
  if (!(std::isfinite(expected_rate) && expected_rate >= 0.0)) return "expected_rate: must be >= 0";
  return "";
}

LaserParams loadLaserParams(const ros::NodeHandle& pnh) {
  LaserParams p;
  loggedParam(pnh, "model", &p.driver.model);
  loggedParam(pnh, "port", &p.driver.port);
  loggedParam(pnh, "reconnect_period", &p.driver.reconnect_period);
  loggedParam(pnh, "frame_id", &p.frame_id);
  loggedParam(pnh, "angle_min", &p.angle_min);
  loggedParam(pnh, "angle_max", &p.angle_max);
  loggedParam(pnh, "range_min", &p.range_min);
  loggedParam(pnh, "range_max", &p.range_max);
  loggedParam(pnh, "upside_down", &p.upside_down);
  loggedParam(pnh, "time_offset", &p.time_offset);
  loggedParam(pnh, "expected_rate", &p.expected_rate);
  const std::string error = p.validate();
  if (!error.empty()) throw std::runtime_error("parameter " + pnh.getNamespace() + "/" + error);
  return p;
}

bool toLaserScan(const sensors::LaserScanData& scan, const LaserParams& params, sensor_msgs::LaserScan* out) {
  const int n = static_cast<int>(scan.ranges.size());
  // Beam angles in the published frame: an upside-down mount sees beam i at -angle_i, so the
  // order is reversed to keep the increment positive.
  const double sign = params.upside_down ? -1.0 : 1.0;
  auto angle = [&](int k) {  // k-th published beam
    const int i = params.upside_down ? n - 1 - k : k;
    return sign * (scan.angle_min + scan.angle_increment * i);
  };
  int first = 0, last = n - 1;
  const double eps = 1e-9;
  while (first < n && angle(first) < params.angle_min - eps) ++first;
  while (last >= first && angle(last) > params.angle_max + eps) --last;
  if (last < first) return false;
  const double range_min = params.range_min > 0.0 ? params.range_min : scan.range_min;
  const double range_max = params.range_max > 0.0 ? params.range_max : scan.range_max;
  out->angle_min = static_cast<float>(angle(first));
  out->angle_max = static_cast<float>(angle(last));
  out->angle_increment = static_cast<float>(scan.angle_increment);
  out->time_increment = static_cast<float>(params.upside_down ? -scan.time_increment : scan.time_increment);
  out->scan_time = static_cast<float>(scan.scan_time);
  out->range_min = static_cast<float>(range_min);
  out->range_max = static_cast<float>(range_max);
  out->ranges.resize(static_cast<std::size_t>(last - first + 1));
  out->intensities.clear();
  for (int k = first; k <= last; ++k) {
    const int i = params.upside_down ? n - 1 - k : k;
    float r = scan.ranges[static_cast<std::size_t>(i)];
    if (std::isfinite(r) && r > range_max) r = std::numeric_limits<float>::infinity();
    if (std::isfinite(r) && r < range_min) r = -std::numeric_limits<float>::infinity();
    out->ranges[static_cast<std::size_t>(k - first)] = r;
    if (!scan.intensities.empty()) out->intensities.push_back(scan.intensities[static_cast<std::size_t>(i)]);
  }
  // The stamp is the time of the first published beam.
  const int first_measured = params.upside_down ? n - 1 - first : first;
  out->header.stamp.fromSec(scan.stamp + params.time_offset + scan.time_increment * first_measured);
  out->header.frame_id = params.frame_id;
  return true;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

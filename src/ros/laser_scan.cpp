#include "amigobot_tracking/ros/laser_scan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "amigobot_tracking/ros/param_aliases.h"
#include "amigobot_tracking/sensors/laser_protocol.h"
#include "amigobot_tracking/sensors/laser_registry.h"

namespace amigobot_tracking {
namespace ros_layer {

const core::FieldTable<LaserParams>& laserFields() {
  using P = LaserParams;
  using core::field;
  static const core::FieldTable<P> table = [] {
    core::FieldTable<P> t;
    core::include(&t, "", &P::driver, sensors::laserDriverFields());  // the driver's rows, described once
    t.push_back(field("angle_convention", &P::angle_convention, "-",
                      "rplidar only: device (angle 0 = the device's 0 deg mark, counter-clockwise, REP 103) or "
                      "rplidar_ros (rplidar_ros's pi - theta: the scan turned by pi, so a mount copied from an "
                      "rplidar_ros setup holds); device by default because the URDF's laser mount is the device's own",
                      core::oneOf({"device", "rplidar_ros"})));
    t.push_back(field("frame_id", &P::frame_id, "-", "frame of the published scan (the URDF's laser mount)"));
    t.push_back(core::defaultText(field("angle_min", &P::angle_min, "rad",
                                        "crop: the first published beam is the first at or after this angle (below "
                                        "the device's first beam: no crop)",
                                        core::anyValue()),
                                  "-pi"));
    t.push_back(core::defaultText(field("angle_max", &P::angle_max, "rad",
                                        "crop: the last published beam is the last at or before this angle, > "
                                        "angle_min (beyond the device's last beam: no crop)",
                                        core::anyValue()),
                                  "pi"));
    t.push_back(field("range_min", &P::range_min, "m",
                      "override of the device's range_min: closer returns are published as -inf; 0: the device's",
                      core::nonNegative()));
    t.push_back(field("range_max", &P::range_max, "m",
                      "override of the device's range_max: farther returns are published as +inf; 0: the device's, "
                      "else > range_min",
                      core::nonNegative()));
    t.push_back(field("upside_down", &P::upside_down, "-",
                      "laser mounted upside down: beams mirrored (angle -> -angle), their order reversed"));
    t.push_back(field("time_offset", &P::time_offset, "s", "added to every scan's stamp, within (-1, 1)",
                      core::interval(-1.0, true, 1.0, true)));
    t.push_back(field("expected_rate", &P::expected_rate, "Hz",
                      "scan rate the diagnostics expect; 0: the model's (hokuyo_urg 10, sick_tim5xx 15, sick_lms1xx 25, "
                      "rplidar 5.5 Hz)",
                      core::nonNegative()));
    return t;
  }();
  return table;
}

namespace {

// "rplidar": the models whose protocol's ROS driver has this angle convention.
std::string modelsWithConvention(const std::string& convention) {
  std::string models;
  for (const sensors::LaserModelEntry& e : sensors::laserModels()) {
    if (sensors::protocolOf(e.model()).rosDriverAngleConvention() == convention) models += (models.empty() ? "" : " | ") + e.name;
  }
  return models;
}

}  // namespace

std::string LaserParams::validate() const {
  const std::string bad = core::checkFields(laserFields(), *this);
  if (!bad.empty()) return bad;
  try {
    driver.validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  if (frame_id.empty()) return "frame_id: empty";
  // driver.validate() above: the model is known.
  const sensors::LaserProtocol& protocol = sensors::protocolOf(sensors::laserModel(driver.model));
  if (angle_convention != "device" && angle_convention != protocol.rosDriverAngleConvention()) {
    return "angle_convention: " + angle_convention + " is for model " + modelsWithConvention(angle_convention);
  }
  if (!(angle_max > angle_min)) return "angle_max: must be > angle_min";
  if (range_max > 0.0 && !(range_max > range_min)) return "range_max: must be > range_min";
  return "";
}

LaserParams loadLaserParams(const ros::NodeHandle& pnh) {
  LaserParams p;
  std::string error = readFields(pnh, laserFields(), &p, "", laserAliases());
  if (error.empty()) error = readSplitLaserAddress(pnh, &p.driver.port);
  if (!error.empty()) throw std::runtime_error("parameter " + error);
  const std::string invalid = p.validate();
  if (!invalid.empty()) throw std::runtime_error("parameter ~" + invalid);
  return p;
}

namespace {

sensors::LaserScanData halfTurn(const sensors::LaserScanData& scan) {
  // rplidar_ros's angle pi - theta is the device's -theta turned by pi: on the full-circle grid
  // [-pi, pi) of an even number of bins, the same grid with its halves swapped.
  sensors::LaserScanData out = scan;
  const std::size_t half = scan.ranges.size() / 2;
  std::rotate(out.ranges.begin(), out.ranges.begin() + static_cast<std::ptrdiff_t>(half), out.ranges.end());
  if (out.intensities.size() == scan.ranges.size())
    std::rotate(out.intensities.begin(), out.intensities.begin() + static_cast<std::ptrdiff_t>(half), out.intensities.end());
  return out;
}

}  // namespace

bool toLaserScan(const sensors::LaserScanData& device_scan, const LaserParams& params, sensor_msgs::LaserScan* out) {
  const bool full_circle = std::abs(device_scan.angle_increment * device_scan.ranges.size() - 2.0 * M_PI) < 1e-6;
  const bool turn = params.angle_convention == "rplidar_ros" && full_circle && device_scan.ranges.size() % 2 == 0;
  sensors::LaserScanData turned;
  if (turn) turned = halfTurn(device_scan);
  const sensors::LaserScanData& scan = turn ? turned : device_scan;
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

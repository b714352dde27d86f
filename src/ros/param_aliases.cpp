#include "amigobot_tracking/ros/param_aliases.h"

#include <algorithm>
#include <cctype>

#include <ros/console.h>

namespace amigobot_tracking {
namespace ros_layer {

const std::vector<ParamAlias>& rosAriaAliases() {
  // RosAria's private parameter names (odom_frame, port and baud are the same names).
  static const std::vector<ParamAlias> aliases = {{"TicksMM", "ticks_mm", "RosAria"},
                                                  {"DriftFactor", "drift_factor", "RosAria"},
                                                  {"RevCount", "rev_count", "RosAria"},
                                                  {"base_link_frame", "base_frame", "RosAria"}};
  return aliases;
}

const std::vector<ParamAlias>& laserAliases() {
  // frame_id, angle_min/max (urg_node), range_min/max, time_offset (urg_node, sick_tim) are
  // the same names. urg_node's serial_baud is not carried: a USB URG has no speed to choose.
  static const std::vector<ParamAlias> aliases = {
      {"serial_port", "port", "urg_node and rplidar_ros"},
      {"serial_baudrate", "baud", "rplidar_ros"},  // 115200 | 256000, as ours
      {"inverted", "upside_down", "rplidar_ros"},  // both mirror the scan
      {"min_ang", "angle_min", "sick_tim"},        // [rad] first beam published
      {"max_ang", "angle_max", "sick_tim"},
  };
  return aliases;
}

const std::vector<ParamAlias>& localizationAliases() {
  // mode (mapping | localization), base_frame, odom_frame, resolution (slam_toolbox) and
  // transform_tolerance, use_map_topic (amcl) are the same names.
  static const std::vector<ParamAlias> aliases = {
      {"initial_pose_x", "initial_pose/x", "amcl"},
      {"initial_pose_y", "initial_pose/y", "amcl"},
      {"initial_pose_a", "initial_pose/yaw", "amcl"},
      {"global_frame_id", "global_frame", "amcl"},
      {"map_frame", "global_frame", "slam_toolbox"},
      {"odom_frame_id", "odom_frame", "amcl"},
      {"base_frame_id", "base_frame", "amcl"},
      {"update_min_d", "min_travel", "amcl"},  // [m] travel before the next scan is matched
      {"minimum_travel_distance", "min_travel", "slam_toolbox"},
      {"update_min_a", "min_rotation", "amcl"},  // [rad]
      {"minimum_travel_heading", "min_rotation", "slam_toolbox"},
      {"map_update_interval", "map_publish_period", "slam_toolbox"},  // [s]
      {"max_laser_range", "range_max", "slam_toolbox"},               // [m] farther echoes unused
  };
  return aliases;
}

namespace {

bool allDigits(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

// ~host_key (+ the TCP port) into *port as "HOST:PORT", unless our ~port was given.
std::string joinAddress(const ros::NodeHandle& pnh, const std::string& host_key, const std::string& tcp_port,
                        bool own_port_set, const std::string& names, std::string* port) {
  bool present = false;
  core::FieldValue host;
  const std::string error = readParamValue(pnh, host_key, core::FieldType::kText, &present, &host);
  if (!error.empty() || !present) return error;
  const std::string text = std::get<std::string>(host);
  if (text.empty()) return "";  // urg_node's "" means: use serial_port
  if (own_port_set) {
    ROS_WARN_STREAM_NAMED("params", "~" << host_key << " (" << names << ") ignored: ~port is set too ('" << *port << "')");
    return "";
  }
  *port = text + ":" + tcp_port;
  ROS_INFO_STREAM_NAMED("params", "  " << pnh.resolveName("port") << " = " << *port << " (from " << names << ")");
  return "";
}

}  // namespace

std::string readSplitLaserAddress(const ros::NodeHandle& pnh, std::string* port) {
  const bool own_port_set = pnh.hasParam("port");
  // urg_node: ip_address + ip_port (an integer).
  bool present = false;
  core::FieldValue ip_port = 10940;
  std::string error = readParamValue(pnh, "ip_port", core::FieldType::kInteger, &present, &ip_port);
  if (!error.empty()) return error;
  const int tcp = std::get<int>(ip_port);
  if (tcp < 1 || tcp > 65535) return "~ip_port: must be in [1, 65535], got " + std::to_string(tcp);
  error = joinAddress(pnh, "ip_address", std::to_string(tcp), own_port_set, "urg_node's ~ip_address and ~ip_port", port);
  if (!error.empty()) return error;
  // sick_tim: hostname + its ~port, digits only (ours is a device or HOST:PORT, never digits).
  const bool sick_port = own_port_set && allDigits(*port);
  return joinAddress(pnh, "hostname", sick_port ? *port : "2112", own_port_set && !sick_port,
                     "sick_tim's ~hostname and ~port", port);
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

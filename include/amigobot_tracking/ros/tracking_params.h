// Parameters of the tracking nodelet: plain structs with SI defaults and validate(), and
// one loader per struct that reads the private namespace and logs every value.
// A loader returns "" or an error naming the parameter; the nodelet refuses to start on
// any error, so nothing is ever enabled with a bad configuration.
#pragma once

#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "amigobot_tracking/core/law/controller_config.h"
#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/core/perception/obstacle_tracker.h"
#include "amigobot_tracking/core/perception/scan_obstacles.h"
#include "amigobot_tracking/core/perception/virtual_obstacles.h"
#include "amigobot_tracking/ros/robot_source.h"

namespace amigobot_tracking {
namespace ros_layer {

// Frames (REP 105), the node's own timing and safety settings, and where the URDF is.
// Defaults and meanings: trackingNodeFields().
struct TrackingNodeConfig {
  std::string global_frame = "map";
  std::string base_frame = "base_link";
  std::string target_frame = "target";
  double control_rate = 20.0;
  double pose_timeout = 0.5;
  double scan_timeout = 0.5;
  double future_stamp_tolerance = 0.1;  // [s] a stamp further ahead of the receiver's clock is stale
  bool require_scan = true;
  // A laser that sees nothing, or fewer scans than it promises (core/perception/scan_health.h).
  bool open_space = false;              // true: a scan without any return is an empty room, not a blind laser
  double min_scan_rate_fraction = 0.7;  // [-] measured / promised scan rate below this stops (0 = off)
  double expected_scan_rate = 0.0;      // [Hz] > 0: the laser's rate, instead of each scan's scan_time
  bool autostart = false;
  double clicked_point_radius = 0.2;
  RobotSource robot;  // ~robot_model / ~robot_params: the robot description (ros/robot_source.h)
  // Read by loadNodeConfig from `robot` (not a parameter): the diamond tracking's own v_max,
  // w_max default to and never exceed, and the ceiling the supervisor explains motion with.
  aria::RobotParams description;
  double target_exclusion_radius = 0.0;
  // Resume ramp (core/supervision/resume_ramp.h): after a zero command of the nodelet's own (inputs lost,
  // disabled, a refused step) the command grows by at most these per second; stops are
  // immediate. Defaults: the AmigoBot firmware's accelerations (config/robots/amigo.yaml).
  double resume_v_accel = 0.3;
  double resume_w_accel = 1.745;
  std::string robot_description_param = "robot_description";
  std::string urdf_offset_link = "control_point";

  // "" or "key: reason" (the table's bounds, non-empty and distinct frames).
  std::string validate() const;
};

const core::FieldTable<TrackingNodeConfig>& trackingNodeFields();

// Robot geometry read from the URDF (robot_description) with urdfdom.
struct UrdfGeometry {
  bool found_radius = false;  // base_frame link has a cylinder/box/sphere collision or visual
  double radius = 0.0;        // [m] footprint radius
  bool found_offset = false;  // a link `offset_link` fixed to base_frame
  double offset = 0.0;        // [m] its x distance ahead of base_frame
};

// Parses URDF xml. Returns "" or why the xml could not be used (unparsable, no such link).
std::string readUrdfGeometry(const std::string& xml, const std::string& base_link, const std::string& offset_link,
                             UrdfGeometry* out);

// The robot's limits were node parameters once; now they live in the robot file. Names the
// file when ~robot_v_max or ~robot_w_max is still set (refused: a value there would widen
// nothing and hide where the limit is), else "".
std::string retiredRobotLimitError(const ros::NodeHandle& pnh, const TrackingNodeConfig& node);
// Loaders: read ~params over the struct's defaults through param_reader.h, log every value,
// return "" or "~key: reason" (wrong type, bounds, or the struct's validate()).
std::string loadNodeConfig(const ros::NodeHandle& pnh, TrackingNodeConfig* config);
// robot_radius and offset: ~robot_radius/~offset if set, else the URDF on the parameter
// server (node.robot_description_param), else the defaults;
// the log says which.
std::string loadControllerConfig(const ros::NodeHandle& pnh, const TrackingNodeConfig& node,
                                 core::ControllerConfig* config);
// "" when the diamond (v_max, w_max) lies inside the robot's (node.description: its robot
// file's v_max, w_max, the driver's diamond), else "v_max: must be <= the robot's v_max ...".
// The one rule for the start-up parameters and a live reconfigure.
std::string robotLimitError(const TrackingNodeConfig& node, const core::ControllerConfig& config);
std::string loadScanObstacleConfig(const ros::NodeHandle& pnh, core::ScanObstacleConfig* config);
std::string loadObstacleTrackerConfig(const ros::NodeHandle& pnh, core::ObstacleTrackerConfig* config);
// ~virtual_obstacles: a list of {id: str, center: [x, y], radius: r} in global_frame.
std::string loadVirtualObstacles(const ros::NodeHandle& pnh, std::vector<core::VirtualObstacle>* list);

}  // namespace ros_layer
}  // namespace amigobot_tracking

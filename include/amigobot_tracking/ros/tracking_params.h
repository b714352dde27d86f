// Parameters of the tracking nodelet: plain structs with SI defaults and validate(), and
// one loader per struct that reads the private namespace and logs every value.
// A loader returns "" or an error naming the parameter; the nodelet refuses to start on
// any error, so nothing is ever enabled with a bad configuration.
#pragma once

#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "amigobot_tracking/core/controller_config.h"
#include "amigobot_tracking/core/obstacle_tracker.h"
#include "amigobot_tracking/core/scan_obstacles.h"
#include "amigobot_tracking/core/virtual_obstacles.h"

namespace amigobot_tracking {
namespace ros_layer {

// Frames (REP 105) and the node's own timing and safety settings.
struct TrackingNodeConfig {
  std::string global_frame = "map";      // frame of poses, obstacles, markers
  std::string base_frame = "base_link";  // the robot (REP 105)
  std::string target_frame = "target";   // the tracked target (another robot, or the reference publisher)
  double control_rate = 20.0;            // [Hz] control timer
  double pose_timeout = 0.5;             // [s] older robot pose or target -> zero command
  double scan_timeout = 0.5;             // [s] older scan -> zero command (when require_scan)
  bool require_scan = true;              // false: run on virtual obstacles alone (no laser)
  bool autostart = false;                // enable tracking at start
  double clicked_point_radius = 0.2;     // [m] radius of a disk added by rviz "Publish Point"
  double robot_v_max = 1.0;              // [m/s] the robot's own limit: v_max never exceeds it
  double robot_w_max = 5.24;             // [rad/s] the robot's own limit (ARIA: 300 deg/s)
  // [m] laser disks whose centre is this close to the target are the target itself (another
  // robot being followed), not obstacles; 0 = off. Never applied to virtual obstacles.
  double target_exclusion_radius = 0.0;
  // Resume ramp (core/resume_ramp.h): after a zero command of the nodelet's own (inputs lost,
  // disabled, a refused step) the command grows by at most these per second; stops are
  // immediate. Defaults: the AmigoBot firmware's accelerations (config/robots/amigo.yaml).
  double resume_v_accel = 0.3;    // [m/s^2]
  double resume_w_accel = 1.745;  // [rad/s^2]

  std::string validate() const;
};

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

// Loaders: read ~params over the struct's defaults, log every value, return "" or an error
// naming the parameter (wrong type, or the struct's validate()).
std::string loadNodeConfig(const ros::NodeHandle& pnh, TrackingNodeConfig* config);
// robot_radius and offset: ~robot_radius/~offset if set, else the URDF on the parameter
// server (~robot_description_param, default "robot_description"), else the defaults;
// the log says which.
std::string loadControllerConfig(const ros::NodeHandle& pnh, const TrackingNodeConfig& node,
                                 core::ControllerConfig* config);
std::string loadScanObstacleConfig(const ros::NodeHandle& pnh, core::ScanObstacleConfig* config);
std::string loadObstacleTrackerConfig(const ros::NodeHandle& pnh, core::ObstacleTrackerConfig* config);
// ~virtual_obstacles: a list of {id: str, center: [x, y], radius: r} in global_frame.
std::string loadVirtualObstacles(const ros::NodeHandle& pnh, std::vector<core::VirtualObstacle>* list);

}  // namespace ros_layer
}  // namespace amigobot_tracking

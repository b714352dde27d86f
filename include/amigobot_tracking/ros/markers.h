// rviz markers of one control step (`~markers`). Built only while someone subscribes.
#pragma once

#include <string>
#include <vector>

#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/core/perception/virtual_obstacles.h"

namespace amigobot_tracking {
namespace ros_layer {

struct MarkerScene {
  std::string frame;                           // global_frame
  ros::Time stamp;
  bool have_pose = false;
  core::Pose2 pose;                            // robot centre
  bool have_output = false;                    // the controller ran this step
  core::ControllerOutput output;
  const core::ControllerConfig* config = nullptr;
  const std::vector<core::Disk>* detected = nullptr;          // laser disks
  const core::VirtualObstacleSet* virtual_obstacles = nullptr;
  std::string status;                          // shown in the text line
};

// Marker building blocks (also world_markers.h).
std_msgs::ColorRGBA markerColor(float r, float g, float b, float a = 1.0f);
geometry_msgs::Point markerPoint(const Eigen::Vector2d& p, double z = 0.0);


// The first marker is DELETEALL (in global_frame), so obstacles that disappeared vanish from
// rviz. Ids count from 0 within each namespace. Namespaces: rho, target, target_velocity,
// offset_point, body, safety_disk, laser_obstacles, virtual_obstacles, virtual_obstacle_ids,
// u_c, diamond, diamond_u, diamond_u_d, text (status line), legend (what the shapes mean).
visualization_msgs::MarkerArray buildMarkers(const MarkerScene& scene);

}  // namespace ros_layer
}  // namespace amigobot_tracking

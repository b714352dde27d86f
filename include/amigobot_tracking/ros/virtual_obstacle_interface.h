// The operator's virtual obstacles in ROS: the `~virtual_obstacle` topic (add or move by
// id), rviz "Publish Point" on `clicked_point`, interactive markers on `~obstacle_markers`
// (drag to move, right click -> Delete), the `~remove_virtual_obstacle` and
// `~clear_virtual_obstacles` services, and the latched `~virtual_obstacles` array.
// Callbacks edit the set under this class's own mutex; the control cycle takes a snapshot.
// `~virtual_obstacle` holds a burst of 10,000 messages; what it adds is published every 0.1 s.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <geometry_msgs/PointStamped.h>
#include <interactive_markers/interactive_marker_server.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>

#include "amigobot_tracking/RemoveVirtualObstacle.h"
#include "amigobot_tracking/VirtualObstacle.h"
#include "amigobot_tracking/core/perception/virtual_obstacles.h"

namespace amigobot_tracking {
namespace ros_layer {

class VirtualObstacleInterface {
 public:
  // Obstacles live in `global_frame`; clicked points in other frames go through `tf`.
  // `initial` must be valid (loadVirtualObstacles checked it). Publishes the latched array.
  VirtualObstacleInterface(ros::NodeHandle nh, ros::NodeHandle pnh, tf2_ros::Buffer& tf, std::string global_frame,
                           double clicked_point_radius, const std::vector<core::VirtualObstacle>& initial);
  VirtualObstacleInterface(const VirtualObstacleInterface&) = delete;
  VirtualObstacleInterface& operator=(const VirtualObstacleInterface&) = delete;

  // Appends the disks as they are now to *out (the control cycle's obstacle list).
  void appendDisks(std::vector<core::Disk>* out) const;
  // The set as it is now (for the markers).
  core::VirtualObstacleSet snapshot() const;

 private:
  void onObstacle(const VirtualObstacle::ConstPtr& msg);
  void onClickedPoint(const geometry_msgs::PointStamped::ConstPtr& msg);
  void onMarkerFeedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback);
  bool onRemove(RemoveVirtualObstacle::Request& req, RemoveVirtualObstacle::Response& res);
  bool onClear(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  // With mutex_ held: latched array, and the interactive markers unless rviz already shows them.
  void publishLocked(bool refresh_interactive = true);

  tf2_ros::Buffer& tf_;
  const std::string global_frame_;
  const double clicked_point_radius_;
  mutable std::mutex mutex_;
  core::VirtualObstacleSet set_;
  ros::Publisher array_pub_;
  std::unique_ptr<interactive_markers::InteractiveMarkerServer> marker_server_;
  bool changed_ = false;  // ~virtual_obstacle edited the set since the last publishLocked
  ros::WallTimer publish_timer_;
  ros::Subscriber obstacle_sub_, clicked_sub_;
  ros::ServiceServer remove_srv_, clear_srv_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking

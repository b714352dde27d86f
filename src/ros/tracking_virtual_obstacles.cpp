// TrackingNode, virtual obstacles: the latched set, the topic, rviz clicked_point, the
// interactive markers (drag to move, right click -> Delete) and the remove/clear services.
#include <cmath>

#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <visualization_msgs/InteractiveMarker.h>

#include "amigobot_tracking/VirtualObstacleArray.h"
#include "amigobot_tracking/ros/tracking_node.h"

namespace amigobot_tracking {
namespace ros_layer {
namespace {

constexpr uint8_t kDeleteMenuEntry = 1;

visualization_msgs::InteractiveMarker interactiveMarkerOf(const core::VirtualObstacle& o, const std::string& frame) {
  visualization_msgs::InteractiveMarker im;
  im.header.frame_id = frame;
  im.name = o.id;
  im.description = o.id;
  im.pose.position.x = o.disk.center.x();
  im.pose.position.y = o.disk.center.y();
  im.pose.orientation.w = 1.0;
  im.scale = static_cast<float>(2.0 * o.disk.radius + 0.2);

  visualization_msgs::Marker disk;
  disk.type = visualization_msgs::Marker::CYLINDER;
  disk.scale.x = disk.scale.y = 2.0 * o.disk.radius;
  disk.scale.z = 0.3;
  disk.pose.position.z = 0.15;
  disk.pose.orientation.w = 1.0;
  disk.color.r = 0.6f;
  disk.color.g = 0.2f;
  disk.color.b = 0.8f;
  disk.color.a = 0.5f;

  visualization_msgs::InteractiveMarkerControl move;  // drag in the ground plane
  move.name = "move";
  move.orientation.w = move.orientation.y = std::sqrt(0.5);
  move.interaction_mode = visualization_msgs::InteractiveMarkerControl::MOVE_PLANE;
  move.always_visible = true;
  move.markers.push_back(disk);
  im.controls.push_back(move);

  visualization_msgs::InteractiveMarkerControl menu;  // right click -> Delete
  menu.name = "menu";
  menu.interaction_mode = visualization_msgs::InteractiveMarkerControl::MENU;
  im.controls.push_back(menu);
  visualization_msgs::MenuEntry remove;
  remove.id = kDeleteMenuEntry;
  remove.parent_id = 0;
  remove.title = "Delete";
  remove.command_type = visualization_msgs::MenuEntry::FEEDBACK;
  im.menu_entries.push_back(remove);
  return im;
}

}  // namespace

void TrackingNode::publishVirtualObstaclesLocked(bool refresh_interactive) {
  VirtualObstacleArray array;
  array.header.stamp = ros::Time::now();
  array.header.frame_id = node_config_.global_frame;
  for (const core::VirtualObstacle& o : virtual_obstacles_.all()) {
    VirtualObstacle m;
    m.id = o.id;
    m.center.x = o.disk.center.x();
    m.center.y = o.disk.center.y();
    m.radius = o.disk.radius;
    array.obstacles.push_back(m);
  }
  virtual_pub_.publish(array);
  if (!refresh_interactive || !marker_server_) return;
  marker_server_->clear();
  for (const core::VirtualObstacle& o : virtual_obstacles_.all()) {
    marker_server_->insert(interactiveMarkerOf(o, node_config_.global_frame),
                           [this](const visualization_msgs::InteractiveMarkerFeedbackConstPtr& f) { onMarkerFeedback(f); });
  }
  marker_server_->applyChanges();
}

void TrackingNode::onVirtualObstacle(const VirtualObstacle::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  const core::VirtualObstacle o{msg->id, {{msg->center.x, msg->center.y}, msg->radius}};
  std::string why;
  const auto change = virtual_obstacles_.upsert(o, &why);
  if (change == core::VirtualObstacleSet::Change::kRejected) {
    ROS_WARN_STREAM_NAMED("tracking", "virtual obstacle rejected: " << why);
    return;
  }
  ROS_INFO_STREAM_NAMED("tracking", "virtual obstacle '" << o.id << "' "
                                                         << (change == core::VirtualObstacleSet::Change::kAdded ? "added" : "updated"));
  publishVirtualObstaclesLocked();
}

void TrackingNode::onClickedPoint(const geometry_msgs::PointStamped::ConstPtr& msg) {
  geometry_msgs::PointStamped global = *msg;
  if (msg->header.frame_id != node_config_.global_frame) {
    try {
      const geometry_msgs::TransformStamped to_global =
          tf_->lookupTransform(node_config_.global_frame, msg->header.frame_id, ros::Time(0));
      tf2::doTransform(*msg, global, to_global);
    } catch (const tf2::TransformException& ex) {
      ROS_WARN_STREAM_NAMED("tracking", "clicked point ignored: " << ex.what());
      return;
    }
  }
  std::lock_guard<std::mutex> lock(state_mutex_);
  const core::VirtualObstacle o{virtual_obstacles_.freshId("click_"),
                                {{global.point.x, global.point.y}, node_config_.clicked_point_radius}};
  std::string why;
  if (virtual_obstacles_.upsert(o, &why) == core::VirtualObstacleSet::Change::kRejected) {
    ROS_WARN_STREAM_NAMED("tracking", "clicked point rejected: " << why);
    return;
  }
  ROS_INFO_STREAM_NAMED("tracking", "virtual obstacle '" << o.id << "' added at (" << o.disk.center.x() << ", "
                                                         << o.disk.center.y() << ")");
  publishVirtualObstaclesLocked();
}

void TrackingNode::onMarkerFeedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback) {
  using visualization_msgs::InteractiveMarkerFeedback;
  std::lock_guard<std::mutex> lock(state_mutex_);
  const core::VirtualObstacle* existing = virtual_obstacles_.find(feedback->marker_name);
  if (!existing) return;
  if (feedback->event_type == InteractiveMarkerFeedback::MENU_SELECT && feedback->menu_entry_id == kDeleteMenuEntry) {
    virtual_obstacles_.remove(feedback->marker_name);
    ROS_INFO_STREAM_NAMED("tracking", "virtual obstacle '" << feedback->marker_name << "' deleted in rviz");
    publishVirtualObstaclesLocked();
  } else if (feedback->event_type == InteractiveMarkerFeedback::POSE_UPDATE &&
             (feedback->header.frame_id.empty() || feedback->header.frame_id == node_config_.global_frame)) {
    core::VirtualObstacle moved = *existing;
    moved.disk.center = {feedback->pose.position.x, feedback->pose.position.y};
    virtual_obstacles_.upsert(moved);
    publishVirtualObstaclesLocked(false);  // rviz already shows it where it was dragged
  }
}

bool TrackingNode::onRemove(RemoveVirtualObstacle::Request& req, RemoveVirtualObstacle::Response& res) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  res.success = virtual_obstacles_.remove(req.id);
  res.message = res.success ? "removed '" + req.id + "'" : "no virtual obstacle '" + req.id + "'";
  if (res.success) publishVirtualObstaclesLocked();
  return true;
}

bool TrackingNode::onClear(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  const std::size_t count = virtual_obstacles_.size();
  virtual_obstacles_.clear();
  publishVirtualObstaclesLocked();
  res.success = true;
  res.message = "cleared " + std::to_string(count) + " virtual obstacles";
  return true;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

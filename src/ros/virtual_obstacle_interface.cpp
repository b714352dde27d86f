#include "amigobot_tracking/ros/virtual_obstacle_interface.h"

#include <cmath>
#include <utility>

#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <visualization_msgs/InteractiveMarker.h>

#include "amigobot_tracking/VirtualObstacleArray.h"

namespace amigobot_tracking {
namespace ros_layer {
namespace {

constexpr uint8_t kDeleteMenuEntry = 1;
// ~virtual_obstacle's subscriber queue: a script may publish a whole course of obstacles in
// one burst, and a queue of 10 kept 72 of 2000. The callback only edits the set (the array
// and the markers go out at most every kPublishPeriod), so a burst this long is held.
constexpr uint32_t kObstacleQueue = 10000;
constexpr double kPublishPeriod = 0.1;  // [s]

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

VirtualObstacleInterface::VirtualObstacleInterface(ros::NodeHandle nh, ros::NodeHandle pnh, tf2_ros::Buffer& tf,
                                                   std::string global_frame, double clicked_point_radius,
                                                   const std::vector<core::VirtualObstacle>& initial)
    : tf_(tf), global_frame_(std::move(global_frame)), clicked_point_radius_(clicked_point_radius) {
  set_.assign(initial);
  array_pub_ = pnh.advertise<VirtualObstacleArray>("virtual_obstacles", 1, true);
  marker_server_ = std::make_unique<interactive_markers::InteractiveMarkerServer>(pnh.resolveName("obstacle_markers"));
  {
    std::lock_guard<std::mutex> lock(mutex_);
    publishLocked();
  }
  obstacle_sub_ = pnh.subscribe("virtual_obstacle", kObstacleQueue, &VirtualObstacleInterface::onObstacle, this);
  // Re-publishing the whole set per message made a burst quadratic (2000 arrays of up to 2000).
  publish_timer_ = pnh.createWallTimer(ros::WallDuration(kPublishPeriod), [this](const ros::WallTimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!changed_) return;
    changed_ = false;
    publishLocked();
  });
  clicked_sub_ = nh.subscribe("clicked_point", 10, &VirtualObstacleInterface::onClickedPoint, this);
  remove_srv_ = pnh.advertiseService("remove_virtual_obstacle", &VirtualObstacleInterface::onRemove, this);
  clear_srv_ = pnh.advertiseService("clear_virtual_obstacles", &VirtualObstacleInterface::onClear, this);
}

void VirtualObstacleInterface::appendDisks(std::vector<core::Disk>* out) const {
  std::lock_guard<std::mutex> lock(mutex_);
  set_.appendDisks(out);
}

core::VirtualObstacleSet VirtualObstacleInterface::snapshot() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return set_;
}

void VirtualObstacleInterface::publishLocked(bool refresh_interactive) {
  changed_ = false;
  VirtualObstacleArray array;
  array.header.stamp = ros::Time::now();
  array.header.frame_id = global_frame_;
  for (const core::VirtualObstacle& o : set_.all()) {
    VirtualObstacle m;
    m.id = o.id;
    m.center.x = o.disk.center.x();
    m.center.y = o.disk.center.y();
    m.radius = o.disk.radius;
    array.obstacles.push_back(m);
  }
  array_pub_.publish(array);
  if (!refresh_interactive || !marker_server_) return;
  marker_server_->clear();
  for (const core::VirtualObstacle& o : set_.all()) {
    marker_server_->insert(interactiveMarkerOf(o, global_frame_),
                           [this](const visualization_msgs::InteractiveMarkerFeedbackConstPtr& f) { onMarkerFeedback(f); });
  }
  marker_server_->applyChanges();
}

void VirtualObstacleInterface::onObstacle(const VirtualObstacle::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  const core::VirtualObstacle o{msg->id, {{msg->center.x, msg->center.y}, msg->radius}};
  std::string why;
  const auto change = set_.upsert(o, &why);
  if (change == core::VirtualObstacleSet::Change::kRejected) {
    ROS_WARN_STREAM_NAMED("tracking", "virtual obstacle rejected: " << why);
    return;
  }
  ROS_INFO_STREAM_NAMED("tracking", "virtual obstacle '" << o.id << "' "
                                                         << (change == core::VirtualObstacleSet::Change::kAdded ? "added" : "updated"));
  changed_ = true;  // published by publish_timer_
}

void VirtualObstacleInterface::onClickedPoint(const geometry_msgs::PointStamped::ConstPtr& msg) {
  geometry_msgs::PointStamped global = *msg;
  if (msg->header.frame_id != global_frame_) {
    try {
      const geometry_msgs::TransformStamped to_global =
          tf_.lookupTransform(global_frame_, msg->header.frame_id, ros::Time(0));
      tf2::doTransform(*msg, global, to_global);
    } catch (const tf2::TransformException& ex) {
      ROS_WARN_STREAM_NAMED("tracking", "clicked point ignored: " << ex.what());
      return;
    }
  }
  std::lock_guard<std::mutex> lock(mutex_);
  const core::VirtualObstacle o{set_.freshId("click_"),
                                {{global.point.x, global.point.y}, clicked_point_radius_}};
  std::string why;
  if (set_.upsert(o, &why) == core::VirtualObstacleSet::Change::kRejected) {
    ROS_WARN_STREAM_NAMED("tracking", "clicked point rejected: " << why);
    return;
  }
  ROS_INFO_STREAM_NAMED("tracking", "virtual obstacle '" << o.id << "' added at (" << o.disk.center.x() << ", "
                                                         << o.disk.center.y() << ")");
  publishLocked();
}

void VirtualObstacleInterface::onMarkerFeedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback) {
  using visualization_msgs::InteractiveMarkerFeedback;
  std::lock_guard<std::mutex> lock(mutex_);
  const core::VirtualObstacle* existing = set_.find(feedback->marker_name);
  if (!existing) return;
  if (feedback->event_type == InteractiveMarkerFeedback::MENU_SELECT && feedback->menu_entry_id == kDeleteMenuEntry) {
    set_.remove(feedback->marker_name);
    ROS_INFO_STREAM_NAMED("tracking", "virtual obstacle '" << feedback->marker_name << "' deleted in rviz");
    publishLocked();
  } else if (feedback->event_type == InteractiveMarkerFeedback::POSE_UPDATE &&
             (feedback->header.frame_id.empty() || feedback->header.frame_id == global_frame_)) {
    core::VirtualObstacle moved = *existing;
    moved.disk.center = {feedback->pose.position.x, feedback->pose.position.y};
    set_.upsert(moved);
    publishLocked(false);  // rviz already shows it where it was dragged
  }
}

bool VirtualObstacleInterface::onRemove(RemoveVirtualObstacle::Request& req, RemoveVirtualObstacle::Response& res) {
  std::lock_guard<std::mutex> lock(mutex_);
  res.success = set_.remove(req.id);
  res.message = res.success ? "removed '" + req.id + "'" : "no virtual obstacle '" + req.id + "'";
  if (res.success) publishLocked();
  return true;
}

bool VirtualObstacleInterface::onClear(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  std::lock_guard<std::mutex> lock(mutex_);
  const std::size_t count = set_.size();
  set_.clear();
  publishLocked();
  res.success = true;
  res.message = "cleared " + std::to_string(count) + " virtual obstacles";
  return true;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

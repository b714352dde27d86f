// The Localization nodelet's maps in and out: `map` and `map_metadata` published (latched, as
// map_server), a map_server's map taken from `map` (use_map_topic, as amcl), and the map saved
// by ~save_map (to ~map_file) or ~save_map_to (to a path), creating the folder.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "amigobot_tracking/ros/localization_messages.h"
#include "amigobot_tracking/ros/localization_node.h"

namespace amigobot_tracking {
namespace ros_layer {

std::string mapFolderProblem(const std::string& yaml_path) {
  namespace fs = std::filesystem;
  if (yaml_path.empty()) return "empty path";
  std::error_code ec;
  const fs::path folder = fs::absolute(fs::path(yaml_path), ec).parent_path();
  if (ec) return "cannot resolve the path: " + ec.message();
  // The nearest folder that exists must be a folder we may write in: the rest is created.
  fs::path existing = folder;
  while (!fs::exists(existing, ec) && existing.has_parent_path() && existing != existing.parent_path())
    existing = existing.parent_path();
  if (!fs::is_directory(existing, ec))
    return "cannot create the folder " + folder.string() + ": " + existing.string() + " is not a folder";
  if (::access(existing.c_str(), W_OK | X_OK) != 0) {
    const std::string why = std::strerror(errno);
    return existing == folder ? "cannot write in the folder " + folder.string() + ": " + why
                              : "cannot create the folder " + folder.string() + " in " + existing.string() + ": " + why;
  }
  return "";
}

void LocalizationNode::publishMap(const localization::OccupancyMap& map) {
  if (map.empty() || config_.use_map_topic) return;  // a map_server owns the map topic then
  nav_msgs::OccupancyGrid msg;
  msg.header.stamp = ros::Time::now();
  msg.header.frame_id = config_.global_frame;
  msg.info.map_load_time = msg.header.stamp;
  toOccupancyGrid(map, &msg);
  map_pub_.publish(msg);
  map_metadata_pub_.publish(msg.info);
}

void LocalizationNode::onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
  localization::OccupancyMap map;
  const std::string problem = fromOccupancyGrid(*msg, &map);
  if (problem.empty() && !msg->header.frame_id.empty() && msg->header.frame_id != config_.global_frame) {
    ROS_ERROR_STREAM_NAMED("localization", "map from " << map_sub_.getTopic() << " refused: frame '" << msg->header.frame_id
                                                       << "' is not the global_frame '" << config_.global_frame << "'");
    return;
  }
  if (!problem.empty()) {
    ROS_ERROR_STREAM_NAMED("localization", "map from " << map_sub_.getTopic() << " refused: " << problem);
    return;
  }
  {
    std::lock_guard<std::mutex> engine(engine_mutex_);
    std::unique_ptr<localization::Engine> next = localization::makeEngine(config_, map);
    // A newer map: the robot has not moved, so the pose carries over (initial_pose at first).
    if (engine_ && last_work_) next->setPose(engine_->estimate().pose, last_work_->odom_base);
    engine_ = std::move(next);
    measures_match_ = engine_->measuresMatch();
  }
  ROS_INFO_STREAM_NAMED("localization", "map from " << map_sub_.getTopic() << ": " << map.width << " x " << map.height
                                                    << " cells of " << map.resolution << " m");
}

bool LocalizationNode::saveMapTo(const std::string& yaml_path, std::string* message) {
  localization::OccupancyMap map;
  {
    std::lock_guard<std::mutex> engine(engine_mutex_);
    *message = engine_ ? engine_->mapToSave(&map) : "nothing to save: no map yet on the map topic";
  }
  if (!message->empty()) return false;
  try {
    localization::saveMap(yaml_path, map);
    *message = "saved " + yaml_path + " (" + std::to_string(map.width) + " x " + std::to_string(map.height) + " cells)";
    publishMap(map);
    return true;
  } catch (const std::exception& e) {
    *message = e.what();
    return false;
  }
}

bool LocalizationNode::onSaveMap(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
  if (config_.map_file.empty()) {
    response.message = "~map_file is empty: no path to save the map to (~save_map_to takes one)";
  } else {
    response.success = saveMapTo(config_.map_file, &response.message);
  }
  ROS_INFO_STREAM_NAMED("localization", "~save_map: " << response.message);
  return true;
}

bool LocalizationNode::onSaveMapTo(SaveMap::Request& request, SaveMap::Response& response) {
  std::string path = request.path.empty() ? config_.map_file : request.path;
  const std::string suffix = ".yaml";
  if (!path.empty() && (path.size() < suffix.size() || path.compare(path.size() - suffix.size(), suffix.size(), suffix) != 0))
    path += suffix;  // map_saver -f NAME writes NAME.yaml and NAME.pgm
  if (path.empty()) {
    response.message = "no path given and ~map_file is empty";
  } else {
    response.success = saveMapTo(path, &response.message);
  }
  ROS_INFO_STREAM_NAMED("localization", "~save_map_to: " << response.message);
  return true;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

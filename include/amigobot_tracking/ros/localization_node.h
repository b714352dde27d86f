// ROS wiring of the localisation layer (nodelet amigobot_tracking/Localization, node
// localization_node): scans through a tf2 MessageFilter (odom -> laser at the scan's stamp),
// odometry from tf odom -> base; each scan is handed to a worker thread that runs the
// localisation Engine of the mode (engine.h: on map_file, or mapping), never asking which. A tf
// thread publishes map -> odom at tf_rate, stamped transform_tolerance ahead (as amcl does),
// so lookups at "now" succeed between scans. Publishes `map` and `map_metadata` (latched, as
// map_server; mapping: every map_publish_period), ~pose and /diagnostics; takes /initialpose
// and, with use_map_topic, the map from `map` (as amcl); serves ~save_map, ~save_map_to and
// ~global_localization.
#pragma once

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <message_filters/subscriber.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_srvs/Empty.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/message_filter.h>
#include <tf2_ros/transform_broadcaster.h>

#include "amigobot_tracking/SaveMap.h"
#include "amigobot_tracking/localization/engine.h"
#include "amigobot_tracking/ros/guarded_tf_listener.h"
#include "amigobot_tracking/ros/rate_monitor.h"
#include "amigobot_tracking/ros/refusal_log.h"
#include "amigobot_tracking/ros/stamp_gate.h"

namespace amigobot_tracking {
namespace ros_layer {

// Reads the private parameters; throws std::runtime_error naming the bad one.
localization::LocalizationConfig loadLocalizationConfig(const ros::NodeHandle& pnh);
// Why a map could not be saved to yaml_path's folder (not a folder, or the nearest existing
// one not writable), naming it; "" when it exists writable or can be created.
std::string mapFolderProblem(const std::string& yaml_path);

class LocalizationNode {
 public:
  // Throws std::runtime_error naming a bad parameter or map file; then nothing is started.
  LocalizationNode(ros::NodeHandle nh, ros::NodeHandle pnh);
  ~LocalizationNode();
  LocalizationNode(const LocalizationNode&) = delete;
  LocalizationNode& operator=(const LocalizationNode&) = delete;

 private:
  struct Work {  // one scan for the worker
    localization::RangeScan scan;
    core::Pose2 odom_base;
    ros::Time stamp;
  };
  struct Output {  // what the publishers and diagnostics read
    bool ready = false;  // a map -> odom exists (after the first scan)
    localization::PoseEstimate estimate;
    std::uint64_t scans = 0, matches = 0, dropped = 0, relocalisations = 0;
    std::string last_error;
  };

  void onScan(const sensor_msgs::LaserScan::ConstPtr& msg);
  void onInitialPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg);
  bool onSaveMap(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  bool onSaveMapTo(SaveMap::Request& request, SaveMap::Response& response);
  // Writes the engine's map to yaml_path; false with *message saying why not.
  bool saveMapTo(const std::string& yaml_path, std::string* message);
  // use_map_topic: a map_server's map; the engine is made (or remade, keeping the pose) on it.
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg);
  bool onGlobalLocalization(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  // amcl's global_localization (std_srvs/Empty): the same search; the outcome is logged.
  bool onAmclGlobalLocalization(std_srvs::Empty::Request& request, std_srvs::Empty::Response& response);
  void workLoop();
  void tfLoop();
  void process(const Work& work);
  void publishTransform(const core::Pose2& map_to_odom);
  void publishPose(const ros::Time& stamp);
  // localization_status: ok when the last scan matched the map at the estimated pose (the
  // match is measured on every scan, at the pose the engine holds).
  void publishStatus(const ros::Time& stamp, const localization::PoseEstimate& estimate);
  // A pose the engine took out of turn (/initialpose, a global search): published at once.
  void poseJumped(const localization::PoseEstimate& estimate, bool relocalised);
  void publishMap(const localization::OccupancyMap& map);
  bool lookup(const std::string& parent, const std::string& child, const ros::Time& stamp, core::Pose2* out);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  localization::LocalizationConfig config_;
  ros::NodeHandle nh_, pnh_;
  tf2_ros::Buffer buffer_;
  // Judges every tf sample before buffer_ sees it (NaN, non-unit rotation, stamped ahead), as
  // the tracking node's: one sample stamped 30 s ahead would otherwise hide odom for 30 s.
  GuardedTfListener listener_;
  tf2_ros::TransformBroadcaster broadcaster_;
  StampGate tf_gate_;  // map -> odom only when its stamp advances (use_sim_time replays)
  message_filters::Subscriber<sensor_msgs::LaserScan> scan_sub_;
  std::unique_ptr<tf2_ros::MessageFilter<sensor_msgs::LaserScan>> filter_;
  ros::Subscriber initial_pose_sub_, map_sub_;
  ros::Publisher map_pub_, map_metadata_pub_, pose_pub_, status_pub_, amcl_pose_pub_;  // amcl_pose: ~pose under amcl's name
  ros::ServiceServer save_map_srv_, save_map_to_srv_, global_srv_, amcl_global_srv_;
  diagnostic_updater::Updater updater_;
  ros::Timer diagnostics_timer_;

  std::mutex engine_mutex_;  // guards the engine (worker, services, /initialpose)
  std::unique_ptr<localization::Engine> engine_;  // null until use_map_topic's first map
  std::atomic<bool> measures_match_{false};       // engine_->measuresMatch(), for diagnostics
  std::optional<Work> last_work_;  // the last scan processed, for ~global_localization
  double last_map_publish_ = -1.0;

  std::mutex mutex_;  // guards output_, pending_, rate_
  std::condition_variable wake_;
  std::optional<Work> pending_;
  RefusalLog scan_refusal_;  // onScan's only (the MessageFilter calls it on one thread)
  Output output_;
  std::unique_ptr<RateMonitor> rate_;

  std::atomic<bool> stop_{false};
  std::thread worker_, tf_thread_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking

// The tracking node: feeds core::TrackingLoop with tf2 poses, laser and virtual obstacles
// and publishes its cmd_vel. Hosted by the nodelet `amigobot_tracking/Tracking` and by the
// standalone `tracking_node`. Wiring only: the cycle (supervisor, controller, obstacle set,
// reconfigure swap) is core::TrackingLoop's; laser disks are LaserObstacles'; the
// operator's disks are VirtualObstacleInterface's; markers are buildMarkers'.
//
// Threads: callbacks only store their input (scan, virtual obstacle edits, reconfigure)
// under their own mutexes; the control timer does all the work under state_mutex_, on one
// snapshot of the inputs.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>

#include "amigobot_tracking/LocalizationStatus.h"
#include "amigobot_tracking/TrackingConfig.h"
#include "amigobot_tracking/core/supervision/input_age.h"
#include "amigobot_tracking/core/supervision/tracking_loop.h"
#include "amigobot_tracking/ros/checked_reconfigure.h"
#include "amigobot_tracking/ros/guarded_tf_listener.h"
#include "amigobot_tracking/ros/laser_obstacles.h"
#include "amigobot_tracking/ros/rate_monitor.h"
#include "amigobot_tracking/ros/master_watch.h"
#include "amigobot_tracking/ros/tracking_params.h"
#include "amigobot_tracking/ros/tracking_statistics.h"
#include "amigobot_tracking/ros/virtual_obstacle_interface.h"

namespace amigobot_tracking {
namespace ros_layer {

class TrackingNode {
 public:
  // `tf` may be shared with the host (then the host feeds it and no clock is judged); null
  // creates a buffer and a GuardedTfListener (start(): it needs future_stamp_tolerance).
  TrackingNode(ros::NodeHandle nh, ros::NodeHandle pnh, std::shared_ptr<tf2_ros::Buffer> tf = nullptr);
  ~TrackingNode();
  TrackingNode(const TrackingNode&) = delete;
  TrackingNode& operator=(const TrackingNode&) = delete;

  // Loads and validates every parameter, then wires topics, services and the timer.
  // Throws std::runtime_error naming the parameter, and wires nothing, on error.
  void start();

  bool enabled() const;
  std::string status() const;  // "disabled", "tracking", or why the command is zero
  CycleStats cycleStats() const;

 private:
  struct Lookup {
    bool ok = false;
    geometry_msgs::TransformStamped transform;
    double age = 0.0;     // [s] on this node's clock (core/supervision/input_age.h)
    std::string problem;  // why the stamp is not trusted, or ""
    std::string clock;    // the publisher's clock is off (core/supervision/clock_offset.h), or ""
    std::string error;
  };
  // `age` tracks the stream's arrivals (a frozen transform ages even when stamped ahead).
  Lookup lookup(const std::string& frame, const ros::Time& now, core::InputAgeTracker* age) const;

  // One whole control cycle at `now`: tf lookups, the loop's step, publish.
  void controlCycle(const ros::Time& now);
  void onTimer(const ros::TimerEvent& event);
  void onLocalizationStatus(const amigobot_tracking::LocalizationStatus::ConstPtr& msg);
  bool onEnable(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  bool onDisable(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  // A live set of gains and limits: "" when taken (between two steps), else why refused.
  std::string onReconfigure(const TrackingConfig& requested);
  // ROS master unreachable longer than pose_timeout: tracking disabled (one zero command),
  // ~enable needed once a master answers (the watch registers everything with a new one).
  void checkMaster();
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  // With state_mutex_ held:
  core::TrackingLoopInputs loopInputsLocked(const ros::Time& now, const Lookup& pose, const Lookup& target);
  void publishLocked(const core::Twist2& u);  // cmd_vel
  void logStopLocked() const;                 // why the supervisor sent zero (throttled)
  void noteClocksLocked(const Lookup& pose, const Lookup& target);  // clock_warning_, WARN (throttled)
  void publishStateLocked(const ros::Time& now, const Lookup& pose, bool have_output,
                          const core::ControllerOutput& out);
  void publishMarkersLocked(const ros::Time& now, const Lookup& pose, bool have_output,
                            const core::ControllerOutput& out, const core::VirtualObstacleSet& virtuals);
  double sinceEpoch(const ros::Time& t) const { return (t - epoch_).toSec(); }

  ros::NodeHandle nh_, pnh_;
  std::shared_ptr<tf2_ros::Buffer> tf_;
  bool own_tf_ = false;                             // tf_ was created here: start() makes tf_listener_
  std::unique_ptr<GuardedTfListener> tf_listener_;  // null when the host feeds tf_

  TrackingNodeConfig node_config_;
  core::ScanObstacleConfig scan_config_;
  core::ObstacleTrackerConfig tracker_config_;
  bool started_ = false;

  // Everything the control cycle uses.
  mutable std::mutex state_mutex_;
  core::TrackingLoop loop_;  // holds the one ControllerConfig in use (and a pending one)
  std::unique_ptr<LaserObstacles> laser_;
  std::unique_ptr<VirtualObstacleInterface> virtual_obstacles_;
  std::vector<core::Disk> laser_disks_, virtual_disks_;  // this cycle's inputs of the loop
  std::size_t virtual_count_ = 0;      // of the last cycle's snapshot
  ros::Time epoch_;
  core::ControllerOutput last_output_;
  double last_pose_age_ = -1.0, last_target_age_ = -1.0, scan_age_ = -1.0;  // [s], -1: none
  std::string clock_warning_;  // a pose or target publisher's clock is off (core/supervision/clock_offset.h), or ""
  core::InputAgeTracker pose_age_, target_age_;
  TrackingStatistics stats_;
  std::unique_ptr<RateMonitor> control_rate_, cmd_vel_rate_;

  // localization_status (issue 25): "" while good or never heard of, else why not.
  mutable std::mutex localization_mutex_;
  std::string localization_problem_;
  ros::Subscriber localization_sub_;

  // ROS wiring (created by start()).
  ros::Publisher cmd_pub_, state_pub_, markers_pub_;
  ros::ServiceServer enable_srv_, disable_srv_;
  std::unique_ptr<CheckedReconfigure<TrackingConfig>> reconfigure_;
  std::unique_ptr<diagnostic_updater::Updater> diagnostics_;
  ros::Timer timer_;
  ros::WallTimer master_timer_;
  std::shared_ptr<MasterWatch> master_;
  std::uint64_t master_registrations_ = 0;
  MasterOutage master_outage_;              // checkMaster's timer only
  bool tracking_before_outage_ = false;     // enabled when the outage disabled tracking
};

}  // namespace ros_layer
}  // namespace amigobot_tracking

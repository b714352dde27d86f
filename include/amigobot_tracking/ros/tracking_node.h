// The tracking node: runs core::PerformanceController on tf2 poses, laser and virtual
// obstacles and publishes cmd_vel. Hosted by the nodelet `amigobot_tracking/Tracking` and
// by the standalone `tracking_node`.
//
// Threads: callbacks only store their input (scan, virtual obstacle edits, reconfigure)
// under mutexes; the control timer does all the work, so a cycle sees one consistent set.
//
// Stale inputs and resuming (the paper leaves target loss open). A robot pose or target
// older than pose_timeout, or a missing transform, gives a zero command (while enabled),
// a WARN diagnostic and a throttled warning. When both are fresh again the controller is
// reset and restarted from the current state: the estimator starts at the first fresh
// target sample with zero velocity (no spike from differentiating across the gap), and
// rho restarts at max(rho_0, 2 |e|), so |e|/rho <= 1/2 and T(|e|/rho) <= 0.55 (no
// saturating burst from an envelope pressed against |e|); rho then decays at lambda.
// Every zero command of the nodelet's own (stale inputs, disable, a refused step) is
// immediate and re-arms the resume ramp (core/resume_ramp.h): from the next step the
// command leaves zero by at most resume_v_accel, resume_w_accel times the time since the
// last command (capped at one control period), scaled as a whole (direction and diamond
// kept), until the controller's command is within reach; then it passes unchanged.
#pragma once

#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/PointStamped.h>
#include <interactive_markers/interactive_marker_server.h>
#include <message_filters/subscriber.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/message_filter.h>
#include <tf2_ros/transform_listener.h>

#include "amigobot_tracking/RemoveVirtualObstacle.h"
#include "amigobot_tracking/TrackingConfig.h"
#include "amigobot_tracking/TrackingState.h"
#include "amigobot_tracking/VirtualObstacle.h"
#include "amigobot_tracking/core/controller.h"
#include "amigobot_tracking/core/obstacle_tracker.h"
#include "amigobot_tracking/core/resume_ramp.h"
#include "amigobot_tracking/core/scan_obstacles.h"
#include "amigobot_tracking/core/virtual_obstacles.h"
#include "amigobot_tracking/ros/tracking_params.h"

namespace amigobot_tracking {
namespace ros_layer {

// Timing of whole control cycles (steady clock), for diagnostics and the benchmark.
struct CycleStats {
  std::uint64_t cycles = 0;
  double last_us = 0.0;
  double max_us = 0.0;
  double sum_us = 0.0;
};

class TrackingNode {
 public:
  // `tf` may be shared with the host (e.g. a benchmark filling it directly); null creates a
  // buffer and a listener.
  TrackingNode(ros::NodeHandle nh, ros::NodeHandle pnh, std::shared_ptr<tf2_ros::Buffer> tf = nullptr);
  ~TrackingNode();
  TrackingNode(const TrackingNode&) = delete;
  TrackingNode& operator=(const TrackingNode&) = delete;

  // Loads and validates every parameter, then wires topics, services and the timer.
  // Returns false (after ROS_FATAL naming the parameter) and wires nothing on error.
  bool start();

  // One whole control cycle at `now`: tf lookups, obstacle set, controller step, publish.
  // Called by the timer; public for the benchmark.
  void controlCycle(const ros::Time& now);

  bool enabled() const;
  std::string status() const;  // "disabled", "tracking", or why the command is zero
  CycleStats cycleStats() const;
  tf2_ros::Buffer& tfBuffer() { return *tf_; }
  // The laser input after the tf2 MessageFilter (public for the benchmark).
  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan);

 private:
  struct Lookup {
    bool ok = false;
    geometry_msgs::TransformStamped transform;
    double age = 0.0;  // [s]
    std::string error;
  };
  Lookup lookup(const std::string& frame, const ros::Time& now) const;

  void onTimer(const ros::TimerEvent& event);
  void onVirtualObstacle(const VirtualObstacle::ConstPtr& msg);
  void onClickedPoint(const geometry_msgs::PointStamped::ConstPtr& msg);
  void onMarkerFeedback(const visualization_msgs::InteractiveMarkerFeedbackConstPtr& feedback);
  bool onEnable(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  bool onDisable(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  bool onRemove(RemoveVirtualObstacle::Request& req, RemoveVirtualObstacle::Response& res);
  bool onClear(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  void onReconfigure(TrackingConfig& config, uint32_t level);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  // With state_mutex_ held (tracking_node.cpp):
  void updateScanObstaclesLocked();
  std::string staleReasonLocked(const Lookup& pose, const Lookup& target, bool scan_fresh) const;  // "" when fresh
  bool stepLocked(const ros::Time& now, const Lookup& pose, const Lookup& target, core::ControllerOutput* out);
  void excludeTargetLocked(const Lookup& target);  // drops laser disks on the followed robot
  void publishStateLocked(const ros::Time& now, const Lookup& pose, bool have_output, const core::ControllerOutput& out);
  void publishMarkersLocked(const ros::Time& now, const Lookup& pose, bool have_output,
                            const core::ControllerOutput& out);
  void updateStatsLocked(const ros::Time& now, std::chrono::steady_clock::time_point wall_start);
  void publishZeroLocked();  // immediate stop; re-arms the resume ramp
  // Publishes the controller's command through the resume ramp; returns what was sent.
  core::Twist2 publishCommandLocked(const ros::Time& now, const core::Twist2& u);
  // With state_mutex_ held (tracking_virtual_obstacles.cpp): latched array + interactive markers.
  void publishVirtualObstaclesLocked(bool refresh_interactive = true);

  ros::NodeHandle nh_, pnh_;
  std::shared_ptr<tf2_ros::Buffer> tf_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;

  TrackingNodeConfig node_config_;
  core::ScanObstacleConfig scan_config_;
  core::ObstacleTrackerConfig tracker_config_;
  core::ControllerConfig controller_config_;  // in use
  core::ControllerConfig pending_config_;     // from dynamic_reconfigure, applied between steps
  bool config_pending_ = false;
  bool started_ = false;

  // Latest scan, written by onScan only.
  mutable std::mutex scan_mutex_;
  sensor_msgs::LaserScan::ConstPtr latest_scan_;

  // Everything the control cycle uses.
  mutable std::mutex state_mutex_;
  core::PerformanceController controller_;
  core::VirtualObstacleSet virtual_obstacles_;
  std::vector<core::Disk> scan_disks_;       // from used_scan_
  std::vector<core::Disk> scan_disks_next_;  // scratch for the next scan
  core::ObstacleTracker obstacle_tracker_;   // laser disks across scans (moving_obstacles)
  std::vector<core::Disk> obstacles_;  // scan + virtual, rebuilt every cycle
  sensor_msgs::LaserScan::ConstPtr processed_scan_;  // last scan looked at
  sensor_msgs::LaserScan::ConstPtr used_scan_;       // last scan turned into scan_disks_ (its age counts)
  double scan_age_ = -1.0;  // [s], -1: no scan yet
  bool enabled_ = false;
  bool lost_ = false;          // inputs were stale: reset and restart on the next fresh step
  bool restart_rho_ = false;   // apply the resume rule for rho on the next step
  bool ramping_ = true;        // the resume ramp is on (from zero, after a stop)
  core::Twist2 last_command_;  // last command published (zero after a stop)
  ros::Time last_command_time_;  // when (zero: never)
  std::string status_ = "disabled";
  ros::Time epoch_;
  core::ControllerOutput last_output_;
  double last_pose_age_ = -1.0, last_target_age_ = -1.0;
  std::uint64_t window_steps_ = 0, window_saturated_ = 0;
  double saturation_ratio_ = 0.0;
  ros::Time window_start_;
  double measured_rate_ = 0.0;
  std::uint64_t cycles_at_window_ = 0;
  CycleStats stats_;

  // ROS wiring (created by start()).
  ros::Publisher cmd_pub_, state_pub_, markers_pub_, virtual_pub_;
  ros::Subscriber virtual_sub_, clicked_sub_;
  ros::ServiceServer enable_srv_, disable_srv_, remove_srv_, clear_srv_;
  std::unique_ptr<message_filters::Subscriber<sensor_msgs::LaserScan>> scan_sub_;
  std::unique_ptr<tf2_ros::MessageFilter<sensor_msgs::LaserScan>> scan_filter_;
  std::unique_ptr<interactive_markers::InteractiveMarkerServer> marker_server_;
  boost::recursive_mutex reconfigure_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<TrackingConfig>> reconfigure_;
  std::unique_ptr<diagnostic_updater::Updater> diagnostics_;
  ros::Timer timer_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking

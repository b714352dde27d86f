#include "amigobot_tracking/ros/tracking_node.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "amigobot_tracking/VirtualObstacleArray.h"
#include "amigobot_tracking/core/avoidance.h"
#include "amigobot_tracking/core/offset_point.h"
#include "amigobot_tracking/ros/conversions.h"
#include "amigobot_tracking/ros/markers.h"
#include "amigobot_tracking/ros/reconfigure_mapping.h"

namespace amigobot_tracking {
namespace ros_layer {
namespace {

double ageOf(const ros::Time& stamp, const ros::Time& now) {
  if (stamp.isZero()) return 0.0;  // static transform: always current
  return std::max(0.0, (now - stamp).toSec());
}

}  // namespace

TrackingNode::TrackingNode(ros::NodeHandle nh, ros::NodeHandle pnh, std::shared_ptr<tf2_ros::Buffer> tf)
    : nh_(nh), pnh_(pnh), tf_(std::move(tf)) {
  if (!tf_) {
    tf_ = std::make_shared<tf2_ros::Buffer>();
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_, nh_, true);
  }
}

TrackingNode::~TrackingNode() {
  timer_.stop();
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    if (enabled_) publishZeroLocked();  // leave the robot standing
    enabled_ = false;
  }
  diagnostics_.reset();
  reconfigure_.reset();
  scan_filter_.reset();
  scan_sub_.reset();
  marker_server_.reset();
  tf_listener_.reset();
}

bool TrackingNode::start() {
  std::vector<core::VirtualObstacle> initial;
  std::string error = loadNodeConfig(pnh_, &node_config_);
  if (error.empty()) error = loadControllerConfig(pnh_, node_config_, &controller_config_);
  if (error.empty()) error = loadScanObstacleConfig(pnh_, &scan_config_);
  if (error.empty()) error = loadObstacleTrackerConfig(pnh_, &tracker_config_);
  if (error.empty()) error = loadVirtualObstacles(pnh_, &initial);
  if (!error.empty()) {
    ROS_FATAL_STREAM_NAMED("tracking", "tracking refuses to start: " << error
                                                                     << ". Nothing is enabled; fix it and restart.");
    return false;
  }
  controller_ = core::PerformanceController(controller_config_);
  obstacle_tracker_ = core::ObstacleTracker(tracker_config_);
  pending_config_ = controller_config_;
  virtual_obstacles_.assign(initial);
  epoch_ = ros::Time::now();
  window_start_ = epoch_;

  cmd_pub_ = nh_.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  state_pub_ = pnh_.advertise<TrackingState>("state", 10);
  markers_pub_ = pnh_.advertise<visualization_msgs::MarkerArray>("markers", 1);
  virtual_pub_ = pnh_.advertise<VirtualObstacleArray>("virtual_obstacles", 1, true);
  marker_server_ = std::make_unique<interactive_markers::InteractiveMarkerServer>(pnh_.resolveName("obstacle_markers"));
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    publishVirtualObstaclesLocked();
  }
  virtual_sub_ = pnh_.subscribe("virtual_obstacle", 10, &TrackingNode::onVirtualObstacle, this);
  clicked_sub_ = nh_.subscribe("clicked_point", 10, &TrackingNode::onClickedPoint, this);
  scan_sub_ = std::make_unique<message_filters::Subscriber<sensor_msgs::LaserScan>>(nh_, "scan", 5);
  scan_filter_ = std::make_unique<tf2_ros::MessageFilter<sensor_msgs::LaserScan>>(
      *scan_sub_, *tf_, node_config_.global_frame, 10, nh_);
  scan_filter_->registerCallback(&TrackingNode::onScan, this);
  scan_filter_->registerFailureCallback(
      [this](const sensor_msgs::LaserScan::ConstPtr& scan, tf2_ros::filter_failure_reasons::FilterFailureReason why) {
        ROS_WARN_THROTTLE(5.0, "tracking: scan in '%s' dropped: no transform to '%s' at its stamp (%s)",
                          scan->header.frame_id.c_str(), node_config_.global_frame.c_str(),
                          why == tf2_ros::filter_failure_reasons::OutTheBack ? "older than the tf buffer"
                          : why == tf2_ros::filter_failure_reasons::EmptyFrameID ? "empty frame_id"
                                                                                  : "tf not available in time");
      });

  enable_srv_ = pnh_.advertiseService("enable", &TrackingNode::onEnable, this);
  disable_srv_ = pnh_.advertiseService("disable", &TrackingNode::onDisable, this);
  remove_srv_ = pnh_.advertiseService("remove_virtual_obstacle", &TrackingNode::onRemove, this);
  clear_srv_ = pnh_.advertiseService("clear_virtual_obstacles", &TrackingNode::onClear, this);

  reconfigure_ = std::make_unique<dynamic_reconfigure::Server<TrackingConfig>>(reconfigure_mutex_, pnh_);
  TrackingConfig initial_gains;
  const std::string unmapped = fillReconfigure(controller_config_, &initial_gains);
  if (!unmapped.empty()) ROS_ERROR_STREAM_NAMED("tracking", unmapped);
  reconfigure_->updateConfig(initial_gains);
  reconfigure_->setCallback([this](TrackingConfig& config, uint32_t level) { onReconfigure(config, level); });

  diagnostics_ = std::make_unique<diagnostic_updater::Updater>(nh_, pnh_, pnh_.getNamespace());
  diagnostics_->setHardwareID("amigobot_tracking");
  diagnostics_->add("tracking", this, &TrackingNode::diagnose);

  {
    std::lock_guard<std::mutex> lock(state_mutex_);  // the services are already live
    started_ = true;
  }
  if (node_config_.autostart) {
    std_srvs::Trigger::Request req;
    std_srvs::Trigger::Response res;
    onEnable(req, res);
  }
  timer_ = nh_.createTimer(ros::Duration(1.0 / node_config_.control_rate), &TrackingNode::onTimer, this);
  ROS_INFO_STREAM_NAMED("tracking", "tracking " << node_config_.base_frame << " -> " << node_config_.target_frame
                                                << " in " << node_config_.global_frame << " at "
                                                << node_config_.control_rate << " Hz, "
                                                << (node_config_.autostart ? "enabled" : "disabled until ~enable"));
  return true;
}

bool TrackingNode::enabled() const {
  std::lock_guard<std::mutex> lock(state_mutex_);
  return enabled_;
}

std::string TrackingNode::status() const {
  std::lock_guard<std::mutex> lock(state_mutex_);
  return status_;
}

CycleStats TrackingNode::cycleStats() const {
  std::lock_guard<std::mutex> lock(state_mutex_);
  return stats_;
}

TrackingNode::Lookup TrackingNode::lookup(const std::string& frame, const ros::Time& now) const {
  Lookup result;
  try {
    result.transform = tf_->lookupTransform(node_config_.global_frame, frame, ros::Time(0));
    result.age = ageOf(result.transform.header.stamp, now);
    result.ok = true;
  } catch (const tf2::TransformException& ex) {
    result.error = ex.what();
  }
  return result;
}

void TrackingNode::onScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
  std::lock_guard<std::mutex> lock(scan_mutex_);
  latest_scan_ = scan;
}

void TrackingNode::updateScanObstaclesLocked() {
  sensor_msgs::LaserScan::ConstPtr scan;
  {
    std::lock_guard<std::mutex> lock(scan_mutex_);
    scan = latest_scan_;
  }
  if (!scan || scan == processed_scan_) return;
  processed_scan_ = scan;
  // Only a scan turned into disks counts as fresh: a bad one must not hide a blind laser.
  try {
    // The MessageFilter let the scan through only once this transform was available.
    const geometry_msgs::TransformStamped sensor =
        tf_->lookupTransform(node_config_.global_frame, scan->header.frame_id, scan->header.stamp);
    if (core::scanToObstacles(toScanGeometry(*scan), scan->ranges, toAffine2d(sensor.transform), scan_config_,
                              &scan_disks_next_)) {
      scan_disks_.swap(scan_disks_next_);  // the previous disks stay until a good scan replaces them
      used_scan_ = scan;
      obstacle_tracker_.update((scan->header.stamp - epoch_).toSec(), scan_disks_);
    } else {
      ROS_WARN_THROTTLE(5.0, "tracking: scan with invalid geometry ignored (frame %s)", scan->header.frame_id.c_str());
    }
  } catch (const tf2::TransformException& ex) {
    ROS_WARN_THROTTLE(5.0, "tracking: scan dropped: %s", ex.what());
  }
}

void TrackingNode::publishZeroLocked() {
  cmd_pub_.publish(geometry_msgs::Twist());
  last_command_ = {};
  last_command_time_ = ros::Time::now();
  ramping_ = true;
}

core::Twist2 TrackingNode::publishCommandLocked(const ros::Time& now, const core::Twist2& u) {
  core::Twist2 sent = u;
  if (ramping_) {
    // Time since the last command, at most one period: a late cycle does not earn a bigger
    // step than the period allows, and one that catches up right after earns less.
    const double period = 1.0 / node_config_.control_rate;
    const double dt = last_command_time_.isZero() ? period
                                                  : std::clamp((now - last_command_time_).toSec(), 0.0, period);
    const core::RampStep step =
        core::rampTowards(u, last_command_, {node_config_.resume_v_accel, node_config_.resume_w_accel}, dt);
    sent = step.u;
    ramping_ = step.limited;
  }
  cmd_pub_.publish(toTwist(sent));
  last_command_ = sent;
  last_command_time_ = now;
  return sent;
}

void TrackingNode::onTimer(const ros::TimerEvent&) { controlCycle(ros::Time::now()); }

void TrackingNode::controlCycle(const ros::Time& now) {
  const auto wall_start = std::chrono::steady_clock::now();
  const bool markers_wanted = markers_pub_.getNumSubscribers() > 0;
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    if (config_pending_) {  // dynamic_reconfigure: swapped between two steps only
      controller_.setConfig(pending_config_);
      controller_config_ = pending_config_;
      config_pending_ = false;
    }
    const Lookup pose = lookup(node_config_.base_frame, now);
    const Lookup target = lookup(node_config_.target_frame, now);
    updateScanObstaclesLocked();
    scan_age_ = used_scan_ ? ageOf(used_scan_->header.stamp, now) : -1.0;
    const bool scan_fresh = scan_age_ >= 0.0 && scan_age_ <= node_config_.scan_timeout;
    obstacles_.clear();
    if (scan_fresh) {
      // With moving_obstacles the laser disks carry velocities from the tracker.
      obstacles_ = controller_config_.moving_obstacles ? obstacle_tracker_.obstaclesAt((now - epoch_).toSec())
                                                       : scan_disks_;
      excludeTargetLocked(target);
    }
    virtual_obstacles_.appendDisks(&obstacles_);
    last_pose_age_ = pose.ok ? pose.age : -1.0;
    last_target_age_ = target.ok ? target.age : -1.0;

    core::ControllerOutput out;
    bool have_output = false;
    const std::string stale = staleReasonLocked(pose, target, scan_fresh);
    if (!enabled_) {
      status_ = "disabled";
    } else if (!stale.empty()) {
      status_ = stale;
      lost_ = true;
      publishZeroLocked();
      ROS_WARN_STREAM_THROTTLE(2.0, "tracking: zero command: " << stale);
    } else {
      have_output = stepLocked(now, pose, target, &out);
    }
    last_output_ = out;
    publishStateLocked(now, pose, have_output, out);
    if (markers_wanted) publishMarkersLocked(now, pose, have_output, out);
    updateStatsLocked(now, wall_start);
  }
  if (diagnostics_) diagnostics_->update();  // rate-limited by the updater; takes the lock itself
}

void TrackingNode::excludeTargetLocked(const Lookup& target) {
  if (!target.ok) return;
  const Eigen::Vector2d p(target.transform.transform.translation.x, target.transform.transform.translation.y);
  core::dropDisksNear(p, node_config_.target_exclusion_radius, &obstacles_);
}

std::string TrackingNode::staleReasonLocked(const Lookup& pose, const Lookup& target, bool scan_fresh) const {
  const double timeout = node_config_.pose_timeout;
  if (!pose.ok) return "no robot pose " + node_config_.global_frame + " -> " + node_config_.base_frame;
  if (pose.age > timeout) return "robot pose is stale (" + std::to_string(pose.age) + " s)";
  if (!target.ok) return "no target " + node_config_.global_frame + " -> " + node_config_.target_frame;
  if (target.age > timeout) return "target is stale (" + std::to_string(target.age) + " s)";
  if (node_config_.require_scan && !scan_fresh) {
    return scan_age_ < 0.0 ? "no scan yet" : "scan is stale (" + std::to_string(scan_age_) + " s)";
  }
  return "";
}

bool TrackingNode::stepLocked(const ros::Time& now, const Lookup& pose, const Lookup& target,
                              core::ControllerOutput* out) {
  if (lost_) {  // resume: start afresh (see the header for the rule)
    controller_.reset();
    restart_rho_ = true;
    lost_ = false;
  }
  const core::Pose2 robot = toPose2(pose.transform.transform);
  const ros::Time pose_stamp = pose.transform.header.stamp.isZero() ? now : pose.transform.header.stamp;
  const core::PoseSample robot_sample{(pose_stamp - epoch_).toSec(), robot};
  // The target sample keeps its own stamp (a static transform has none: use now).
  const ros::Time stamp = target.transform.header.stamp.isZero() ? now : target.transform.header.stamp;
  const core::TargetSample sample{(stamp - epoch_).toSec(),
                                  {target.transform.transform.translation.x, target.transform.transform.translation.y}};
  const double t = (now - epoch_).toSec();
  if (restart_rho_) {
    core::ControllerConfig restart = controller_config_;
    const double error = (sample.position - core::offsetPoint(robot, restart.offset)).norm();
    restart.rho_0 = std::max(restart.rho_0, 2.0 * error);
    controller_.setConfig(restart);
    *out = controller_.stepStamped(t, robot_sample, sample, obstacles_);
    controller_.setConfig(controller_config_);
    restart_rho_ = false;
  } else {
    *out = controller_.stepStamped(t, robot_sample, sample, obstacles_);
  }
  if (!out->valid) {
    status_ = "controller: " + out->error;
    publishZeroLocked();
    lost_ = true;  // e.g. time went backwards (bag loop): restart when usable
    ROS_WARN_STREAM_THROTTLE(2.0, "tracking: zero command: " << status_);
    return false;
  }
  if (!controller_.diamond().contains(out->u, 1e-9)) {  // never expected: belt and braces
    status_ = "command outside the diamond";
    publishZeroLocked();
    ROS_ERROR_THROTTLE(2.0, "tracking: controller command outside the diamond; sent zero");
    return false;
  }
  // The state and markers show what was sent: u is the ramped command while ramping.
  out->u = publishCommandLocked(now, out->u);
  status_ = "tracking";
  ++window_steps_;
  if (out->active.saturated) ++window_saturated_;
  return true;
}

void TrackingNode::publishStateLocked(const ros::Time& now, const Lookup& pose, bool have_output,
                                      const core::ControllerOutput& out) {
  const double inf = std::numeric_limits<double>::infinity();
  TrackingState state;
  state.header.stamp = now;
  state.header.frame_id = node_config_.global_frame;
  if (have_output) fillState(out, &state);
  state.enabled = enabled_;
  state.status = status_;
  state.t = (now - epoch_).toSec();
  state.rho = have_output ? out.rho : controller_.rho();
  state.obstacles = static_cast<int>(obstacles_.size());
  if (!have_output) state.min_clearance = inf;
  state.min_clearance_body =
      pose.ok ? core::clearance(toPose2(pose.transform.transform).position(), controller_config_.robot_radius, obstacles_)
              : inf;
  state.pose_age = last_pose_age_;
  state.target_age = last_target_age_;
  state_pub_.publish(state);
}

void TrackingNode::publishMarkersLocked(const ros::Time& now, const Lookup& pose, bool have_output,
                                        const core::ControllerOutput& out) {
  MarkerScene scene;
  scene.frame = node_config_.global_frame;
  scene.stamp = now;
  scene.have_pose = pose.ok;
  if (pose.ok) scene.pose = toPose2(pose.transform.transform);
  scene.have_output = have_output;
  scene.output = out;
  scene.config = &controller_config_;
  scene.detected = &scan_disks_;
  scene.virtual_obstacles = &virtual_obstacles_;
  scene.status = status_;
  markers_pub_.publish(buildMarkers(scene));
}

void TrackingNode::updateStatsLocked(const ros::Time& now, std::chrono::steady_clock::time_point wall_start) {
  ++stats_.cycles;
  const double window = (now - window_start_).toSec();
  if (window >= 1.0) {  // rates and ratios over about one second
    measured_rate_ = static_cast<double>(stats_.cycles - cycles_at_window_) / window;
    saturation_ratio_ = window_steps_ ? static_cast<double>(window_saturated_) / window_steps_ : 0.0;
    cycles_at_window_ = stats_.cycles;
    window_steps_ = window_saturated_ = 0;
    window_start_ = now;
  }
  const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - wall_start).count();
  stats_.last_us = us;
  stats_.max_us = std::max(stats_.max_us, us);
  stats_.sum_us += us;
}

void TrackingNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  using diagnostic_msgs::DiagnosticStatus;
  if (!enabled_) {
    status.summary(DiagnosticStatus::OK, "disabled");
  } else if (status_ == "tracking") {
    status.summary(DiagnosticStatus::OK, "tracking");
  } else {
    status.summary(DiagnosticStatus::WARN, "zero command: " + status_);
  }
  status.add("enabled", enabled_);
  status.add("status", status_);
  status.add("control rate set [Hz]", node_config_.control_rate);
  status.add("control rate measured [Hz]", measured_rate_);
  status.add("robot pose age [s]", last_pose_age_);
  status.add("target age [s]", last_target_age_);
  status.add("scan age [s]", scan_age_);
  status.add("saturation ratio", saturation_ratio_);
  status.add("resume ramp on", enabled_ && ramping_);
  status.add("rho [m]", controller_.rho());
  status.add("|e| [m]", last_output_.valid ? last_output_.e.norm() : 0.0);
  status.add("min clearance [m]", last_output_.valid ? last_output_.min_clearance : -1.0);
  status.add("obstacles (laser + virtual)", obstacles_.size());
  status.add("virtual obstacles", virtual_obstacles_.size());
  status.add("cycle time last [us]", stats_.last_us);
  status.add("cycle time max [us]", stats_.max_us);
  status.add("cycle time mean [us]", stats_.cycles ? stats_.sum_us / stats_.cycles : 0.0);
}

bool TrackingNode::onEnable(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  if (!started_) {  // unreachable: services exist only after a valid start
    res.success = false;
    res.message = "not started (configuration error)";
    return true;
  }
  if (!enabled_) {
    controller_.reset();
    restart_rho_ = true;
    lost_ = false;
    enabled_ = true;
    ramping_ = true;  // the robot is taken as standing: the command leaves zero on the ramp
    last_command_ = {};
  }
  res.success = true;
  res.message = "tracking enabled";
  ROS_INFO_NAMED("tracking", "tracking enabled");
  return true;
}

bool TrackingNode::onDisable(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  enabled_ = false;
  publishZeroLocked();  // one zero command, then cmd_vel is left to others
  res.success = true;
  res.message = "tracking disabled";
  ROS_INFO_NAMED("tracking", "tracking disabled");
  return true;
}

void TrackingNode::onReconfigure(TrackingConfig& config, uint32_t) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  core::ControllerConfig candidate = config_pending_ ? pending_config_ : controller_config_;
  // The robot's limits cap the diamond; the capped value is shown back in the GUI.
  config.v_max = std::min(config.v_max, node_config_.robot_v_max);
  config.w_max = std::min(config.w_max, node_config_.robot_w_max);
  std::string invalid = applyReconfigure(config, &candidate);
  if (invalid.empty()) invalid = candidate.validate();
  if (!invalid.empty()) {
    const core::ControllerConfig& kept = config_pending_ ? pending_config_ : controller_config_;
    ROS_ERROR_STREAM_NAMED("tracking", "reconfigure rejected, gains unchanged: " << invalid);
    fillReconfigure(kept, &config);
    return;
  }
  pending_config_ = candidate;
  config_pending_ = true;
  ROS_INFO_STREAM_NAMED("tracking", "reconfigure: " << describeLiveFields(candidate));
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

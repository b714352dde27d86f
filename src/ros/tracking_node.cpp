#include "amigobot_tracking/ros/tracking_node.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

#include <visualization_msgs/MarkerArray.h>

#include "amigobot_tracking/core/perception/body_intrusion.h"
#include "amigobot_tracking/ros/conversions.h"
#include "amigobot_tracking/ros/markers.h"
#include "amigobot_tracking/ros/reconfigure_mapping.h"

namespace amigobot_tracking {
namespace ros_layer {
namespace {

core::SupervisorConfig supervisorConfigOf(const TrackingNodeConfig& node) {
  core::SupervisorConfig c;
  c.max_speed = node.description.dynamics.max_velocity;
  c.pose_timeout = node.pose_timeout;
  c.scan_timeout = node.scan_timeout;
  c.require_scan = node.require_scan;
  c.control_period = 1.0 / node.control_rate;
  c.ramp = {node.resume_v_accel, node.resume_w_accel};
  c.pose_link = node.global_frame + " -> " + node.base_frame;
  c.target_link = node.global_frame + " -> " + node.target_frame;
  return c;
}

}  // namespace

TrackingNode::TrackingNode(ros::NodeHandle nh, ros::NodeHandle pnh, std::shared_ptr<tf2_ros::Buffer> tf)
    : nh_(nh), pnh_(pnh), tf_(std::move(tf)) {
  own_tf_ = !tf_;
  if (own_tf_) tf_ = std::make_shared<tf2_ros::Buffer>();
}

TrackingNode::~TrackingNode() {
  timer_.stop();
  master_timer_.stop();
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    // Leave the robot standing.
    if (started_ && loop_.supervisor().enabled()) publishLocked(loop_.disable(sinceEpoch(ros::Time::now())));
  }
  diagnostics_.reset();
  reconfigure_.reset();
  laser_.reset();
  virtual_obstacles_.reset();
  tf_listener_.reset();
}

void TrackingNode::start() {
  std::vector<core::VirtualObstacle> initial;
  core::TrackingLoopConfig loop_config;
  std::string error = loadNodeConfig(pnh_, &node_config_);
  if (error.empty()) error = loadControllerConfig(pnh_, node_config_, &loop_config.controller);
  if (error.empty()) error = loadScanObstacleConfig(pnh_, &scan_config_);
  if (error.empty()) error = loadObstacleTrackerConfig(pnh_, &tracker_config_);
  if (error.empty()) error = loadVirtualObstacles(pnh_, &initial);
  if (!error.empty()) throw std::runtime_error(error);
  loop_config.supervisor = supervisorConfigOf(node_config_);
  loop_config.pose_jump_limit_is_rho_inf = true;  // a localisation jump larger than the tracking bound stops
  loop_config.target_exclusion_radius = node_config_.target_exclusion_radius;
  loop_ = core::TrackingLoop(loop_config);
  if (own_tf_) tf_listener_ = std::make_unique<GuardedTfListener>(*tf_, nh_, node_config_.future_stamp_tolerance);
  epoch_ = ros::Time::now();
  pose_age_ = core::InputAgeTracker(node_config_.future_stamp_tolerance);
  target_age_ = core::InputAgeTracker(node_config_.future_stamp_tolerance);
  const double rate = node_config_.control_rate, inf = std::numeric_limits<double>::infinity();
  control_rate_ = std::make_unique<RateMonitor>("control rate", "control rate measured [Hz]", rate, rate, 0.1, 1);
  cmd_vel_rate_ = std::make_unique<RateMonitor>("cmd_vel", "cmd_vel rate measured [Hz]", rate, inf, 0.1, 1);

  cmd_pub_ = nh_.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  state_pub_ = pnh_.advertise<TrackingState>("state", 10);
  markers_pub_ = pnh_.advertise<visualization_msgs::MarkerArray>("markers", 1);
  virtual_obstacles_ = std::make_unique<VirtualObstacleInterface>(nh_, pnh_, *tf_, node_config_.global_frame,
                                                                  node_config_.clicked_point_radius, initial);
  LaserHealthConfig health;
  health.open_space = node_config_.open_space;
  health.rate.min_fraction = node_config_.min_scan_rate_fraction;
  health.rate.expected_rate = node_config_.expected_scan_rate;
  laser_ = std::make_unique<LaserObstacles>(*tf_, node_config_.global_frame, scan_config_, tracker_config_, epoch_,
                                            node_config_.future_stamp_tolerance, health);
  laser_->subscribe(nh_);
  localization_sub_ = nh_.subscribe("localization_status", 5, &TrackingNode::onLocalizationStatus, this);

  enable_srv_ = pnh_.advertiseService("enable", &TrackingNode::onEnable, this);
  disable_srv_ = pnh_.advertiseService("disable", &TrackingNode::onDisable, this);

  TrackingConfig initial_gains;
  const std::string unmapped = fillReconfigure(core::controllerFields(), loop_.controller().config(), &initial_gains);
  if (!unmapped.empty()) ROS_ERROR_STREAM_NAMED("tracking", unmapped);
  reconfigure_ = std::make_unique<CheckedReconfigure<TrackingConfig>>(
      pnh_, initial_gains, [this](const TrackingConfig& requested) { return onReconfigure(requested); });

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
  master_ = MasterWatch::shared();
  master_timer_ = nh_.createWallTimer(ros::WallDuration(MasterWatch::kPollPeriod),
                                      [this](const ros::WallTimerEvent&) { checkMaster(); });
  ROS_INFO_STREAM_NAMED("tracking", "tracking " << node_config_.base_frame << " -> " << node_config_.target_frame
                                                << " in " << node_config_.global_frame << " at "
                                                << node_config_.control_rate << " Hz, "
                                                << (node_config_.autostart ? "enabled" : "disabled until ~enable"));
}

bool TrackingNode::enabled() const {
  std::lock_guard<std::mutex> lock(state_mutex_);
  return loop_.supervisor().enabled();
}

std::string TrackingNode::status() const {
  std::lock_guard<std::mutex> lock(state_mutex_);
  return loop_.supervisor().status();
}

CycleStats TrackingNode::cycleStats() const {
  std::lock_guard<std::mutex> lock(state_mutex_);
  return stats_.cycles();
}

TrackingNode::Lookup TrackingNode::lookup(const std::string& frame, const ros::Time& now,
                                          core::InputAgeTracker* age) const {
  Lookup result;
  try {
    result.transform = tf_->lookupTransform(node_config_.global_frame, frame, ros::Time(0));
    age->seen(result.transform.header.stamp.toSec(), now.toSec());
    const core::InputAge a = age->at(now.toSec());
    result.age = a.age;
    result.problem = a.problem;
    result.ok = true;
  } catch (const tf2::TransformException& ex) {
    result.error = ex.what();
  }
  if (!tf_listener_) return result;
  // Skewed clocks are named as such: samples arriving at a healthy rate but stamped old (or
  // dropped as stamped ahead) read as "clock ... behind/ahead", not as a dead publisher. The
  // robot still stops once the age passes pose_timeout: the stamps cannot be trusted.
  const core::FrameClock clock =
      tf_listener_->clockOf(result.ok ? tf_listener_->chain(node_config_.global_frame, frame) : std::vector<std::string>{frame}, now);
  result.clock = clock.problem;
  const bool alive = clock.since_arrival >= 0.0 && clock.since_arrival <= node_config_.pose_timeout;
  if (!clock.problem.empty() && alive && (!result.ok || !result.problem.empty() || !(result.age <= node_config_.pose_timeout))) {
    result.problem = clock.problem;
  }
  return result;
}

void TrackingNode::onLocalizationStatus(const amigobot_tracking::LocalizationStatus::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(localization_mutex_);
  localization_problem_ = msg->ok ? "" : (msg->reason.empty() ? "not ok" : msg->reason);
}

void TrackingNode::onTimer(const ros::TimerEvent&) { controlCycle(ros::Time::now()); }

core::TrackingLoopInputs TrackingNode::loopInputsLocked(const ros::Time& now, const Lookup& pose,
                                                       const Lookup& target) {
  core::TrackingLoopInputs in;
  in.t = sinceEpoch(now);
  in.supervisor.have_pose = pose.ok;
  in.supervisor.pose_age = pose.age;
  // A static transform has no stamp: use now.
  const ros::Time pose_stamp = pose.transform.header.stamp.isZero() ? now : pose.transform.header.stamp;
  in.pose = {sinceEpoch(pose_stamp), toPose2(pose.transform.transform)};
  in.supervisor.have_target = target.ok;
  in.supervisor.target_age = target.age;
  const ros::Time stamp = target.transform.header.stamp.isZero() ? now : target.transform.header.stamp;
  in.target.stamp = sinceEpoch(stamp);
  in.target.position = {target.transform.transform.translation.x, target.transform.transform.translation.y};
  in.supervisor.scan_age = scan_age_;
  laser_disks_.clear();
  // The laser disks carry the obstacle tracker's velocities only with moving_obstacles. The
  // recommended law uses any velocity it is given (virtual obstacles', the simulator's); with the
  // tracker's, e2e_avoidance stalled beside a static virtual obstacle in 2 of 8 runs (the yield
  // manoeuvre, once any disk moves, also yields to static ones): not on by default until mended
  // (docs/recommended_law.md).
  if (loop_.scanFresh(scan_age_)) laser_->obstacles(loop_.nextConfig().moving_obstacles, now, &laser_disks_);
  virtual_disks_.clear();
  virtual_obstacles_->appendDisks(&virtual_disks_);
  in.scan_disks = &laser_disks_;
  in.virtual_disks = &virtual_disks_;
  // Issue 25's checks: untrusted stamps, bad localisation, something inside the body.
  in.supervisor.pose_problem = pose.problem;
  in.supervisor.target_problem = target.problem;
  in.supervisor.scan_problem = laser_->scanProblem();
  {
    std::lock_guard<std::mutex> lock(localization_mutex_);
    in.supervisor.localization_problem = localization_problem_;
  }
  if (pose.ok)
    in.supervisor.body_intrusion = core::bodyIntrusion(in.pose.pose.position(), loop_.nextConfig().robot_radius, laser_disks_,
                                            virtual_obstacles_->snapshot().all());
  return in;
}

void TrackingNode::controlCycle(const ros::Time& now) {
  const auto wall_start = TrackingStatistics::Clock::now();
  const bool markers_wanted = markers_pub_.getNumSubscribers() > 0;
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    const Lookup pose = lookup(node_config_.base_frame, now, &pose_age_);
    const Lookup target = lookup(node_config_.target_frame, now, &target_age_);
    scan_age_ = laser_->update(now);
    last_pose_age_ = pose.ok ? pose.age : -1.0;
    last_target_age_ = target.ok ? target.age : -1.0;
    noteClocksLocked(pose, target);
    const core::TrackingLoopResult r = loop_.step(loopInputsLocked(now, pose, target));
    virtual_count_ = r.virtual_disks;
    if (r.publish) {
      publishLocked(r.u);
      if (!r.tracking) logStopLocked();
    }
    if (r.tracking) stats_.addStep(r.output.active.saturated);
    last_output_ = r.output;
    control_rate_->tick();
    publishStateLocked(now, pose, r.tracking, r.output);
    if (markers_wanted) publishMarkersLocked(now, pose, r.tracking, r.output, virtual_obstacles_->snapshot());
    stats_.endCycle(sinceEpoch(now), wall_start);
  }
  if (diagnostics_) diagnostics_->update();  // rate-limited by the updater; takes the lock itself
}

void TrackingNode::noteClocksLocked(const Lookup& pose, const Lookup& target) {
  clock_warning_ = !target.clock.empty() ? target.clock : pose.clock;
  // Off but not (yet) past pose_timeout: tracking goes on with less margin; say so. (Past it,
  // the clock is the stop's reason and logStopLocked says it.)
  const bool stop_reason = clock_warning_ == target.problem || clock_warning_ == pose.problem;
  if (!clock_warning_.empty() && !stop_reason) ROS_WARN_STREAM_THROTTLE_NAMED(10.0, "tracking", "tracking: " << clock_warning_);
}

void TrackingNode::publishLocked(const core::Twist2& u) {
  cmd_pub_.publish(toTwist(u));
  if (cmd_vel_rate_) cmd_vel_rate_->tick();
}

void TrackingNode::logStopLocked() const {
  if (loop_.supervisor().state() == core::TrackingSupervisor::State::kCommandRefused) {
    ROS_ERROR_THROTTLE(2.0, "tracking: controller command outside the diamond; sent zero");
  } else {
    ROS_WARN_STREAM_THROTTLE(2.0, "tracking: zero command: " << loop_.supervisor().status());
  }
}

bool TrackingNode::onEnable(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  if (!started_) {  // unreachable: services exist only after a valid start
    res.success = false;
    res.message = "not started (configuration error)";
    return true;
  }
  if (loop_.enable()) cmd_vel_rate_->clear();  // cmd_vel starts again now
  res.success = true;
  res.message = "tracking enabled";
  ROS_INFO_NAMED("tracking", "tracking enabled");
  return true;
}

bool TrackingNode::onDisable(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  publishLocked(loop_.disable(sinceEpoch(ros::Time::now())));  // one zero command, then cmd_vel is left to others
  res.success = true;
  res.message = "tracking disabled";
  ROS_INFO_NAMED("tracking", "tracking disabled");
  return true;
}

void TrackingNode::checkMaster() {
  const MasterWatch::State master = master_->state();
  if (master.registrations != master_registrations_) {
    master_registrations_ = master.registrations;
    ROS_INFO_STREAM_NAMED("tracking", "a new ROS master answers: registered again (" << master.last_registration
                                                                                     << "); ~enable to track");
  }
  const MasterOutage::Action action =
      master_outage_.check(master.reachable, master.unreachable_for, master.identity, node_config_.pose_timeout);
  if (action == MasterOutage::Action::kNone || action == MasterOutage::Action::kStayStopped) return;
  std::lock_guard<std::mutex> lock(state_mutex_);
  if (!started_) return;
  if (action == MasterOutage::Action::kStop) {
    tracking_before_outage_ = loop_.supervisor().enabled();
    if (!tracking_before_outage_) return;
    publishLocked(loop_.disable(sinceEpoch(ros::Time::now())));
    ROS_ERROR_STREAM_NAMED("tracking", "ROS master unreachable for "
                                           << master.unreachable_for
                                           << " s: tracking disabled until the same master answers again (a new "
                                              "one: ~enable once it is back)");
  } else if (tracking_before_outage_) {  // kResume: the master that answered before
    if (loop_.enable()) cmd_vel_rate_->clear();
    ROS_WARN_NAMED("tracking", "the same ROS master answers again (it was busy or the link hiccuped): tracking "
                               "enabled again as before the outage");
  }
}

// The same rules as at start-up. A diamond beyond the robot's is refused, not capped: /cmd_vel
// outside the driver's clamp jumps when the driver cuts it, and capping v_max alone while the
// rest of the set is taken would run a shape and gains the user never asked for. The whole set
// is refused; the reconfigure client is told (checked_reconfigure.h).
std::string TrackingNode::onReconfigure(const TrackingConfig& requested) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  core::ControllerConfig candidate = loop_.nextConfig();
  std::string invalid = applyReconfigure(requested, core::controllerFields(), &candidate);
  if (invalid.empty()) invalid = robotLimitError(node_config_, candidate);
  if (invalid.empty()) invalid = candidate.validate();
  if (invalid.empty()) invalid = core::bandReachError(candidate, 1.0 / node_config_.control_rate);
  if (!invalid.empty()) {
    ROS_ERROR_STREAM_NAMED("tracking", "reconfigure refused, gains and limits unchanged: " << invalid);
    return invalid;
  }
  loop_.setPendingConfig(candidate);
  ROS_INFO_STREAM_NAMED("tracking", "reconfigure: " << core::describeLiveFields(core::controllerFields(), candidate));
  return "";
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

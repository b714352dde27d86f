#include "amigobot_tracking/ros/localization_node.h"

#include <diagnostic_msgs/DiagnosticStatus.h>

#include <cstdio>

#include "amigobot_tracking/LocalizationStatus.h"
#include "amigobot_tracking/core/perception/scan_obstacles.h"

#include "amigobot_tracking/localization/initial_pose.h"
#include "amigobot_tracking/localization/poses.h"
#include "amigobot_tracking/ros/localization_messages.h"
#include "amigobot_tracking/ros/param_aliases.h"

namespace amigobot_tracking {
namespace ros_layer {

using localization::LocalizationConfig;

namespace {
// [s] tf samples stamped further ahead of their arrival than transform_tolerance + this are
// dropped: this node's own map -> odom is stamped transform_tolerance ahead (as amcl's), and
// 0.1 s is the tracking node's default future_stamp_tolerance.
constexpr double kFutureStampMargin = 0.1;
}  // namespace

LocalizationConfig loadLocalizationConfig(const ros::NodeHandle& pnh) {
  LocalizationConfig config;
  const std::string error = readParams(pnh, localization::localizationFields(), &config, "", localizationAliases());
  if (!error.empty()) throw std::runtime_error("parameter " + error);
  return config;
}

LocalizationNode::LocalizationNode(ros::NodeHandle nh, ros::NodeHandle pnh)
    : config_(loadLocalizationConfig(pnh)), nh_(nh), pnh_(pnh),
      listener_(buffer_, nh, config_.transform_tolerance + kFutureStampMargin), updater_(nh, pnh),
      engine_(config_.use_map_topic ? nullptr : localization::makeEngine(config_)) {
  if (engine_ && engine_->mapGrows() && !config_.map_file.empty()) {
    // Refused now, not after a whole mapping drive: ~save_map writes there.
    const std::string problem = mapFolderProblem(config_.map_file);
    if (!problem.empty()) throw std::runtime_error("parameter ~map_file: " + config_.map_file + ": " + problem);
  }
  measures_match_ = engine_ && engine_->measuresMatch();
  // Any laser's rate: the window only shows a stall (0 Hz) or a worker that falls behind.
  rate_ = std::make_unique<RateMonitor>("scans", "scans processed [Hz]", 1.0, 100.0, 0.1, 10);
  if (config_.use_map_topic) {
    map_sub_ = nh_.subscribe("map", 1, &LocalizationNode::onMap, this);  // latched by map_server
  } else {
    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    map_metadata_pub_ = nh_.advertise<nav_msgs::MapMetaData>("map_metadata", 1, true);
  }
  pose_pub_ = pnh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("pose", 5);
  status_pub_ = nh_.advertise<amigobot_tracking::LocalizationStatus>("localization_status", 5);
  amcl_pose_pub_ = nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("amcl_pose", 5);
  if (engine_ && !engine_->mapGrows()) publishMap(engine_->map());
  worker_ = std::thread([this] { workLoop(); });
  tf_thread_ = std::thread([this] { tfLoop(); });
  initial_pose_sub_ = nh_.subscribe("initialpose", 2, &LocalizationNode::onInitialPose, this);
  save_map_srv_ = pnh_.advertiseService("save_map", &LocalizationNode::onSaveMap, this);
  save_map_to_srv_ = pnh_.advertiseService("save_map_to", &LocalizationNode::onSaveMapTo, this);
  global_srv_ = pnh_.advertiseService("global_localization", &LocalizationNode::onGlobalLocalization, this);
  amcl_global_srv_ = nh_.advertiseService("global_localization", &LocalizationNode::onAmclGlobalLocalization, this);
  updater_.setHardwareID("none");
  updater_.add("Localization (" + config_.mode + ")", this, &LocalizationNode::diagnose);
  diagnostics_timer_ = nh_.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { updater_.update(); });
  // Scans only when odom -> laser is known at their stamp.
  scan_sub_.subscribe(nh_, "scan", 5);
  filter_ = std::make_unique<tf2_ros::MessageFilter<sensor_msgs::LaserScan>>(scan_sub_, buffer_, config_.odom_frame, 10, nh_);
  filter_->registerCallback(&LocalizationNode::onScan, this);
}

LocalizationNode::~LocalizationNode() {
  filter_.reset();
  scan_sub_.unsubscribe();
  stop_ = true;
  wake_.notify_all();
  if (worker_.joinable()) worker_.join();
  if (tf_thread_.joinable()) tf_thread_.join();
  diagnostics_timer_.stop();
}

bool LocalizationNode::lookup(const std::string& parent, const std::string& child, const ros::Time& stamp, core::Pose2* out) {
  try {
    *out = toPose2(buffer_.lookupTransform(parent, child, stamp, ros::Duration(0.05)).transform);
    return true;
  } catch (const tf2::TransformException& e) {
    std::lock_guard<std::mutex> lock(mutex_);
    output_.last_error = e.what();
    return false;
  }
}

void LocalizationNode::onScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
  // A scan whose geometry or beams cannot be used (core/perception/scan_obstacles.h) is not matched:
  // the pose keeps its last correction and ages, as with no scan.
  const core::ScanGeometry geometry{msg->angle_min, msg->angle_increment, msg->range_min, msg->range_max};
  const std::string refused = core::scanBeamsProblem(geometry, msg->angle_max, msg->ranges.data(), msg->ranges.size());
  if (!refused.empty()) {
    if (scan_refusal_.due(refused)) {
      ROS_ERROR_STREAM_NAMED("localization", "localization: scan refused (frame '" << msg->header.frame_id
                                                                                   << "'): " << refused);
    }
    return;
  }
  scan_refusal_.clear();
  Work work;
  core::Pose2 mount;
  if (!lookup(config_.odom_frame, config_.base_frame, msg->header.stamp, &work.odom_base) ||
      !lookup(config_.base_frame, msg->header.frame_id, msg->header.stamp, &mount)) {
    return;
  }
  work.scan = toRangeScan(*msg, mount);
  work.stamp = msg->header.stamp;
  std::lock_guard<std::mutex> lock(mutex_);
  if (pending_) ++output_.dropped;  // the worker is behind: only the newest scan counts
  pending_ = std::move(work);
  wake_.notify_one();
}

void LocalizationNode::workLoop() {
  while (!stop_) {
    Work work;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return stop_ || pending_; });
      if (stop_) return;
      work = std::move(*pending_);
      pending_.reset();
    }
    process(work);
  }
}

void LocalizationNode::process(const Work& work) {
  std::optional<localization::OccupancyMap> map_to_publish;
  localization::PoseEstimate update;
  {
    std::lock_guard<std::mutex> engine(engine_mutex_);
    if (!engine_) {  // use_map_topic, no map yet: the scan is kept for ~global_localization only
      last_work_ = work;
      return;
    }
    update = engine_->update(work.scan, work.odom_base);
    const double now = ros::WallTime::now().toSec();
    if (engine_->mapGrows() && (last_map_publish_ < 0.0 || now - last_map_publish_ >= config_.map_publish_period)) {
      last_map_publish_ = now;
      map_to_publish = engine_->map();
    }
    last_work_ = work;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    output_.ready = true;
    output_.estimate = update;
    output_.matches += update.matched;
    ++output_.scans;
    rate_->tick();
  }
  publishTransform(update.map_to_odom);
  publishPose(work.stamp);
  publishStatus(work.stamp, update);
  if (map_to_publish) publishMap(*map_to_publish);
}

void LocalizationNode::tfLoop() {
  ros::WallRate rate(config_.tf_rate);
  while (!stop_ && ros::ok()) {
    std::optional<core::Pose2> map_to_odom;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (output_.ready) map_to_odom = output_.estimate.map_to_odom;
    }
    if (map_to_odom) publishTransform(*map_to_odom);
    rate.sleep();
  }
}

void LocalizationNode::publishTransform(const core::Pose2& map_to_odom) {
  if (!map_to_odom.isFinite()) {  // never published as NaN: tf readers keep the last good one and age it
    ROS_ERROR_STREAM_THROTTLE_NAMED(2.0, "localization", "map -> odom not published: not finite (" << map_to_odom.x << ", "
                                                              << map_to_odom.y << ", " << map_to_odom.theta << ")");
    return;
  }
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time::now() + ros::Duration(config_.transform_tolerance);
  if (!tf_gate_.pass(t.header.stamp)) return;  // the same stamp again: tf2 would warn TF_REPEATED_DATA
  t.header.frame_id = config_.global_frame;
  t.child_frame_id = config_.odom_frame;
  t.transform = toTransform(map_to_odom);
  broadcaster_.sendTransform(t);
}

void LocalizationNode::publishPose(const ros::Time& stamp) {
  geometry_msgs::PoseWithCovarianceStamped msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = config_.global_frame;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!output_.estimate.pose.isFinite() || !output_.estimate.covariance.allFinite()) {
      ROS_ERROR_STREAM_THROTTLE_NAMED(2.0, "localization", "~pose not published: the estimate is not finite");
      return;
    }
    msg.pose = toPoseWithCovariance(output_.estimate.pose, output_.estimate.covariance);
  }
  pose_pub_.publish(msg);
  amcl_pose_pub_.publish(msg);
}

bool LocalizationNode::onAmclGlobalLocalization(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  std_srvs::Trigger::Request request;
  std_srvs::Trigger::Response response;
  onGlobalLocalization(request, response);
  if (response.success) {
    ROS_INFO_STREAM_NAMED("localization", "global_localization: " << response.message);
  } else {
    ROS_WARN_STREAM_NAMED("localization", "global_localization: " << response.message);
  }
  return true;
}

void LocalizationNode::publishStatus(const ros::Time& stamp, const localization::PoseEstimate& estimate) {
  amigobot_tracking::LocalizationStatus msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = config_.global_frame;
  msg.match = estimate.match;
  msg.min_match = config_.min_match;
  if (!estimate.localized) msg.reason = estimate.not_localized;
  msg.ok = msg.reason.empty();
  status_pub_.publish(msg);
}

void LocalizationNode::onInitialPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg) {
  const auto& p = msg->pose.pose.position;
  const auto& o = msg->pose.pose.orientation;
  const core::Translation3 position{p.x, p.y, p.z};
  const core::Quaternion4 orientation{o.x, o.y, o.z, o.w};
  localization::OccupancyMap map;
  {
    std::lock_guard<std::mutex> engine(engine_mutex_);
    if (!engine_->mapGrows()) map = engine_->map();  // the bounds (a growing map has none yet)
  }
  const std::string bad = localization::initialPoseProblem(msg->header.frame_id, config_.global_frame, position, orientation, map);
  if (!bad.empty()) {
    ROS_WARN_STREAM_NAMED("localization", "/initialpose ignored, the pose is unchanged: " << bad);
    return;
  }
  core::Pose2 odom_base;
  if (!lookup(config_.odom_frame, config_.base_frame, ros::Time(0), &odom_base)) return;
  geometry_msgs::Pose unit = msg->pose.pose;
  const core::Quaternion4 q = core::normalised(orientation);
  unit.orientation.x = q.x;
  unit.orientation.y = q.y;
  unit.orientation.z = q.z;
  unit.orientation.w = q.w;
  const core::Pose2 pose = toPose2(unit);
  localization::PoseEstimate estimate;
  {
    std::lock_guard<std::mutex> engine(engine_mutex_);
    const std::string refused = engine_ ? engine_->setPose(pose, odom_base) : "/initialpose ignored: no map yet on the map topic";
    if (!refused.empty()) {
      ROS_WARN_STREAM_NAMED("localization", refused);
      return;
    }
    estimate = engine_->estimate();
  }
  ROS_INFO_STREAM_NAMED("localization", "initial pose (" << pose.x << ", " << pose.y << ", " << pose.theta << ")");
  poseJumped(estimate, false);
}

void LocalizationNode::poseJumped(const localization::PoseEstimate& estimate, bool relocalised) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    output_.ready = true;
    output_.estimate = estimate;
    output_.relocalisations += relocalised;
  }
  publishTransform(estimate.map_to_odom);  // the jump, in one step
  // Until the next scan is measured there, the pose is the operator's word only: tracking waits.
  publishStatus(ros::Time::now(), estimate);
}

bool LocalizationNode::onGlobalLocalization(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
  localization::GlobalSearch result;
  localization::PoseEstimate estimate;
  {
    std::lock_guard<std::mutex> engine(engine_mutex_);
    if (!engine_) {
      response.message = "no map yet on the map topic";
      return true;
    }
    if (!last_work_) {
      response.message = "no scan yet";
      return true;
    }
    response.message = engine_->globalSearch(last_work_->scan, last_work_->odom_base, &result);
    if (!response.message.empty()) return true;
    estimate = engine_->estimate();
  }
  char text[200];
  std::snprintf(text, sizeof text, "%s (%.3f, %.3f, %.3f) matching %.0f %% of the beams, %d candidates",
                result.found ? "relocalised at" : "not found; best", result.pose.x, result.pose.y, result.pose.theta,
                100.0 * result.match, result.candidates);
  response.success = result.found;
  response.message = text;
  ROS_INFO_STREAM_NAMED("localization", "~global_localization: " << text);
  if (result.found) poseJumped(estimate, true);
  return true;
}

void LocalizationNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!output_.ready) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, config_.use_map_topic && !measures_match_
                                                                ? std::string("waiting for the map on the map topic")
                                                                : "waiting for scans (and tf " + config_.odom_frame + " -> laser)");
  } else if (output_.estimate.lost) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "lost: the scans do not fit the map");
  } else if (!output_.estimate.localized) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "not localized: " + output_.estimate.not_localized);
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, config_.mode == "mapping" ? "mapping" : "localized");
  }
  rate_->report(status, output_.ready);
  status.add("mode", config_.mode);
  status.add("map file", config_.use_map_topic ? "(the map topic)" : config_.map_file);
  if (measures_match_) {  // a map made of its own scans has no match to report
    status.add("match (fraction of beams on the map)", output_.estimate.match);
    status.add("ICP goodness", output_.estimate.icp_goodness);
  }
  const localization::PoseEstimate& e = output_.estimate;
  status.add("covariance xx [m^2]", e.covariance(0, 0));
  status.add("covariance yy [m^2]", e.covariance(1, 1));
  status.add("covariance yaw [rad^2]", e.covariance(2, 2));
  status.add("pose x [m]", e.pose.x);
  status.add("pose y [m]", e.pose.y);
  status.add("pose yaw [rad]", e.pose.theta);
  status.add("scans processed", output_.scans);
  status.add("scans matched", output_.matches);
  status.add("scans dropped (worker busy)", output_.dropped);
  status.add("relocalisations", output_.relocalisations);
  status.add("last tf error", output_.last_error);
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

#include "amigobot_tracking/ros/driver.h"

#include "amigobot_tracking/ros/param_aliases.h"
#include "amigobot_tracking/ros/sonar_cloud.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Range.h>
#include <std_msgs/Bool.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include "amigobot_tracking/ros/param_reader.h"
#include "amigobot_tracking/ros/reconfigure_mapping.h"

namespace amigobot_tracking {
namespace ros_layer {
namespace {

// [s] ~stamp_offset's bound: beyond every timeout of the stack (a bigger skew tests nothing more).
constexpr double kMaxStampOffset = 5.0;

geometry_msgs::Quaternion yawQuaternion(double yaw) {
  tf2::Quaternion q;
  q.setRPY(0.0, 0.0, yaw);
  return tf2::toMsg(q);
}

}  // namespace

const core::FieldTable<DriverParams>& driverFields() {
  static const core::FieldTable<DriverParams> table = [] {
    using D = DriverParams;
    using core::field;
    core::FieldTable<D> t = {
        field("command_mode", &D::command_mode, "-",
              "vel_rvel sends VEL + RVEL; vel2 sends VEL2, whose wheel-speed steps of the robot file's vel2_divisor "
              "(20 mm/s) are too coarse at AmigoBot speeds (aria_command_study)",
              core::oneOf({"vel_rvel", "vel2"})),
        field("odom_frame", &D::odom_frame, "-", "odometry frame: odom's frame_id and the parent of the odom tf"),
        field("base_frame", &D::base_frame, "-",
              "robot frame: odom's child, parent of the sonar frames, frame of sonar_cloud and the state topics "
              "(robot.launch sets base_footprint, the URDF's root); RosAria's base_link_frame is read as an alias"),
        field("sonar_frame_prefix", &D::sonar_frame_prefix, "-",
              "transducer i publishes in <prefix><i> (sonar_range frame_id, static sonar tf)"),
        field("publish_tf", &D::publish_tf, "-", "broadcast the tf odom_frame -> base_frame from odometry"),
        field("publish_sonar_tf", &D::publish_sonar_tf, "-",
              "static tf base_frame -> <sonar_frame_prefix><i> from the robot file's sonar poses (turn off when "
              "robot_state_publisher runs the URDF)"),
        field("position_variance", &D::position_variance, "m^2", "odom pose covariance, x and y",
              core::nonNegative()),
        field("heading_variance", &D::heading_variance, "rad^2", "odom pose covariance, heading (yaw)",
              core::nonNegative()),
        field("battery_low_voltage", &D::battery_low_voltage, "V", "below this the diagnostics WARN battery low",
              core::nonNegative()),
        field("sonar_min_range", &D::sonar_min_range, "m", "min_range of every sensor_msgs/Range on sonar_range",
              core::nonNegative()),
        field("cmd_vel_source", &D::cmd_vel_source, "-",
              "node (caller id, e.g. /amigobot_manager) whose cmd_vel is driven; empty: the first publisher, until "
              "it has been silent 1 s. Others are ignored with a throttled WARN naming them"),
        field("master_timeout", &D::master_timeout, "s",
              "ROS master unreachable this long -> zero velocity, motors disabled, cmd_vel ignored until a master "
              "answers. The same master back (busy, a link hiccup): the motors on again as they were. A restarted "
              "master: the process registers its topics and services with it by itself; the motors stay disabled "
              "until the enable_motors service",
              core::boundedTimeout()),
        core::live(field("stamp_offset", &D::stamp_offset, "s",
                         "a test aid, keep 0 on a robot: added to the stamps of odometry, its tf, sonar and the state "
                         "topics, so the driver emulates a clock this far ahead (+) or behind (-) of the other "
                         "machines; within +-5 s, a WARN while not 0. The two-machine test sets -0.45 on the target",
                         core::interval(-kMaxStampOffset, false, kMaxStampOffset, false)),
                   -5.0, 5.0),
    };
    core::include(&t, "", &D::robot, robotSourceFields());
    core::include(&t, "", &D::client, aria::clientFields());
    return t;
  }();
  return table;
}

std::string DriverParams::validate() const {
  const std::string bad = core::checkFields(driverFields(), *this);
  if (!bad.empty()) return bad;
  if (odom_frame.empty()) return "odom_frame: must not be empty";
  if (base_frame.empty()) return "base_frame: must not be empty";
  return client.validate();
}

DriverParams loadDriverParams(const ros::NodeHandle& pnh) {
  ROS_INFO_STREAM_NAMED("driver", "driver parameters:");
  DriverParams p;
  const std::string error = readFields(pnh, driverFields(), &p, "", rosAriaAliases());
  if (!error.empty()) throw std::runtime_error(error);
  p.client.robot = loadRobot(p.robot);
  // The diamond's home is the robot file; a driver limit that tightens it still works, named.
  if (p.client.v_max > 0.0 || p.client.w_max > 0.0)
    ROS_WARN_STREAM_NAMED("driver", "~v_max " << p.client.v_max << " / ~w_max " << p.client.w_max
                                              << " (0 = the robot's) tighten the robot's diamond (" << p.client.robot.v_max
                                              << ", " << p.client.robot.w_max << ") of " << p.client.robot.origin()
                                              << "; the diamond is set there, these may only make it smaller");
  p.client.command_mode = *aria::parseCommandMode(p.command_mode);  // a choice of the table
  const std::string invalid = p.validate();
  if (!invalid.empty()) throw std::runtime_error("~" + invalid);
  return p;
}

AmigobotDriver::AmigobotDriver(ros::NodeHandle nh, ros::NodeHandle pnh)
    : params_(loadDriverParams(pnh)), nh_(nh), pnh_(pnh), updater_(nh, pnh) {
  odom_pub_ = nh_.advertise<nav_msgs::Odometry>("odom", 10);
  sonar_pub_ = nh_.advertise<sensor_msgs::Range>("sonar_range", 50);
  motors_pub_ = nh_.advertise<std_msgs::Bool>("motors_state", 1, true);
  sonar_cloud_pub_ = nh_.advertise<sensor_msgs::PointCloud2>("sonar_cloud", 1);
  state_topics_ = std::make_unique<DriverStateTopics>(nh_, params_.base_frame);
  enable_srv_ = nh_.advertiseService("enable_motors", &AmigobotDriver::enableMotors, this);
  disable_srv_ = nh_.advertiseService("disable_motors", &AmigobotDriver::disableMotors, this);
  reset_srv_ = nh_.advertiseService("reset_odometry", &AmigobotDriver::resetOdometry, this);
  updater_.setHardwareID("amigobot " + params_.client.port);
  updater_.add("AmigoBot driver", this, &AmigobotDriver::diagnose);
  sip_rate_ = std::make_unique<RateMonitor>("SIP rate", "SIP rate [Hz]", 0.5 / params_.client.robot.dynamics.cycle,
                                            std::numeric_limits<double>::infinity(), 0.0, 1);
  diagnostics_timer_ = nh_.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { updater_.force_update(); });
  if (params_.publish_sonar_tf) publishSonarTransforms();

  client_ = std::make_unique<aria::AriaClient>(params_.client, [](aria::LogLevel level, const std::string& text) {
    switch (level) {
      case aria::LogLevel::kDebug: ROS_DEBUG_STREAM_NAMED("aria", text); break;
      case aria::LogLevel::kInfo: ROS_INFO_STREAM_NAMED("aria", text); break;
      case aria::LogLevel::kWarn: ROS_WARN_STREAM_NAMED("aria", text); break;
      case aria::LogLevel::kError: ROS_ERROR_STREAM_NAMED("aria", text); break;
    }
  });
  client_->setSipCallback([this](const aria::RobotState& state) { onSip(state); });
  client_->start();
  link_timer_ = nh_.createTimer(ros::Duration(params_.client.robot.dynamics.cycle), [this](const ros::TimerEvent&) { checkLink(); });
  master_ = MasterWatch::shared();
  master_timer_ = nh_.createWallTimer(ros::WallDuration(MasterWatch::kPollPeriod), [this](const ros::WallTimerEvent&) { checkMaster(); });
  cmd_vel_lock_ = std::make_unique<core::CommandLock>(params_.cmd_vel_source, kCommandLockRelease);
  cmd_vel_sub_ = nh_.subscribe("cmd_vel", 1, &AmigobotDriver::onCmdVel, this);
  stamp_offset_ = params_.stamp_offset;
  warnStampOffset();
  amigobot_tracking::DriverConfig in_force;
  fillReconfigure(driverFields(), liveParams(), &in_force);
  reconfigure_ = std::make_unique<CheckedReconfigure<amigobot_tracking::DriverConfig>>(
      pnh_, in_force, [this](const amigobot_tracking::DriverConfig& requested) { return onReconfigure(requested); });
}

DriverParams AmigobotDriver::liveParams() const {
  DriverParams p = params_;
  p.client = client_->motionLimits();
  p.stamp_offset = stamp_offset_;
  return p;
}

std::string AmigobotDriver::onReconfigure(const amigobot_tracking::DriverConfig& requested) {
  DriverParams p = liveParams();
  std::string error = applyReconfigure(requested, driverFields(), &p);
  if (error.empty()) error = p.validate();
  if (error.empty()) error = client_->setMotionLimits(p.client);
  if (!error.empty()) {
    ROS_ERROR_STREAM("reconfigure refused, keeping the limits in force: " << error);
    return error;
  }
  const bool changed = p.stamp_offset != stamp_offset_;
  stamp_offset_ = p.stamp_offset;
  if (changed) warnStampOffset();
  return error;
}

void AmigobotDriver::warnStampOffset() const {
  const double offset = stamp_offset_;
  if (offset == 0.0) return;
  ROS_WARN_STREAM_NAMED("driver", "every stamp this driver publishes is shifted by " << offset
                                  << " s (~stamp_offset, a test aid emulating a skewed clock; 0 on a robot)");
}

AmigobotDriver::~AmigobotDriver() {
  reconfigure_.reset();
  cmd_vel_sub_.shutdown();
  diagnostics_timer_.stop();
  link_timer_.stop();
  master_timer_.stop();
  client_->stop();
}

void AmigobotDriver::onCmdVel(const ros::MessageEvent<const geometry_msgs::Twist>& event) {
  if (master_stop_) return;  // a peer still connected must not drive past a lost master
  const std::string& publisher = event.getPublisherName();
  // Wall time: a paused simulation clock must not hand the lock over.
  if (!cmd_vel_lock_->accept(publisher, ros::WallTime::now().toSec())) {
    const char* why = cmd_vel_lock_->configured() ? "~cmd_vel_source" : "first publisher";
    ROS_WARN_STREAM_THROTTLE_NAMED(2.0, "driver", "cmd_vel from " << publisher << " ignored: "
                                                                   << cmd_vel_lock_->owner() << " drives (" << why
                                                                   << ")");
    return;
  }
  const geometry_msgs::Twist::ConstPtr msg = event.getConstMessage();
  client_->setVelocity({msg->linear.x, msg->angular.z});  // NaN is refused (and stops) inside
}

void AmigobotDriver::onSip(const aria::RobotState& state) {
  sip_rate_->tick();
  std::lock_guard<std::mutex> lock(publish_mutex_);
  const ros::Time stamp = ros::Time::now() + ros::Duration(stamp_offset_);
  const auto& pose = state.odometry.pose;
  const auto& twist = state.odometry.twist;
  nav_msgs::Odometry odom;
  odom.header.stamp = stamp;
  odom.header.frame_id = params_.odom_frame;
  odom.child_frame_id = params_.base_frame;
  odom.pose.pose.position.x = pose.x;
  odom.pose.pose.position.y = pose.y;
  odom.pose.pose.orientation = yawQuaternion(pose.theta);
  odom.twist.twist.linear.x = twist.v;
  odom.twist.twist.angular.z = twist.omega;
  // Planar robot: z, roll and pitch are known exactly; huge variance would mislead fusers
  // that ignore them, so use a small value, and x, y, yaw from the parameters.
  const double fixed = 1e-6;
  const double pose_diag[6] = {params_.position_variance, params_.position_variance, fixed, fixed, fixed,
                               params_.heading_variance};
  const double twist_diag[6] = {1e-3, fixed, fixed, fixed, fixed, 1e-2};
  for (int i = 0; i < 6; ++i) {
    odom.pose.covariance[static_cast<std::size_t>(i * 7)] = pose_diag[i];
    odom.twist.covariance[static_cast<std::size_t>(i * 7)] = twist_diag[i];
  }
  odom_pub_.publish(odom);
  if (params_.publish_tf) {
    geometry_msgs::TransformStamped t;
    t.header = odom.header;
    t.child_frame_id = params_.base_frame;
    t.transform.translation.x = pose.x;
    t.transform.translation.y = pose.y;
    t.transform.rotation = odom.pose.pose.orientation;
    tf_.sendTransform(t);
  }
  publishMotorsStateLocked(state.motors_enabled);
  // One sensor_msgs/Range per transducer reading in this SIP, in the transducer's frame.
  // REP 117: no echo within the maximum range is +inf.
  const double max_range = params_.client.robot.sonar_max_range;
  for (std::size_t i = 0; i < state.sonar_updated.size(); ++i) {
    if (!state.sonar_updated[i]) continue;
    sensor_msgs::Range range;
    range.header.stamp = stamp;
    range.header.frame_id = params_.sonar_frame_prefix + std::to_string(i);
    range.radiation_type = sensor_msgs::Range::ULTRASOUND;
    range.field_of_view = 0.4;
    range.min_range = static_cast<float>(params_.sonar_min_range);
    range.max_range = static_cast<float>(max_range);
    const double r = state.sonar_ranges[i];
    range.range = r >= max_range ? std::numeric_limits<float>::infinity() : static_cast<float>(r);
    sonar_pub_.publish(range);
  }
  if (sonar_cloud_pub_.getNumSubscribers() > 0) {
    sonar_cloud_pub_.publish(makeSonarCloud(state.sonar_ranges, params_.client.robot.sonars, max_range,
                                            params_.base_frame, stamp));
  }
  state_topics_->publish(state, client_->status().config, stamp);
}

void AmigobotDriver::publishMotorsStateLocked(bool enabled) {
  if (last_motors_state_ == static_cast<int>(enabled)) return;
  std_msgs::Bool motors;
  motors.data = enabled;
  motors_pub_.publish(motors);
  last_motors_state_ = enabled;
}

void AmigobotDriver::checkLink() {
  const aria::ClientStatus status = client_->status();
  reportOneWayLink(status);
  if (status.link == aria::LinkState::kConnected) return;
  std::lock_guard<std::mutex> lock(publish_mutex_);
  publishMotorsStateLocked(false);
}

void AmigobotDriver::publishSonarTransforms() {
  std::vector<geometry_msgs::TransformStamped> transforms;
  for (std::size_t i = 0; i < params_.client.robot.sonars.size(); ++i) {
    const auto& s = params_.client.robot.sonars[i];
    geometry_msgs::TransformStamped t;
    t.header.stamp = ros::Time::now();
    t.header.frame_id = params_.base_frame;
    t.child_frame_id = params_.sonar_frame_prefix + std::to_string(i);
    t.transform.translation.x = s.x;
    t.transform.translation.y = s.y;
    t.transform.rotation = yawQuaternion(s.yaw);
    transforms.push_back(t);
  }
  static_tf_.sendTransform(transforms);
}

bool AmigobotDriver::enableMotors(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  client_->requestMotors(true);
  return true;
}

bool AmigobotDriver::disableMotors(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  client_->requestMotors(false);
  return true;
}

bool AmigobotDriver::resetOdometry(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  client_->resetOdometry();
  return true;
}

void AmigobotDriver::diagnose(diagnostic_updater::DiagnosticStatusWrapper& d) {
  const aria::ClientStatus s = client_->status();
  using diagnostic_msgs::DiagnosticStatus;
  const bool connected = s.link == aria::LinkState::kConnected;
  const MasterWatch::State master = master_->state();
  if (!connected) {
    d.summaryf(DiagnosticStatus::ERROR, "not connected (%s)%s%s", aria::linkStateName(s.link).c_str(),
               s.last_error.empty() ? "" : ": ", s.last_error.c_str());
  } else if (s.acknowledgement == aria::AcknowledgementState::kUnacknowledged) {
    d.summaryf(DiagnosticStatus::ERROR, "one-way link: the robot has not answered for %.2f s while its SIPs arrive",
               s.unanswered_for);
  } else if (master_stop_) {
    d.summaryf(DiagnosticStatus::ERROR, "stopped: ROS master unreachable for %.1f s", master.unreachable_for);
  } else if (s.robot && s.robot->battery_voltage < params_.battery_low_voltage) {
    d.summaryf(DiagnosticStatus::WARN, "battery low: %.1f V", s.robot->battery_voltage);
  } else {
    d.summary(DiagnosticStatus::OK, "connected");
  }
  d.add("link", aria::linkStateName(s.link));
  d.add("port", params_.client.port);
  d.add("baud", s.baud > 0 ? std::to_string(s.baud) : std::string("- (TCP)"));
  if (s.identity) d.add("robot", s.identity->name + " (" + s.identity->robot_class + " " + s.identity->subclass + ")");
  sip_rate_->report(d, connected);  // "SIP rate [Hz]" and its window; no SIPs is no news without a link
  d.add("SIPs", s.sips);
  d.add("connections", s.connections);
  d.add("still-open recoveries", s.still_open_recoveries);
  d.add("baud recoveries (CLOSE at every baud)", s.baud_recoveries);
  d.add("bytes received", s.bytes_received);
  d.add("bytes sent", s.bytes_sent);
  d.add("parser packets", s.parser.packets);
  d.add("parser garbage bytes", s.parser.garbage_bytes);
  d.add("parser bad checksums", s.parser.bad_checksum);
  d.add("parser bad counts", s.parser.bad_count);
  d.add("parser truncated", s.parser.truncated);
  d.add("commands sent", s.commands_sent);
  d.add("non-finite cmd_vel refused", s.non_finite_requests);
  d.add("command mode", aria::commandModeName(params_.client.command_mode));
  d.add("motors requested", s.motors_requested);
  d.add("robot hears the driver", aria::acknowledgementStateName(s.acknowledgement));
  d.add("probes sent / answered", std::to_string(s.probes_sent) + " / " + std::to_string(s.probes_answered));
  d.add("ROS master", master.reachable ? "reachable" : "unreachable");
  d.add("registrations with a new master", master.registrations);
  if (s.robot) {
    d.add("motors enabled", s.robot->motors_enabled);
    d.add("battery [V]", s.robot->battery_voltage);
    d.add("stall", s.robot->left_stall || s.robot->right_stall);
  }
  if (!s.last_error.empty()) d.add("last error", s.last_error);
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

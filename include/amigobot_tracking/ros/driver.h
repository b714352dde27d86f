// ROS wrapper of the AmigoBot driver (aria::AriaClient): cmd_vel in; odom, tf, sonar,
// battery, motors_state and /diagnostics out; enable_motors, disable_motors and
// reset_odometry services. Shared by the nodelet amigobot_tracking/Driver and the node
// amigobot_driver_node. Serial I/O runs on the client's thread; the cmd_vel callback only
// stores the latest request.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <amigobot_tracking/DriverConfig.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

#include "amigobot_tracking/aria/client.h"
#include "amigobot_tracking/core/supervision/command_lock.h"
#include "amigobot_tracking/ros/checked_reconfigure.h"
#include "amigobot_tracking/ros/driver_state_topics.h"
#include "amigobot_tracking/ros/master_watch.h"
#include "amigobot_tracking/ros/param_reader.h"
#include "amigobot_tracking/ros/rate_monitor.h"
#include "amigobot_tracking/ros/robot_source.h"

namespace amigobot_tracking {
namespace ros_layer {

struct DriverParams {
  aria::ClientConfig client;
  RobotSource robot;                     // ~robot_model / ~robot_params (ros/robot_source.h)
  std::string command_mode = "vel_rvel";  // vel_rvel | vel2
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  std::string sonar_frame_prefix = "sonar_";  // transducer i publishes in <prefix><i>
  bool publish_tf = true;
  bool publish_sonar_tf = true;  // static base_link -> sonar_i from the robot parameters
  double position_variance = 1e-3;  // [m^2] odom pose covariance, x and y
  double heading_variance = 1e-2;   // [rad^2]
  double battery_low_voltage = 11.0;  // [V] diagnostics warn below this
  double sonar_min_range = 0.1;       // [m] sensor_msgs/Range min_range
  // The node whose cmd_vel is driven (its caller id, e.g. "/amigobot_manager"); "": the first
  // publisher, until it has been silent for kCommandLockRelease (core/supervision/command_lock.h).
  std::string cmd_vel_source;
  // [s] ROS master unreachable this long: stop, motors disabled until enable_motors.
  double master_timeout = 0.5;
  // [s] A TEST AID, 0 on a robot: added to every stamp the driver publishes (odometry, tf,
  // sonar, state topics), so one machine's driver emulates a clock this far ahead (+) or
  // behind (-) of the others (the two-machine test's skewed target). Live (reconfigure).
  double stamp_offset = 0.0;

  // "" or "key: reason": the table's bounds, non-empty frames, then client.validate() (with
  // client.robot and client.command_mode already chosen from robot_model/robot_params/command_mode).
  std::string validate() const;
};

// The driver's ROS parameters: its own rows and aria::clientFields(), flat.
const core::FieldTable<DriverParams>& driverFields();

// Reads the private parameters (docs/ros_api.md); throws std::runtime_error("~key: reason").
DriverParams loadDriverParams(const ros::NodeHandle& pnh);

class AmigobotDriver {
 public:
  // With cmd_vel_source empty, another publisher may drive after the lock holder has been
  // silent this long [s] (longer than any publisher's period, shorter than an operator waits).
  static constexpr double kCommandLockRelease = 1.0;

  AmigobotDriver(ros::NodeHandle nh, ros::NodeHandle pnh);
  ~AmigobotDriver();  // stops the robot: zero velocity, ENABLE 0, CLOSE

 private:
  void onCmdVel(const ros::MessageEvent<const geometry_msgs::Twist>& event);
  void onSip(const aria::RobotState& state);  // client I/O thread
  bool enableMotors(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool disableMotors(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool resetOdometry(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);
  void publishSonarTransforms();
  // dynamic_reconfigure: "" when the client took the set, else why it refused it (then the
  // limits in force stay and the reconfigure call fails with the reason).
  std::string onReconfigure(const amigobot_tracking::DriverConfig& requested);
  // params_ with what reconfigure changed: the client's limits in force and stamp_offset_.
  DriverParams liveParams() const;
  void warnStampOffset() const;  // a WARN while ~stamp_offset is not 0
  // motors_state, latched, published on change only; publish_mutex_ held.
  void publishMotorsStateLocked(bool enabled);
  // Without a link the motors are not enabled, whatever the last SIP said (SIP period).
  void checkLink();
  // ROS master gone longer than master_timeout: zero, ENABLE 0, cmd_vel ignored until a master
  // answers again (the watch registers everything with a new one); the motors stay off.
  void checkMaster();
  // Commands unanswered while SIPs arrive (aria/acknowledgement_watch.h): ERROR, diagnostics.
  void reportOneWayLink(const aria::ClientStatus& status);

  DriverParams params_;
  ros::NodeHandle nh_, pnh_;
  ros::Subscriber cmd_vel_sub_;
  ros::Publisher odom_pub_, sonar_pub_, motors_pub_;
  ros::Publisher sonar_cloud_pub_;  // built only while someone subscribes
  ros::ServiceServer enable_srv_, disable_srv_, reset_srv_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;
  diagnostic_updater::Updater updater_;
  std::unique_ptr<RateMonitor> sip_rate_;  // ticked per SIP; warns below half the robot's SIP rate
  ros::Timer diagnostics_timer_, link_timer_;
  ros::WallTimer master_timer_;  // wall clock: a paused /clock must not hide a dead master
  std::shared_ptr<MasterWatch> master_;
  std::atomic<bool> master_stop_{false};  // set by checkMaster, read by onCmdVel
  MasterOutage master_outage_;            // checkMaster's timer only
  bool motors_before_outage_ = false;     // requested when the outage stopped the robot
  std::atomic<double> stamp_offset_{0.0};  // params_.stamp_offset as reconfigured (read per SIP)
  std::uint64_t master_registrations_ = 0;
  bool one_way_reported_ = false;
  std::mutex publish_mutex_;
  int last_motors_state_ = -1;  // -1: not yet published
  std::unique_ptr<DriverStateTopics> state_topics_;  // battery_voltage, battery, stall, bumper, estop
  std::unique_ptr<aria::AriaClient> client_;
  std::unique_ptr<core::CommandLock> cmd_vel_lock_;  // one source drives (cmd_vel callback only)
  std::unique_ptr<CheckedReconfigure<amigobot_tracking::DriverConfig>> reconfigure_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking

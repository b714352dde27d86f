// TrackingNode, what a cycle shows: ~state, ~markers (while subscribed) and the "tracking"
// diagnostics task.
#include <limits>

#include "amigobot_tracking/core/law/avoidance.h"
#include "amigobot_tracking/ros/conversions.h"
#include "amigobot_tracking/ros/markers.h"
#include "amigobot_tracking/ros/tracking_node.h"

namespace amigobot_tracking {
namespace ros_layer {

void TrackingNode::publishStateLocked(const ros::Time& now, const Lookup& pose, bool have_output,
                                      const core::ControllerOutput& out) {
  const double inf = std::numeric_limits<double>::infinity();
  TrackingState state;
  state.header.stamp = now;
  state.header.frame_id = node_config_.global_frame;
  if (have_output) fillState(out, &state);
  state.enabled = loop_.supervisor().enabled();
  state.status = loop_.supervisor().status();
  state.t = sinceEpoch(now);
  state.rho = have_output ? out.rho : loop_.controller().rho();
  state.obstacles = static_cast<int>(loop_.obstacles().size());
  if (!have_output) state.min_clearance = inf;
  state.min_clearance_body =
      pose.ok ? core::clearance(toPose2(pose.transform.transform).position(), loop_.controller().config().robot_radius, loop_.obstacles())
              : inf;
  state.pose_age = last_pose_age_;
  state.target_age = last_target_age_;
  state_pub_.publish(state);
}

void TrackingNode::publishMarkersLocked(const ros::Time& now, const Lookup& pose, bool have_output,
                                        const core::ControllerOutput& out, const core::VirtualObstacleSet& virtuals) {
  MarkerScene scene;
  scene.frame = node_config_.global_frame;
  scene.stamp = now;
  scene.have_pose = pose.ok;
  if (pose.ok) scene.pose = toPose2(pose.transform.transform);
  scene.have_output = have_output;
  scene.output = out;
  scene.config = &loop_.controller().config();
  scene.detected = &laser_->disks();
  scene.virtual_obstacles = &virtuals;
  scene.status = loop_.supervisor().status();
  markers_pub_.publish(buildMarkers(scene));
}

void TrackingNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  using diagnostic_msgs::DiagnosticStatus;
  const bool enabled = loop_.supervisor().enabled();
  if (!enabled) {
    status.summary(DiagnosticStatus::OK, "disabled");
  } else if (loop_.supervisor().state() == core::TrackingSupervisor::State::kTracking) {
    if (clock_warning_.empty()) {
      status.summary(DiagnosticStatus::OK, "tracking");
    } else {
      status.summary(DiagnosticStatus::WARN, "tracking; " + clock_warning_);
    }
  } else {
    status.summary(DiagnosticStatus::WARN, "zero command: " + loop_.supervisor().status());
  }
  status.add("enabled", enabled);
  status.add("status", loop_.supervisor().status());
  status.add("control rate set [Hz]", node_config_.control_rate);
  control_rate_->report(status, true);
  cmd_vel_rate_->report(status, enabled);  // silent while disabled, by design
  status.add("robot pose age [s]", last_pose_age_);
  status.add("target age [s]", last_target_age_);
  status.add("clocks", clock_warning_.empty() ? std::string("no offset beyond future_stamp_tolerance") : clock_warning_);
  status.add("scan age [s]", scan_age_);
  status.add("last scan refused", laser_ ? laser_->refusal() : std::string());
  status.add("saturation ratio", stats_.saturationRatio());
  status.add("resume ramp on", enabled && loop_.supervisor().ramping());
  status.add("rho [m]", loop_.controller().rho());
  status.add("|e| [m]", last_output_.valid ? last_output_.e.norm() : 0.0);
  status.add("min clearance [m]", last_output_.valid ? last_output_.min_clearance : -1.0);
  status.add("obstacles (laser + virtual)", loop_.obstacles().size());
  status.add("virtual obstacles", virtual_count_);
  status.add("cycle time last [us]", stats_.cycles().last_us);
  status.add("cycle time max [us]", stats_.cycles().max_us);
  status.add("cycle time mean [us]", stats_.meanCycleUs());
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

#include "amigobot_tracking/ros/ground_truth.h"

#include <cmath>

#include "amigobot_tracking/ros/param_reader.h"

namespace amigobot_tracking {
namespace ros_layer {

core::Pose2 mapToOdom(const core::Pose2& truth, const core::Pose2& odom_base) {
  const double theta = core::wrapAngle(truth.theta - odom_base.theta);
  const double c = std::cos(theta), s = std::sin(theta);
  core::Pose2 out;
  out.theta = theta;
  out.x = truth.x - (c * odom_base.x - s * odom_base.y);
  out.y = truth.y - (s * odom_base.x + c * odom_base.y);
  return out;
}

void TruthPairing::add(double stamp, const core::Pose2& truth) {
  if (!samples_.empty() && stamp <= samples_.back().first) samples_.clear();  // time went back: start again
  samples_.emplace_back(stamp, truth);
  while (!samples_.empty() && samples_.front().first < stamp - keep_) samples_.pop_front();
}

std::optional<core::Pose2> TruthPairing::correction(const OdometryAt& odom_at) {
  for (auto it = samples_.rbegin(); it != samples_.rend(); ++it) {
    core::Pose2 odom_base;
    if (!odom_at(it->first, &odom_base)) continue;
    const core::Pose2 result = mapToOdom(it->second, odom_base);
    samples_.erase(samples_.begin(), it.base());
    return result;
  }
  return std::nullopt;
}

const core::FieldTable<GroundTruthConfig>& groundTruthFields() {
  using G = GroundTruthConfig;
  using core::field;
  static const core::FieldTable<G> table = {
      field("host", &G::host, "-", "the emulator's status socket address"),
      field("port", &G::port, "-", "its --status-port", core::interval(1, false, 65535, false)),
      field("global_frame", &G::global_frame, "-", "map frame"),
      field("odom_frame", &G::odom_frame, "-", "odometry frame"),
      field("base_frame", &G::base_frame, "-", "robot frame"),
      field("rate", &G::rate, "Hz", "map -> odom updates", core::positive()),
      field("transform_tolerance", &G::transform_tolerance, "s", "map -> odom is stamped this far ahead",
            core::durationOrZero()),
      field("socket_timeout", &G::socket_timeout, "s", "a slower status reply counts as a lost link",
            core::boundedTimeout()),
      field("reconnect_period", &G::reconnect_period, "s", "between reconnection attempts", core::duration()),
      field("publish_tf", &G::publish_tf, "-", "broadcast map -> odom (false: only the ground_truth topic)"),
  };
  return table;
}

std::string GroundTruthConfig::validate() const {
  const std::string bad = core::checkFields(groundTruthFields(), *this);
  if (!bad.empty()) return bad;
  if (host.empty()) return "host: must not be empty";
  if (global_frame.empty() || odom_frame.empty() || base_frame.empty())
    return "global_frame/odom_frame/base_frame: must not be empty";
  return "";
}

std::string loadGroundTruthConfig(const ros::NodeHandle& pnh, GroundTruthConfig* config) {
  return readParams(pnh, groundTruthFields(), config);
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

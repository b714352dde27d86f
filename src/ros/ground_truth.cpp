#include "amigobot_tracking/ros/ground_truth.h"

#include <cmath>

#include "amigobot_tracking/ros/logged_param.h"

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

std::string GroundTruthConfig::validate() const {
  if (host.empty()) return "host must not be empty";
  if (port <= 0 || port > 65535) return "port must be in 1..65535, got " + std::to_string(port);
  if (global_frame.empty() || odom_frame.empty() || base_frame.empty()) return "frames must not be empty";
  if (!(std::isfinite(rate) && rate > 0.0)) return "rate must be > 0";
  if (!(std::isfinite(transform_tolerance) && transform_tolerance >= 0.0)) return "transform_tolerance must be >= 0";
  if (!(std::isfinite(socket_timeout) && socket_timeout > 0.0)) return "socket_timeout must be > 0";
  if (!(std::isfinite(reconnect_period) && reconnect_period > 0.0)) return "reconnect_period must be > 0";
  return "";
}

std::string loadGroundTruthConfig(const ros::NodeHandle& pnh, GroundTruthConfig* config) {
  loggedParam(pnh, "host", &config->host);
  loggedParam(pnh, "port", &config->port);
  loggedParam(pnh, "global_frame", &config->global_frame);
  loggedParam(pnh, "odom_frame", &config->odom_frame);
  loggedParam(pnh, "base_frame", &config->base_frame);
  loggedParam(pnh, "rate", &config->rate);
  loggedParam(pnh, "transform_tolerance", &config->transform_tolerance);
  loggedParam(pnh, "socket_timeout", &config->socket_timeout);
  loggedParam(pnh, "reconnect_period", &config->reconnect_period);
  const std::string error = config->validate();
  return error.empty() ? "" : "parameter " + pnh.getNamespace() + "/" + error;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

// reference_publisher: broadcasts tf global_frame -> target_frame moving along a reference
// (rose, circle, spline, waypoints; core/reference.h, core/waypoint_reference.h), so a
// robot can track a virtual target in an empty room. The frame's x axis points along the
// velocity. Before start_delay the target waits at its initial point.
//
// Parameters (private): global_frame (map), target_frame (target), rate [Hz] (50),
// time_scale [-] (1: >1 runs the reference slower), start_delay [s] (0),
// origin [x, y] [m] ([0, 0]) added to every point, and reference/type with its keys:
//   rose:      amplitude [m] (1.0), k [-] (3), period_scale [s/rad] (1.0: the rose's own time scale)
//   circle:    center [x, y] ([0, 0]), radius [m] (1.0), period [s] (30)
//   spline:    waypoints [[x, y], ...], duration [s]
//   waypoints: waypoints [[x, y], ...], speed [m/s] (0.2), loop (false)
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include "amigobot_tracking/core/reference.h"
#include "amigobot_tracking/core/waypoint_reference.h"
#include "amigobot_tracking/ros/conversions.h"
#include "amigobot_tracking/ros/node_command_line.h"

using amigobot_tracking::core::Reference;

namespace {

bool number(const XmlRpc::XmlRpcValue& v, double* out) {
  auto& value = const_cast<XmlRpc::XmlRpcValue&>(v);
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) *out = static_cast<double>(value);
  else if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) *out = static_cast<int>(value);
  else return false;
  return std::isfinite(*out);
}

bool point(const XmlRpc::XmlRpcValue& v, Eigen::Vector2d* out) {
  return v.getType() == XmlRpc::XmlRpcValue::TypeArray && v.size() == 2 && number(v[0], &out->x()) &&
         number(v[1], &out->y());
}

// Reads ~name as [x, y]; absent keeps *out. Throws naming the parameter on a bad value.
void readPoint(const ros::NodeHandle& pnh, const std::string& name, Eigen::Vector2d* out) {
  XmlRpc::XmlRpcValue v;
  if (!pnh.getParam(name, v)) return;
  if (!point(v, out)) throw std::invalid_argument("parameter " + pnh.resolveName(name) + " must be [x, y]");
}

std::vector<Eigen::Vector2d> readWaypoints(const ros::NodeHandle& pnh, const std::string& name) {
  XmlRpc::XmlRpcValue v;
  const std::string where = "parameter " + pnh.resolveName(name);
  if (!pnh.getParam(name, v) || v.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    throw std::invalid_argument(where + " must be a list [[x, y], ...]");
  }
  std::vector<Eigen::Vector2d> points(v.size());
  for (int i = 0; i < v.size(); ++i) {
    if (!point(v[i], &points[i])) throw std::invalid_argument(where + " entry " + std::to_string(i) + " must be [x, y]");
  }
  return points;
}

double readPositive(const ros::NodeHandle& pnh, const std::string& name, double fallback) {
  double value = fallback;
  if (pnh.hasParam(name) && !pnh.getParam(name, value)) {
    throw std::invalid_argument("parameter " + pnh.resolveName(name) + " must be a number");
  }
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument("parameter " + pnh.resolveName(name) + " must be > 0, got " + std::to_string(value));
  }
  ROS_INFO_STREAM("  " << pnh.resolveName(name) << " = " << value);
  return value;
}

std::unique_ptr<Reference> makeReference(const ros::NodeHandle& pnh) {
  std::string type = "circle";
  pnh.getParam("reference/type", type);
  ROS_INFO_STREAM("  " << pnh.resolveName("reference/type") << " = " << type);
  using namespace amigobot_tracking::core;
  try {
    if (type == "rose") {
      return std::make_unique<RoseReference>(readPositive(pnh, "reference/amplitude", 1.0),
                                             readPositive(pnh, "reference/k", 3.0),
                                             readPositive(pnh, "reference/period_scale", 1.0));
    }
    if (type == "circle") {
      Eigen::Vector2d center(0.0, 0.0);
      readPoint(pnh, "reference/center", &center);
      return std::make_unique<CircleReference>(center, readPositive(pnh, "reference/radius", 1.0),
                                               readPositive(pnh, "reference/period", 30.0));
    }
    if (type == "spline") {
      return std::make_unique<SplineReference>(readWaypoints(pnh, "reference/waypoints"),
                                               readPositive(pnh, "reference/duration", 60.0));
    }
    if (type == "waypoints") {
      bool loop = false;
      pnh.getParam("reference/loop", loop);
      return std::make_unique<WaypointReference>(readWaypoints(pnh, "reference/waypoints"),
                                                 readPositive(pnh, "reference/speed", 0.2), loop);
    }
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(e.what()).find("parameter") == 0
                                    ? e.what()
                                    : "parameter " + pnh.resolveName("reference") + ": " + e.what());
  }
  throw std::invalid_argument("parameter " + pnh.resolveName("reference/type") +
                              " must be rose, circle, spline or waypoints, got '" + type + "'");
}

}  // namespace

const amigobot_tracking::ros_layer::NodeHelp kHelp{
    "Broadcasts tf global_frame -> target_frame moving along a reference (rose, circle, spline, waypoints).",
    "global_frame, target_frame, rate, time_scale, start_delay, origin, reference/type and its keys: see the head of "
    "src/tools/reference_publisher.cpp."};

int main(int argc, char** argv) {
  amigobot_tracking::ros_layer::initNode(argc, argv, "reference_publisher", kHelp);
  ros::NodeHandle pnh("~");
  std::string global_frame = "map", target_frame = "target";
  pnh.getParam("global_frame", global_frame);
  pnh.getParam("target_frame", target_frame);
  std::unique_ptr<Reference> reference;
  double rate = 0.0, time_scale = 0.0, start_delay = 0.0;
  Eigen::Vector2d origin(0.0, 0.0);
  try {
    rate = readPositive(pnh, "rate", 50.0);
    time_scale = readPositive(pnh, "time_scale", 1.0);
    pnh.getParam("start_delay", start_delay);
    if (!(std::isfinite(start_delay) && start_delay >= 0.0)) {
      throw std::invalid_argument("parameter " + pnh.resolveName("start_delay") + " must be >= 0");
    }
    readPoint(pnh, "origin", &origin);
    reference = makeReference(pnh);
  } catch (const std::invalid_argument& e) {
    ROS_FATAL_STREAM("reference_publisher refuses to start: " << e.what());
    return 1;
  }
  ROS_INFO_STREAM("reference_publisher: " << global_frame << " -> " << target_frame << " at " << rate
                                          << " Hz, time_scale " << time_scale << ", start_delay " << start_delay
                                          << " s, origin (" << origin.transpose() << ")");

  tf2_ros::TransformBroadcaster broadcaster;
  while (ros::ok() && ros::Time::now().isZero()) ros::WallDuration(0.01).sleep();  // sim time: wait for /clock
  const ros::Time start = ros::Time::now();
  double heading = 0.0;
  ros::Rate loop(rate);
  while (ros::ok()) {
    const ros::Time now = ros::Time::now();
    // Reference time: held at 0 during the delay, then slowed down by time_scale.
    const double tau = std::max(0.0, (now - start).toSec() - start_delay) / time_scale;
    const amigobot_tracking::core::ReferenceState s = reference->at(tau);
    if (s.velocity.norm() > 1e-6) heading = std::atan2(s.velocity.y(), s.velocity.x());
    const Eigen::Vector2d at = origin + s.position;
    broadcaster.sendTransform(
        amigobot_tracking::ros_layer::toTransform(global_frame, target_frame, {at.x(), at.y(), heading}, now));
    ros::spinOnce();
    loop.sleep();
  }
  return 0;
}

// reference_publisher: broadcasts tf global_frame -> target_frame moving along a reference
// (rose, circle, spline, waypoints; core/reference/reference_spec.h), so a
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

#include "amigobot_tracking/core/reference/reference_spec.h"
#include "amigobot_tracking/ros/conversions.h"
#include "amigobot_tracking/ros/master_watch.h"
#include "amigobot_tracking/ros/node_command_line.h"
#include "amigobot_tracking/ros/param_reader.h"

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
  amigobot_tracking::ros_layer::noteParamKey(pnh, name);
  if (!pnh.getParam(name, v)) return;
  if (!point(v, out)) throw std::invalid_argument("parameter " + pnh.resolveName(name) + " must be [x, y]");
}

std::vector<Eigen::Vector2d> readWaypoints(const ros::NodeHandle& pnh, const std::string& name) {
  XmlRpc::XmlRpcValue v;
  amigobot_tracking::ros_layer::noteParamKey(pnh, name);
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

// The plain parameters; origin, reference/center and reference/waypoints are lists (above).
// The curve's keys are core::referenceFields() under reference/ (the simulator's scenarios
// read the same spec).
struct PublisherConfig {
  std::string global_frame = "map";
  std::string target_frame = "target";
  double rate = 50.0;
  double time_scale = 1.0;
  double start_delay = 0.0;
  amigobot_tracking::core::ReferenceSpec reference;

  std::string validate() const { return amigobot_tracking::core::checkFields(fields(), *this); }

  static const amigobot_tracking::core::FieldTable<PublisherConfig>& fields() {
    using P = PublisherConfig;
    using namespace amigobot_tracking::core;
    static const FieldTable<P> table = [] {
      FieldTable<P> t = {
          field("global_frame", &P::global_frame, "-", "frame the target moves in"),
          field("target_frame", &P::target_frame, "-", "the broadcast frame"),
          field("rate", &P::rate, "Hz", "tf broadcasts per second", positive()),
          field("time_scale", &P::time_scale, "-", "> 1 runs the reference slower", positive()),
          field("start_delay", &P::start_delay, "s", "the target waits at its first point this long", nonNegative()),
      };
      include(&t, "reference/", &P::reference, referenceFields());
      return t;
    }();
    return table;
  }
};

std::unique_ptr<Reference> makeReference(const ros::NodeHandle& pnh, PublisherConfig c) {
  try {
    const amigobot_tracking::core::ReferenceCurve& curve = amigobot_tracking::core::referenceCurve(c.reference.type);
    if (curve.center) readPoint(pnh, "reference/center", &c.reference.center);
    if (curve.waypoints) c.reference.waypoints = readWaypoints(pnh, "reference/waypoints");
    return amigobot_tracking::core::makeReference(c.reference);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(e.what()).find("parameter") == 0
                                    ? e.what()
                                    : "parameter " + pnh.resolveName("reference") + ": " + e.what());
  }
}

}  // namespace

const amigobot_tracking::ros_layer::NodeHelp kHelp{
    "Broadcasts tf global_frame -> target_frame moving along a reference (rose, circle, spline, waypoints).",
    "global_frame, target_frame, rate, time_scale, start_delay, origin, reference/type and its keys: see the head of "
    "src/tools/reference_publisher.cpp."};

int main(int argc, char** argv) {
  amigobot_tracking::ros_layer::initNode(argc, argv, "reference_publisher", kHelp);
  ros::NodeHandle pnh("~");
  // A restarted master learns this node's topics again, as the nodelets' (ros/master_watch.h).
  const auto master_watch = amigobot_tracking::ros_layer::MasterWatch::shared();
  PublisherConfig config;
  std::unique_ptr<Reference> reference;
  Eigen::Vector2d origin(0.0, 0.0);
  try {
    const std::string error = amigobot_tracking::ros_layer::readParams(pnh, PublisherConfig::fields(), &config);
    if (!error.empty()) throw std::invalid_argument(error);
    readPoint(pnh, "origin", &origin);
    reference = makeReference(pnh, config);
  } catch (const std::invalid_argument& e) {
    ROS_FATAL_STREAM("reference_publisher refuses to start: " << e.what());
    return 1;
  }
  const std::string &global_frame = config.global_frame, &target_frame = config.target_frame;
  const double rate = config.rate, time_scale = config.time_scale, start_delay = config.start_delay;
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

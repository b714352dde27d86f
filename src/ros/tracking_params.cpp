#include "amigobot_tracking/ros/tracking_params.h"

#include <cmath>
#include <sstream>

#include <ros/console.h>
#include <urdf_parser/urdf_parser.h>

namespace amigobot_tracking {
namespace ros_layer {
namespace {

template <typename T>
const char* typeName();
template <>
const char* typeName<double>() { return "a number"; }
template <>
const char* typeName<int>() { return "an integer"; }
template <>
const char* typeName<bool>() { return "true or false"; }
template <>
const char* typeName<std::string>() { return "a string"; }

// Reads ~name over *value when set; logs the value used. False (with *error naming the
// parameter) when the parameter exists with the wrong type: a typo must not silently
// fall back to a default.
template <typename T>
bool readParam(const ros::NodeHandle& pnh, const std::string& name, T* value, std::string* error) {
  const bool present = pnh.hasParam(name);
  if (present) {
    T read{};
    if (!pnh.getParam(name, read)) {
      *error = "parameter " + pnh.resolveName(name) + " must be " + typeName<T>();
      return false;
    }
    *value = read;
  }
  ROS_INFO_STREAM_NAMED("tracking", "  " << pnh.resolveName(name) << " = " << std::boolalpha << *value
                                         << (present ? "" : " (default)"));
  return true;
}

bool positiveFinite(double v) { return std::isfinite(v) && v > 0.0; }

bool number(const XmlRpc::XmlRpcValue& v, double* out) {
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
    *out = static_cast<double>(const_cast<XmlRpc::XmlRpcValue&>(v));
    return true;
  }
  if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) {
    *out = static_cast<int>(const_cast<XmlRpc::XmlRpcValue&>(v));
    return true;
  }
  return false;
}

// Footprint radius of one urdfdom geometry placed at `origin` in the link frame.
bool geometryRadius(const urdf::GeometrySharedPtr& geometry, const urdf::Pose& origin, double* radius) {
  if (!geometry) return false;
  double r = 0.0;
  switch (geometry->type) {
    case urdf::Geometry::CYLINDER: r = std::static_pointer_cast<urdf::Cylinder>(geometry)->radius; break;
    case urdf::Geometry::SPHERE: r = std::static_pointer_cast<urdf::Sphere>(geometry)->radius; break;
    case urdf::Geometry::BOX: {
      const urdf::Vector3& d = std::static_pointer_cast<urdf::Box>(geometry)->dim;
      r = 0.5 * std::hypot(d.x, d.y);
      break;
    }
    default: return false;  // meshes: no footprint without loading them
  }
  *radius = r + std::hypot(origin.position.x, origin.position.y);
  return true;
}

}  // namespace

std::string TrackingNodeConfig::validate() const {
  std::ostringstream err;
  if (global_frame.empty() || base_frame.empty() || target_frame.empty()) {
    err << (global_frame.empty() ? "global_frame" : base_frame.empty() ? "base_frame" : "target_frame")
        << " must not be empty";
  } else if (global_frame == base_frame || base_frame == target_frame || global_frame == target_frame) {
    err << "global_frame, base_frame and target_frame must differ, got " << global_frame << ", " << base_frame
        << ", " << target_frame;
  } else if (!positiveFinite(control_rate) || control_rate > 1000.0) {
    err << "control_rate must be in (0, 1000] Hz, got " << control_rate;
  } else if (!positiveFinite(pose_timeout)) {
    err << "pose_timeout must be a finite number > 0, got " << pose_timeout;
  } else if (!positiveFinite(scan_timeout)) {
    err << "scan_timeout must be a finite number > 0, got " << scan_timeout;
  } else if (!positiveFinite(clicked_point_radius)) {
    err << "clicked_point_radius must be a finite number > 0, got " << clicked_point_radius;
  } else if (!positiveFinite(robot_v_max)) {
    err << "robot_v_max must be a finite number > 0, got " << robot_v_max;
  } else if (!positiveFinite(robot_w_max)) {
    err << "robot_w_max must be a finite number > 0, got " << robot_w_max;
  } else if (!(std::isfinite(target_exclusion_radius) && target_exclusion_radius >= 0.0)) {
    err << "target_exclusion_radius must be a finite number >= 0 (0 = off), got " << target_exclusion_radius;
  } else if (!positiveFinite(resume_v_accel)) {
    err << "resume_v_accel must be a finite number > 0, got " << resume_v_accel;
  } else if (!positiveFinite(resume_w_accel)) {
    err << "resume_w_accel must be a finite number > 0, got " << resume_w_accel;
  }
  return err.str();
}

std::string readUrdfGeometry(const std::string& xml, const std::string& base_link, const std::string& offset_link,
                             UrdfGeometry* out) {
  *out = UrdfGeometry();
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
  if (!model) return "robot_description is not valid URDF";
  const urdf::LinkConstSharedPtr base = model->getLink(base_link);
  if (!base) return "the URDF has no link '" + base_link + "'";
  if (base->collision) {
    out->found_radius = geometryRadius(base->collision->geometry, base->collision->origin, &out->radius);
  }
  if (!out->found_radius && base->visual) {
    out->found_radius = geometryRadius(base->visual->geometry, base->visual->origin, &out->radius);
  }
  const urdf::LinkConstSharedPtr point = model->getLink(offset_link);
  if (point && point->parent_joint && point->parent_joint->parent_link_name == base_link) {
    out->found_offset = true;
    out->offset = point->parent_joint->parent_to_joint_origin_transform.position.x;
  }
  return "";
}

std::string loadNodeConfig(const ros::NodeHandle& pnh, TrackingNodeConfig* c) {
  ROS_INFO_STREAM_NAMED("tracking", "tracking node parameters:");
  std::string error;
  const bool ok = readParam(pnh, "global_frame", &c->global_frame, &error) &&
                  readParam(pnh, "base_frame", &c->base_frame, &error) &&
                  readParam(pnh, "target_frame", &c->target_frame, &error) &&
                  readParam(pnh, "control_rate", &c->control_rate, &error) &&
                  readParam(pnh, "pose_timeout", &c->pose_timeout, &error) &&
                  readParam(pnh, "scan_timeout", &c->scan_timeout, &error) &&
                  readParam(pnh, "require_scan", &c->require_scan, &error) &&
                  readParam(pnh, "autostart", &c->autostart, &error) &&
                  readParam(pnh, "clicked_point_radius", &c->clicked_point_radius, &error) &&
                  readParam(pnh, "robot_v_max", &c->robot_v_max, &error) &&
                  readParam(pnh, "robot_w_max", &c->robot_w_max, &error) &&
                  readParam(pnh, "target_exclusion_radius", &c->target_exclusion_radius, &error) &&
                  readParam(pnh, "resume_v_accel", &c->resume_v_accel, &error) &&
                  readParam(pnh, "resume_w_accel", &c->resume_w_accel, &error);
  if (!ok) return error;
  const std::string invalid = c->validate();
  return invalid.empty() ? "" : "parameter ~" + invalid;
}

std::string loadControllerConfig(const ros::NodeHandle& pnh, const TrackingNodeConfig& node,
                                 core::ControllerConfig* c) {
  ROS_INFO_STREAM_NAMED("tracking", "controller parameters:");
  std::string error;
  // Geometry: URDF first, explicit parameters override it.
  std::string description_param = "robot_description", offset_link = "control_point";
  if (!readParam(pnh, "robot_description_param", &description_param, &error) ||
      !readParam(pnh, "urdf_offset_link", &offset_link, &error)) {
    return error;
  }
  std::string xml, key;
  // Relative names are searched from ~ upwards (the usual /robot_description, or a namespaced one).
  if (pnh.searchParam(description_param, key) && pnh.getParam(key, xml)) {
    UrdfGeometry urdf;
    const std::string why = readUrdfGeometry(xml, node.base_frame, offset_link, &urdf);
    if (!why.empty()) return "parameter " + key + ": " + why;
    if (urdf.found_radius) c->robot_radius = urdf.radius;
    if (urdf.found_offset) c->offset = urdf.offset;
    ROS_INFO_STREAM_NAMED("tracking", "  URDF " << key << ": radius "
                                                << (urdf.found_radius ? std::to_string(urdf.radius) : "not found")
                                                << ", offset link '" << offset_link << "' "
                                                << (urdf.found_offset ? std::to_string(urdf.offset) : "not found"));
  } else {
    ROS_INFO_STREAM_NAMED("tracking", "  no URDF '" << description_param << "' on the parameter server"
                                                      << ": robot_radius and offset come from parameters/defaults");
  }
  core::EstimatorConfig& e = c->estimator;
  const bool ok = readParam(pnh, "robot_radius", &c->robot_radius, &error) &&
                  readParam(pnh, "offset", &c->offset, &error) && readParam(pnh, "v_max", &c->v_max, &error) &&
                  readParam(pnh, "w_max", &c->w_max, &error) && readParam(pnh, "k_d", &c->k_d, &error) &&
                  readParam(pnh, "k_o", &c->k_o, &error) && readParam(pnh, "lambda", &c->lambda, &error) &&
                  readParam(pnh, "rho_inf", &c->rho_inf, &error) && readParam(pnh, "rho_0", &c->rho_0, &error) &&
                  readParam(pnh, "k_r", &c->k_r, &error) && readParam(pnh, "delta", &c->delta, &error) &&
                  readParam(pnh, "body_safe", &c->body_safe, &error) &&
                  readParam(pnh, "min_margin", &c->min_margin, &error) &&
                  readParam(pnh, "max_error_ratio", &c->max_error_ratio, &error) &&
                  readParam(pnh, "max_relaxation_interval", &c->max_relaxation_interval, &error) &&
                  readParam(pnh, "estimator/a1", &e.a1, &error) && readParam(pnh, "estimator/a2", &e.a2, &error) &&
                  readParam(pnh, "estimator/lambda_o", &e.lambda_o, &error) &&
                  readParam(pnh, "estimator/rho_o", &e.rho_o, &error) &&
                  readParam(pnh, "estimator/rho_o0", &e.rho_o0, &error) &&
                  readParam(pnh, "estimator/jump_threshold", &e.jump_threshold, &error) &&
                  // Beyond the paper (each off by default = the paper's law).
                  readParam(pnh, "tangential_avoidance", &c->tangential_avoidance, &error) &&
                  readParam(pnh, "k_t", &c->k_t, &error) &&
                  readParam(pnh, "tangential_hysteresis", &c->tangential_hysteresis, &error) &&
                  readParam(pnh, "moving_obstacles", &c->moving_obstacles, &error) &&
                  readParam(pnh, "obstacle_horizon", &c->obstacle_horizon, &error) &&
                  readParam(pnh, "predict_target", &c->predict_target, &error) &&
                  readParam(pnh, "compensate_pose_age", &c->compensate_pose_age, &error) &&
                  readParam(pnh, "max_prediction", &c->max_prediction, &error);
  if (!ok) return error;
  const std::string invalid = c->validate();
  if (!invalid.empty()) return "parameter ~" + invalid;
  std::ostringstream err;
  if (c->v_max > node.robot_v_max) {
    err << "parameter ~v_max must be <= ~robot_v_max = " << node.robot_v_max << ", got " << c->v_max;
  } else if (c->w_max > node.robot_w_max) {
    err << "parameter ~w_max must be <= ~robot_w_max = " << node.robot_w_max << ", got " << c->w_max;
  } else {
    const std::string band = core::bandReachError(*c, 1.0 / node.control_rate);
    if (!band.empty()) err << "parameter ~" << band << " (~control_rate = " << node.control_rate << " Hz)";
  }
  return err.str();
}

std::string loadObstacleTrackerConfig(const ros::NodeHandle& pnh, core::ObstacleTrackerConfig* c) {
  ROS_INFO_STREAM_NAMED("tracking", "laser obstacle tracking parameters (used with moving_obstacles):");
  std::string error;
  const bool ok = readParam(pnh, "obstacle_tracker/gate", &c->gate, &error) &&
                  readParam(pnh, "obstacle_tracker/position_gain", &c->position_gain, &error) &&
                  readParam(pnh, "obstacle_tracker/velocity_gain", &c->velocity_gain, &error) &&
                  readParam(pnh, "obstacle_tracker/max_speed", &c->max_speed, &error) &&
                  readParam(pnh, "obstacle_tracker/still_speed", &c->still_speed, &error) &&
                  readParam(pnh, "obstacle_tracker/forget_after", &c->forget_after, &error) &&
                  readParam(pnh, "obstacle_tracker/min_hits", &c->min_hits, &error);
  if (!ok) return error;
  const std::string invalid = c->validate();
  return invalid.empty() ? "" : "parameter ~obstacle_tracker/" + invalid;
}

std::string loadScanObstacleConfig(const ros::NodeHandle& pnh, core::ScanObstacleConfig* c) {
  ROS_INFO_STREAM_NAMED("tracking", "laser obstacle parameters:");
  std::string error;
  const bool ok = readParam(pnh, "scan/cluster_tolerance", &c->cluster_tolerance, &error) &&
                  readParam(pnh, "scan/max_disk_radius", &c->max_disk_radius, &error) &&
                  readParam(pnh, "scan/min_disk_radius", &c->min_disk_radius, &error) &&
                  readParam(pnh, "scan/min_cluster_points", &c->min_cluster_points, &error) &&
                  readParam(pnh, "scan/max_range", &c->max_range, &error);
  if (!ok) return error;
  const std::string invalid = c->validate();
  return invalid.empty() ? "" : "parameter ~scan/" + invalid;
}

std::string loadVirtualObstacles(const ros::NodeHandle& pnh, std::vector<core::VirtualObstacle>* list) {
  list->clear();
  XmlRpc::XmlRpcValue value;
  if (!pnh.getParam("virtual_obstacles", value)) {
    ROS_INFO_STREAM_NAMED("tracking", "  " << pnh.resolveName("virtual_obstacles") << " = [] (default)");
    return "";
  }
  const std::string where = "parameter " + pnh.resolveName("virtual_obstacles");
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray) return where + " must be a list";
  for (int i = 0; i < value.size(); ++i) {
    XmlRpc::XmlRpcValue& entry = value[i];
    const std::string at = where + " entry " + std::to_string(i);
    if (entry.getType() != XmlRpc::XmlRpcValue::TypeStruct) return at + " must be {id, center: [x, y], radius}";
    core::VirtualObstacle o;
    o.id = "yaml_" + std::to_string(i);
    if (entry.hasMember("id")) {
      if (entry["id"].getType() != XmlRpc::XmlRpcValue::TypeString) return at + ": id must be a string";
      o.id = static_cast<std::string>(entry["id"]);
    }
    if (!entry.hasMember("center") || entry["center"].getType() != XmlRpc::XmlRpcValue::TypeArray ||
        entry["center"].size() != 2 || !number(entry["center"][0], &o.disk.center.x()) ||
        !number(entry["center"][1], &o.disk.center.y())) {
      return at + ": center must be [x, y] in metres";
    }
    if (!entry.hasMember("radius") || !number(entry["radius"], &o.disk.radius)) {
      return at + ": radius must be a number in metres";
    }
    list->push_back(o);
    ROS_INFO_STREAM_NAMED("tracking", "  virtual obstacle '" << o.id << "' at (" << o.disk.center.x() << ", "
                                                             << o.disk.center.y() << ") radius " << o.disk.radius);
  }
  core::VirtualObstacleSet check;
  std::string why;
  if (!check.assign(*list, &why)) return where + " " + why;
  return "";
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

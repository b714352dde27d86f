#include "amigobot_tracking/ros/tracking_params.h"

#include <cmath>
#include <sstream>

#include <ros/console.h>
#include <urdf_parser/urdf_parser.h>

#include "amigobot_tracking/ros/param_reader.h"

namespace amigobot_tracking {
namespace ros_layer {
namespace {

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

const core::FieldTable<TrackingNodeConfig>& trackingNodeFields() {
  using N = TrackingNodeConfig;
  using core::field;
  using core::positive;
  static const core::FieldTable<N> table = [] {
    core::FieldTable<N> t = {
      field("global_frame", &N::global_frame, "-", "frame of poses, obstacles and markers"),
      field("base_frame", &N::base_frame, "-", "the robot being controlled (REP 105)"),
      field("target_frame", &N::target_frame, "-",
            "the tracked target (reference_publisher's frame or another robot's base_link)"),
      field("control_rate", &N::control_rate, "Hz", "control timer rate, one controller step per tick",
            core::interval(1.0, false, 1000.0, false)),
      field("pose_timeout", &N::pose_timeout, "s", "robot pose or target older than this -> zero command",
            core::boundedTimeout()),
      field("scan_timeout", &N::scan_timeout, "s", "scan older than this -> zero command (when require_scan)",
            core::boundedTimeout()),
      field("future_stamp_tolerance", &N::future_stamp_tolerance, "s",
            "a pose, target or scan stamped further ahead of this node's clock (or stamped 0) is stale, named in "
            "the status; tf samples stamped further ahead of their arrival are dropped, and a publisher's clock "
            "offset beyond it is named; in [0, 1]",
            core::interval(0.0, false, 1.0, false)),
      field("require_scan", &N::require_scan, "-", "false: run on virtual obstacles alone (no laser)"),
      field("open_space", &N::open_space, "-",
            "true: a scan with no return within range_max is an empty room; false: such a scan is a blind laser, "
            "refused with an ERROR (the robot stops after scan_timeout)"),
      field("min_scan_rate_fraction", &N::min_scan_rate_fraction, "-",
            "a scan rate measured below this fraction of the one the laser promises (1 / scan_time, or "
            "expected_scan_rate) stops the robot with an ERROR naming both rates; in [0, 1), 0: off",
            core::interval(0.0, false, 1.0, true)),
      field("expected_scan_rate", &N::expected_scan_rate, "Hz",
            "the laser's scan rate, for a driver that leaves scan_time 0 (or gets it wrong); 0: each scan's "
            "scan_time",
            core::interval(0.0, false, 1000.0, false)),
      field("autostart", &N::autostart, "-", "enable tracking at start (else call ~enable)"),
      field("clicked_point_radius", &N::clicked_point_radius, "m",
            "radius of the disk an rviz Publish Point click adds", core::boundedRadius()),
      field("target_exclusion_radius", &N::target_exclusion_radius, "m",
            "laser disks this close to the target are the followed robot, not obstacles (0: off; never applied to "
            "virtual obstacles)",
            core::boundedRadiusOrOff()),
      field("resume_v_accel", &N::resume_v_accel, "m/s^2",
            "after a stop of the node's own (stale inputs, disable -> enable, a refused step) v leaves zero at "
            "most this fast (AmigoBot trans_accel); stops stay immediate",
            positive()),
      field("resume_w_accel", &N::resume_w_accel, "rad/s^2",
            "after a stop of the node's own omega leaves zero at most this fast (AmigoBot rot_accel, 100 deg/s^2); "
            "(v, omega) is scaled as a whole, so it keeps its direction and the diamond",
            positive()),
      field("robot_description_param", &N::robot_description_param, "-",
            "parameter holding the URDF, the source of R and r (a relative name is searched from ~ upwards)"),
      field("urdf_offset_link", &N::urdf_offset_link, "-",
            "URDF link fixed to base_frame whose x is the offset r of the controlled point"),
    };
    core::include(&t, "", &N::robot, robotSourceFields());
    return t;
  }();
  return table;
}

std::string TrackingNodeConfig::validate() const {
  const std::string bad = core::checkFields(trackingNodeFields(), *this);
  if (!bad.empty()) return bad;
  std::ostringstream err;
  if (global_frame.empty() || base_frame.empty() || target_frame.empty()) {
    err << (global_frame.empty() ? "global_frame" : base_frame.empty() ? "base_frame" : "target_frame")
        << ": must not be empty";
  } else if (global_frame == base_frame || base_frame == target_frame || global_frame == target_frame) {
    err << "target_frame: global_frame, base_frame and target_frame must differ, got " << global_frame << ", "
        << base_frame << ", " << target_frame;
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
  std::string error = readParams(pnh, trackingNodeFields(), c);
  if (!error.empty()) return error;
  try {
    c->description = loadRobot(c->robot);
  } catch (const std::exception& e) {
    return e.what();
  }
  return retiredRobotLimitError(pnh, *c);
}

std::string retiredRobotLimitError(const ros::NodeHandle& pnh, const TrackingNodeConfig& node) {
  for (const char* key : {"robot_v_max", "robot_w_max"}) {
    noteParamKey(pnh, key);
    if (pnh.hasParam(key))
      return std::string("~") + key + ": no longer a parameter: the robot's limits are v_max and w_max of its robot file (" +
             node.description.origin() +
             ", ~robot_params); set them there, or tighten tracking's own ~v_max/~w_max";
  }
  return "";
}

std::string loadControllerConfig(const ros::NodeHandle& pnh, const TrackingNodeConfig& node,
                                 core::ControllerConfig* c) {
  ROS_INFO_STREAM_NAMED("tracking", "controller parameters:");
  // Geometry: URDF first, explicit parameters override it.
  const std::string& description_param = node.robot_description_param;
  const std::string& offset_link = node.urdf_offset_link;
  std::string xml, key;
  noteParamKey(pnh, description_param);
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
  // Tracking's diamond defaults to the robot's (its robot file), and may only be smaller.
  c->v_max = node.description.v_max;
  c->w_max = node.description.w_max;
  // The recommended law brakes with the base it drives: its robot file's ramps and delays.
  c->actuator = node.description.dynamics;
  const std::string error = readParams(pnh, core::controllerFields(), c);
  if (!error.empty()) return error;
  std::ostringstream err;
  const std::string outside = robotLimitError(node, *c);
  if (!outside.empty()) {
    err << "parameter ~" << outside;
  } else {
    const std::string band = core::bandReachError(*c, 1.0 / node.control_rate);
    if (!band.empty()) err << "parameter ~" << band << " (~control_rate = " << node.control_rate << " Hz)";
  }
  return err.str();
}

std::string robotLimitError(const TrackingNodeConfig& node, const core::ControllerConfig& c) {
  return core::diamondInsideError(node.description, c.v_max, c.w_max, "v_max", "w_max", node.description.origin());
}

std::string loadObstacleTrackerConfig(const ros::NodeHandle& pnh, core::ObstacleTrackerConfig* c) {
  ROS_INFO_STREAM_NAMED("tracking", "laser obstacle tracking parameters (used with moving_obstacles):");
  return readParams(pnh, core::obstacleTrackerFields(), c, "obstacle_tracker/");
}

std::string loadScanObstacleConfig(const ros::NodeHandle& pnh, core::ScanObstacleConfig* c) {
  ROS_INFO_STREAM_NAMED("tracking", "laser obstacle parameters:");
  return readParams(pnh, core::scanObstacleFields(), c, "scan/");
}

std::string loadVirtualObstacles(const ros::NodeHandle& pnh, std::vector<core::VirtualObstacle>* list) {
  list->clear();
  XmlRpc::XmlRpcValue value;
  noteParamKey(pnh, "virtual_obstacles");
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

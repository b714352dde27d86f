#include "amigobot_tracking/ros/conversions.h"

#include <algorithm>
#include <cmath>

#include <tf2/LinearMath/Quaternion.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

namespace amigobot_tracking {
namespace ros_layer {
namespace {

Eigen::Quaterniond quaternion(const geometry_msgs::Quaternion& q) { return {q.w, q.x, q.y, q.z}; }

geometry_msgs::Vector3 vector3(const Eigen::Vector2d& v) {
  geometry_msgs::Vector3 m;
  m.x = v.x();
  m.y = v.y();
  return m;
}

geometry_msgs::Point point(const Eigen::Vector2d& v) {
  geometry_msgs::Point m;
  m.x = v.x();
  m.y = v.y();
  return m;
}

}  // namespace

core::Pose2 toPose2(const geometry_msgs::Transform& t) {
  return {t.translation.x, t.translation.y, tf2::getYaw(t.rotation)};
}

Eigen::Affine2d toAffine2d(const geometry_msgs::Transform& t) {
  Eigen::Affine2d a = Eigen::Affine2d::Identity();
  a.linear() = quaternion(t.rotation).normalized().toRotationMatrix().topLeftCorner<2, 2>();
  a.translation() << t.translation.x, t.translation.y;
  return a;
}

core::ScanGeometry toScanGeometry(const sensor_msgs::LaserScan& scan) {
  return {scan.angle_min, scan.angle_increment, scan.range_min, scan.range_max};
}

geometry_msgs::Twist toTwist(const core::Twist2& u) {
  geometry_msgs::Twist m;
  m.linear.x = u.v;
  m.angular.z = u.omega;
  return m;
}

geometry_msgs::TransformStamped toTransform(const std::string& parent, const std::string& child,
                                            const core::Pose2& pose, const ros::Time& stamp) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = pose.x;
  t.transform.translation.y = pose.y;
  t.transform.rotation = toQuaternion(pose.theta);
  return t;
}

geometry_msgs::Quaternion toQuaternion(double yaw) {
  tf2::Quaternion q;
  q.setRPY(0.0, 0.0, yaw);
  return tf2::toMsg(q);
}

void fillState(const core::ControllerOutput& out, TrackingState* s) {
  s->valid = out.valid;
  s->t = out.t;
  s->e = vector3(out.e);
  s->e_norm = out.e.norm();
  s->rho = out.rho;
  s->p_r = point(out.p_r);
  s->p_d = point(out.p_d);
  s->v_hat = vector3(out.v_hat);
  s->v_d = out.u_d.v;
  s->omega_d = out.u_d.omega;
  s->v = out.u.v;
  s->omega = out.u.omega;
  s->u_c = vector3(out.u_c);
  s->u_t = vector3(out.u_t);
  s->passing_side = out.passing_side;
  s->saturated = out.active.saturated;
  s->avoiding = out.active.avoiding;
  s->conflict = out.active.conflict;
  s->rho_relaxed = out.active.rho_relaxed;
  s->envelope_widened = out.active.envelope_widened;
  s->yielding = out.active.yielding;
  s->detected_obstacles = out.detected_obstacles;
  s->min_clearance = out.min_clearance;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

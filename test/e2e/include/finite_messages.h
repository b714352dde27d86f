// What counts as "published as NaN" per message type, for nan_watcher.h: each judge returns ""
// when the message is fine, else the first field that is not, named. Allowed non-finite values,
// and only these:
//   - sensor_msgs/LaserScan ranges: +inf (no return within range_max) and -inf (closer than
//     range_min), REP 117; never NaN (our drivers map every beam to a reading or +-inf). The
//     header numbers (angles, times, range limits) and intensities must be finite.
//   - sensor_msgs/Range range: +inf / -inf, REP 117 (the sonar: no echo is +inf).
//   - amigobot_tracking/TrackingState min_clearance, min_clearance_body: +inf ("no obstacle",
//     as the message documents); pose_age, target_age: +inf (a stamp not trusted, core/supervision/input_age.h).
//   - diagnostic_msgs/DiagnosticArray values: text; one that reads as a number must not be NaN
//     (NaN) or -inf; +inf is allowed (an age of a stamp not trusted, as in TrackingState).
// Everything else numeric (tf, Twist, Odometry, poses, markers, paths) must be finite.
#pragma once

#include <cmath>
#include <cstdlib>
#include <string>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/Range.h>
#include <tf2_msgs/TFMessage.h>
#include <visualization_msgs/MarkerArray.h>

#include "amigobot_tracking/TrackingState.h"

namespace e2e {
namespace finite {

inline bool ok(double v) { return std::isfinite(v); }
inline bool ok(const geometry_msgs::Vector3& v) { return ok(v.x) && ok(v.y) && ok(v.z); }
inline bool ok(const geometry_msgs::Point& p) { return ok(p.x) && ok(p.y) && ok(p.z); }
inline bool ok(const geometry_msgs::Quaternion& q) { return ok(q.x) && ok(q.y) && ok(q.z) && ok(q.w); }
inline bool ok(const geometry_msgs::Pose& p) { return ok(p.position) && ok(p.orientation); }
inline bool ok(const geometry_msgs::Twist& t) { return ok(t.linear) && ok(t.angular); }
inline bool ok(const std_msgs::ColorRGBA& c) { return ok(c.r) && ok(c.g) && ok(c.b) && ok(c.a); }
// +inf allowed (an age never seen / not trusted, a clearance with nothing near): not NaN, not -inf.
inline bool okOrPlusInf(double v) { return ok(v) || v == INFINITY; }

inline std::string judge(const tf2_msgs::TFMessage& m) {
  for (const auto& t : m.transforms)
    if (!ok(t.transform.translation) || !ok(t.transform.rotation)) return t.header.frame_id + " -> " + t.child_frame_id;
  return "";
}
inline std::string judge(const geometry_msgs::Twist& m) { return ok(m) ? "" : "twist"; }
inline std::string judge(const nav_msgs::Odometry& m) { return ok(m.pose.pose) && ok(m.twist.twist) ? "" : "odometry"; }
inline std::string judge(const geometry_msgs::PoseWithCovarianceStamped& m) { return ok(m.pose.pose) ? "" : "pose"; }
inline std::string judge(const geometry_msgs::PoseStamped& m) { return ok(m.pose) ? "" : "pose"; }

inline std::string judge(const sensor_msgs::LaserScan& m) {
  if (!ok(m.angle_min) || !ok(m.angle_max) || !ok(m.angle_increment) || !ok(m.time_increment) || !ok(m.scan_time) ||
      !ok(m.range_min) || !ok(m.range_max))
    return "scan header numbers (angles, times, range limits)";
  for (std::size_t i = 0; i < m.ranges.size(); ++i)
    if (std::isnan(m.ranges[i])) return "scan range " + std::to_string(i) + " is NaN (REP 117 allows +-inf only here)";
  for (std::size_t i = 0; i < m.intensities.size(); ++i)
    if (!ok(m.intensities[i])) return "scan intensity " + std::to_string(i);
  return "";
}

inline std::string judge(const sensor_msgs::Range& m) {
  return !std::isnan(m.range) && ok(m.field_of_view) && ok(m.min_range) && ok(m.max_range) ? "" : "range";
}

inline std::string judge(const visualization_msgs::MarkerArray& m) {
  for (const auto& k : m.markers) {
    bool good = ok(k.pose) && ok(k.scale) && ok(k.color);
    for (const auto& p : k.points) good = good && ok(p);
    for (const auto& c : k.colors) good = good && ok(c);
    if (!good) return "marker " + k.ns + "/" + std::to_string(k.id);
  }
  return "";
}

inline std::string judge(const nav_msgs::Path& m) {
  for (const auto& p : m.poses)
    if (!ok(p.pose)) return "path pose";
  return "";
}

inline std::string judge(const amigobot_tracking::TrackingState& m) {
  const double plain[] = {m.t, m.e_norm, m.rho, m.v_d, m.omega_d, m.v, m.omega};
  for (double v : plain)
    if (!ok(v)) return "tracking state number";
  if (!ok(m.e) || !ok(m.p_r) || !ok(m.p_d) || !ok(m.v_hat) || !ok(m.u_c) || !ok(m.u_t)) return "tracking state vector";
  if (!okOrPlusInf(m.min_clearance) || !okOrPlusInf(m.min_clearance_body) || !okOrPlusInf(m.pose_age) ||
      !okOrPlusInf(m.target_age))
    return "tracking state clearance or age (+inf allowed, not NaN)";
  return "";
}

inline std::string judge(const diagnostic_msgs::DiagnosticArray& m) {
  for (const auto& s : m.status) {
    for (const auto& kv : s.values) {
      char* end = nullptr;
      const double v = std::strtod(kv.value.c_str(), &end);
      if (end != kv.value.c_str() && *end == '\0' && !okOrPlusInf(v)) return s.name + ": " + kv.key + " = " + kv.value;
    }
  }
  return "";
}

}  // namespace finite
}  // namespace e2e

#include "amigobot_tracking/ros/markers.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace amigobot_tracking {
namespace ros_layer {
namespace {

using visualization_msgs::Marker;

std_msgs::ColorRGBA color(float r, float g, float b, float a = 1.0f) { return markerColor(r, g, b, a); }

geometry_msgs::Point point(const Eigen::Vector2d& p, double z = 0.0) { return markerPoint(p, z); }

class Builder {
 public:
  explicit Builder(const MarkerScene& scene) : scene_(scene) {
    // With a frame, rviz's tf filter passes DELETEALL in order with the ADDs; without one it
    // fails the filter and rviz applies it at once, ahead of the previous message's queued ADDs,
    // so a marker whose id changed between two messages (the status text) stayed twice.
    Marker clear;
    clear.header.frame_id = scene.frame;
    clear.header.stamp = scene.stamp;
    clear.action = Marker::DELETEALL;
    array_.markers.push_back(clear);
  }

  Marker& add(const std::string& ns, int type, const std_msgs::ColorRGBA& c) {
    Marker m;
    m.header.frame_id = scene_.frame;
    m.header.stamp = scene_.stamp;
    m.ns = ns;
    m.id = next_id_[ns]++;  // stable per namespace: the same element keeps its (ns, id) from step to step
    m.type = type;
    m.action = Marker::ADD;
    m.pose.orientation.w = 1.0;
    m.scale.x = m.scale.y = m.scale.z = 0.02;
    m.color = c;
    array_.markers.push_back(m);
    return array_.markers.back();
  }

  void disk(const std::string& ns, const Eigen::Vector2d& c, double radius, const std_msgs::ColorRGBA& col,
            double height = 0.02) {
    Marker& m = add(ns, Marker::CYLINDER, col);
    m.pose.position = point(c, 0.5 * height);
    m.scale.x = m.scale.y = 2.0 * radius;
    m.scale.z = height;
  }

  void circle(const std::string& ns, const Eigen::Vector2d& c, double radius, const std_msgs::ColorRGBA& col) {
    Marker& m = add(ns, Marker::LINE_STRIP, col);
    const int segments = 48;
    for (int i = 0; i <= segments; ++i) {
      const double a = 2.0 * M_PI * i / segments;
      m.points.push_back(point(c + radius * Eigen::Vector2d(std::cos(a), std::sin(a)), 0.01));
    }
  }

  void arrow(const std::string& ns, const Eigen::Vector2d& from, const Eigen::Vector2d& vec,
             const std_msgs::ColorRGBA& col) {
    Marker& m = add(ns, Marker::ARROW, col);
    m.points = {point(from, 0.05), point(from + vec, 0.05)};
    m.scale.x = 0.02;  // shaft diameter
    m.scale.y = 0.05;  // head diameter
    m.scale.z = 0.05;
  }

  void text(const std::string& ns, const Eigen::Vector2d& at, const std::string& s, double height = 0.12,
            const std_msgs::ColorRGBA& col = color(1, 1, 1)) {
    Marker& m = add(ns, Marker::TEXT_VIEW_FACING, col);
    m.pose.position = point(at, 0.4);
    m.scale.z = height;
    m.text = s;
  }

  visualization_msgs::MarkerArray take() { return std::move(array_); }

 private:
  const MarkerScene& scene_;
  visualization_msgs::MarkerArray array_;
  std::map<std::string, int> next_id_;
};

}  // namespace

std_msgs::ColorRGBA markerColor(float r, float g, float b, float a) {
  std_msgs::ColorRGBA c;
  c.r = r;
  c.g = g;
  c.b = b;
  c.a = a;
  return c;
}

geometry_msgs::Point markerPoint(const Eigen::Vector2d& p, double z) {
  geometry_msgs::Point m;
  m.x = p.x();
  m.y = p.y();
  m.z = z;
  return m;
}

visualization_msgs::MarkerArray buildMarkers(const MarkerScene& scene) {
  Builder b(scene);
  const core::ControllerConfig& config = *scene.config;
  const core::ControllerOutput& out = scene.output;
  const double reach = config.effectiveRadius() + config.delta;  // detection distance from p_r, plus r_j

  if (scene.detected) {
    for (const core::Disk& d : *scene.detected) {
      const bool near = scene.have_output && (out.p_r - d.center).norm() <= reach + d.radius;
      b.disk("laser_obstacles", d.center, d.radius, near ? color(1.0f, 0.45f, 0.0f, 0.9f) : color(0.6f, 0.6f, 0.6f, 0.6f));
    }
  }
  if (scene.virtual_obstacles) {
    for (const core::VirtualObstacle& o : scene.virtual_obstacles->all()) {
      const bool near = scene.have_output && (out.p_r - o.disk.center).norm() <= reach + o.disk.radius;
      b.disk("virtual_obstacles", o.disk.center, o.disk.radius,
             near ? color(0.9f, 0.1f, 0.9f, 0.9f) : color(0.6f, 0.2f, 0.8f, 0.6f), 0.3);
      b.text("virtual_obstacle_ids", o.disk.center, o.id, 0.15);
    }
  }
  if (scene.have_pose) {
    const Eigen::Vector2d centre = scene.pose.position();
    b.disk("body", centre, config.robot_radius, color(0.2f, 0.4f, 1.0f, 0.5f), 0.1);
  }
  if (scene.have_output) {
    // rho circle around the target, green when |e| << rho, red as |e| approaches rho.
    const double ratio = std::clamp(out.e.norm() / std::max(out.rho, 1e-9), 0.0, 1.0);
    b.circle("rho", out.p_d, out.rho, color(static_cast<float>(ratio), static_cast<float>(1.0 - ratio), 0.0f));
    b.disk("target", out.p_d, 0.05, color(1.0f, 0.2f, 0.2f), 0.1);
    b.arrow("target_velocity", out.p_d, out.v_hat, color(1.0f, 0.6f, 0.6f));
    b.disk("offset_point", out.p_r, 0.04, color(0.0f, 1.0f, 1.0f), 0.12);
    b.circle("safety_disk", out.p_r, config.effectiveRadius(), color(0.0f, 0.8f, 1.0f, 0.8f));
    b.arrow("u_c", out.p_r, config.k_o * out.u_c, color(1.0f, 1.0f, 0.0f));
  }
  if (scene.have_pose) {
    // The diamond |v|/v_max + |w|/w_max <= 1 drawn 0.6 m to the robot's left in the map,
    // v up, w left, half-size `s`; the applied (v, w) green, desired (v_d, w_d) red.
    const double s = 0.25;
    const Eigen::Vector2d at = scene.pose.position() + Eigen::Vector2d(0.0, 0.6 + s);
    Marker& diamond = b.add("diamond", Marker::LINE_STRIP, color(0.8f, 0.8f, 0.8f));
    for (const Eigen::Vector2d& corner : {Eigen::Vector2d(0, s), Eigen::Vector2d(-s, 0), Eigen::Vector2d(0, -s),
                                          Eigen::Vector2d(s, 0), Eigen::Vector2d(0, s)}) {
      diamond.points.push_back(point(at + corner, 0.01));
    }
    auto plot = [&](const core::Twist2& u) {
      const double v = std::clamp(u.v / config.v_max, -2.0, 2.0), w = std::clamp(u.omega / config.w_max, -2.0, 2.0);
      return point(at + s * Eigen::Vector2d(-w, v), 0.02);
    };
    const core::Twist2 zero;
    Marker& applied = b.add("diamond_u", Marker::POINTS, color(0.1f, 1.0f, 0.1f));
    applied.scale.x = applied.scale.y = 0.05;
    applied.points.push_back(plot(scene.have_output ? out.u : zero));
    Marker& desired = b.add("diamond_u_d", Marker::POINTS, color(1.0f, 0.1f, 0.1f));
    desired.scale.x = desired.scale.y = 0.035;
    desired.points.push_back(plot(scene.have_output ? out.u_d : zero));

    std::ostringstream line;
    line.precision(2);
    line << std::fixed;
    if (scene.have_output) {
      line << "|e| " << out.e.norm() << " m  rho " << out.rho << " m";
      if (out.active.saturated) line << "  saturated";
      if (out.active.avoiding) line << "  avoiding(" << out.detected_obstacles << ")";
      if (out.active.conflict) line << "  conflict";
      if (out.active.rho_relaxed) line << "  rho_relaxed";
      if (out.active.envelope_widened) line << "  envelope_widened";
      if (out.active.yielding) line << "  yielding";
      line << "  ";
    }
    line << scene.status;
    b.text("text", scene.pose.position() + Eigen::Vector2d(0.0, -0.5), line.str());
    // What the shapes are (untick the "legend" namespace in rviz's Displays panel to hide it).
    b.text("legend", scene.pose.position() + Eigen::Vector2d(0.0, -1.0),
           "white diamond: (v, w) limits U, green dot applied, red desired\n"
           "cyan circle: safety disk R+r around the offset point (cyan dot)\n"
           "yellow arrow: repulsion k_o u_c; red dot + pink arrow: target, v_hat\n"
           "ring around the target: rho (green: |e| << rho, red: near it)",
           0.09, color(0.85f, 0.85f, 0.85f));
  }
  return b.take();
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

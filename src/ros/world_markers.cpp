#include "amigobot_tracking/ros/world_markers.h"

#include <cmath>

#include "amigobot_tracking/ros/markers.h"

namespace amigobot_tracking {
namespace ros_layer {
const core::FieldTable<WorldMarkersConfig>& worldMarkersFields() {
  using W = WorldMarkersConfig;
  static const core::FieldTable<W> table = {
      core::field("world_file", &W::world_file, "-", "world YAML (obstacles, walls, polygons); required"),
      core::field("frame_id", &W::frame_id, "-", "frame of the world's coordinates"),
      core::field("height", &W::height, "m", "drawn height of walls and disks", core::positive()),
      core::field("wall_thickness", &W::wall_thickness, "m", "drawn thickness of a wall", core::positive()),
  };
  return table;
}

std::string WorldMarkersConfig::validate() const {
  const std::string bad = core::checkFields(worldMarkersFields(), *this);
  if (!bad.empty()) return bad;
  if (world_file.empty()) return "world_file: must name a world YAML";
  if (frame_id.empty()) return "frame_id: must not be empty";
  return "";
}

visualization_msgs::MarkerArray worldMarkers(const world::World& world, const WorldMarkersConfig& config) {
  using visualization_msgs::Marker;
  visualization_msgs::MarkerArray array;
  Marker clear;
  clear.action = Marker::DELETEALL;
  array.markers.push_back(clear);
  const auto add = [&](const std::string& ns, int type, const std_msgs::ColorRGBA& c) -> Marker& {
    Marker m;
    m.header.frame_id = config.frame_id;
    m.ns = ns;
    m.id = static_cast<int>(array.markers.size());
    m.type = type;
    m.action = Marker::ADD;
    m.pose.orientation.w = 1.0;
    m.color = c;
    array.markers.push_back(m);
    return array.markers.back();
  };
  // Muted colours, none of which the tracking markers use (test/rviz/check_rviz_markers.py
  // tells those apart by colour).
  for (const core::Disk& d : world.obstacles) {
    Marker& m = add("disks", Marker::CYLINDER, markerColor(0.45f, 0.55f, 0.45f, 0.8f));
    m.pose.position = markerPoint(d.center, 0.5 * config.height);
    m.scale.x = m.scale.y = 2.0 * d.radius;
    m.scale.z = config.height;
  }
  for (const world::Segment& s : world.walls) {
    Marker& m = add("walls", Marker::CUBE, markerColor(0.7f, 0.7f, 0.75f, 0.7f));
    const Eigen::Vector2d along = s.to - s.from;
    const double yaw = std::atan2(along.y(), along.x());
    m.pose.position = markerPoint(0.5 * (s.from + s.to), 0.5 * config.height);
    m.pose.orientation.z = std::sin(0.5 * yaw);
    m.pose.orientation.w = std::cos(0.5 * yaw);
    m.scale.x = along.norm();
    m.scale.y = config.wall_thickness;
    m.scale.z = config.height;
  }
  for (const world::Polygon& p : world.polygons) {
    Marker& m = add("polygons", Marker::LINE_STRIP, markerColor(0.75f, 0.55f, 0.35f, 1.0f));
    m.scale.x = config.wall_thickness;
    for (const Eigen::Vector2d& v : p.points) m.points.push_back(markerPoint(v, 0.02));
    m.points.push_back(markerPoint(p.points.front(), 0.02));
  }
  return array;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

// The world file drawn for rviz (visualization_msgs/MarkerArray): disks as cylinders, walls
// as thin boxes, solid polygons as closed outlines. Published latched by world_markers.
#pragma once

#include <string>

#include <visualization_msgs/MarkerArray.h>

#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/world/world.h"

namespace amigobot_tracking {
namespace ros_layer {

struct WorldMarkersConfig {
  std::string world_file;        // world YAML (world/world.h); required
  std::string frame_id = "map";  // frame of the world's coordinates
  double height = 0.4;           // [m] drawn height of walls and disks
  double wall_thickness = 0.05;  // [m] drawn thickness of a wall
  std::string validate() const;  // "" or "key: reason"
};

const core::FieldTable<WorldMarkersConfig>& worldMarkersFields();

// The markers of `world` in `config.frame_id`: namespaces "disks", "walls", "polygons",
// after one DELETEALL so a republished world replaces the old one.
visualization_msgs::MarkerArray worldMarkers(const world::World& world, const WorldMarkersConfig& config);

}  // namespace ros_layer
}  // namespace amigobot_tracking

// world_markers: the MarkerArray that draws a world (one marker per disk, wall and polygon,
// in the configured frame, walls as boxes along their segment) and its parameter checks.
#include <cmath>

#include <gtest/gtest.h>

#include "amigobot_tracking/ros/world_markers.h"

using namespace amigobot_tracking;
using visualization_msgs::Marker;

TEST(WorldMarkers, OneMarkerPerShapeAfterADeleteAll) {
  world::World room;
  room.obstacles = {{{1.0, 2.0}, 0.25}};
  room.walls = {{{0.0, 0.0}, {0.0, 4.0}}, {{0.0, 4.0}, {3.0, 4.0}}};
  room.polygons = {{{{2.0, 1.0}, {3.0, 1.0}, {3.0, 2.0}}}};
  ros_layer::WorldMarkersConfig config;
  config.world_file = "lab.yaml";
  config.frame_id = "world";
  const visualization_msgs::MarkerArray a = ros_layer::worldMarkers(room, config);
  ASSERT_EQ(a.markers.size(), 5u);
  EXPECT_EQ(a.markers[0].action, Marker::DELETEALL);
  const Marker& disk = a.markers[1];
  EXPECT_EQ(disk.type, Marker::CYLINDER);
  EXPECT_EQ(disk.header.frame_id, "world");
  EXPECT_DOUBLE_EQ(disk.scale.x, 0.5);
  EXPECT_DOUBLE_EQ(disk.pose.position.y, 2.0);
  // The first wall runs along +y: a box 4 m long centred at (0, 2), turned by 90 degrees.
  const Marker& wall = a.markers[2];
  EXPECT_EQ(wall.type, Marker::CUBE);
  EXPECT_EQ(wall.ns, "walls");
  EXPECT_DOUBLE_EQ(wall.scale.x, 4.0);
  EXPECT_DOUBLE_EQ(wall.scale.y, config.wall_thickness);
  EXPECT_DOUBLE_EQ(wall.pose.position.y, 2.0);
  EXPECT_NEAR(2.0 * std::atan2(wall.pose.orientation.z, wall.pose.orientation.w), M_PI / 2, 1e-12);
  const Marker& table = a.markers[4];
  EXPECT_EQ(table.type, Marker::LINE_STRIP);
  ASSERT_EQ(table.points.size(), 4u) << "a closed outline: the first point again at the end";
  EXPECT_DOUBLE_EQ(table.points.back().x, table.points.front().x);
  EXPECT_NE(a.markers[1].id, a.markers[2].id);
}

TEST(WorldMarkers, ValidateNamesTheBadField) {
  ros_layer::WorldMarkersConfig c;
  EXPECT_NE(c.validate().find("world_file"), std::string::npos) << "the world file is required";
  c.world_file = "lab.yaml";
  EXPECT_EQ(c.validate(), "");
  c.height = 0.0;
  EXPECT_NE(c.validate().find("height"), std::string::npos);
  c = ros_layer::WorldMarkersConfig{};
  c.world_file = "lab.yaml";
  c.frame_id.clear();
  EXPECT_NE(c.validate().find("frame_id"), std::string::npos);
}

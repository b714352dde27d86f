// rviz markers of one control step (ros/markers.h), no master needed.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "amigobot_tracking/ros/markers.h"

using namespace amigobot_tracking;
using namespace amigobot_tracking::ros_layer;
using visualization_msgs::Marker;

namespace {

struct Fixture {
  core::ControllerConfig config;
  std::vector<core::Disk> detected{{{1.0, 0.0}, 0.1}, {{10.0, 0.0}, 0.1}};  // one near p_r, one far
  core::VirtualObstacleSet virtual_obstacles;
  MarkerScene scene;

  Fixture() {
    virtual_obstacles.upsert({"box", {{0.0, 3.0}, 0.25}});
    scene.frame = "map";
    scene.stamp = ros::Time(5.0);
    scene.have_pose = true;
    scene.have_output = true;
    scene.output.p_r = {0.3, 0.0};
    scene.output.p_d = {1.0, 1.0};
    scene.output.e = scene.output.p_d - scene.output.p_r;
    scene.output.rho = 2.0 * scene.output.e.norm();
    scene.config = &config;
    scene.detected = &detected;
    scene.virtual_obstacles = &virtual_obstacles;
    scene.status = "tracking";
  }
};

std::multimap<std::string, Marker> byNamespace(const visualization_msgs::MarkerArray& array) {
  std::multimap<std::string, Marker> out;
  for (const Marker& m : array.markers) out.emplace(m.ns, m);
  return out;
}

}  // namespace

TEST(Markers, StartWithDeleteAllAndHaveUniqueIds) {
  Fixture f;
  const visualization_msgs::MarkerArray array = buildMarkers(f.scene);
  ASSERT_FALSE(array.markers.empty());
  EXPECT_EQ(array.markers[0].action, Marker::DELETEALL);
  // A DELETEALL without a frame fails rviz's tf filter and is applied out of order.
  EXPECT_EQ(array.markers[0].header.frame_id, "map");
  std::vector<std::pair<std::string, int>> ids;
  for (std::size_t i = 1; i < array.markers.size(); ++i) {
    EXPECT_EQ(array.markers[i].header.frame_id, "map");
    ids.emplace_back(array.markers[i].ns, array.markers[i].id);
  }
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(std::adjacent_find(ids.begin(), ids.end()), ids.end());
}

TEST(Markers, TheStatusTextKeepsItsIdWhenTheObstacleCountChanges) {
  // Its id was its index in the array: one laser disk more or less gave the text a new id,
  // and rviz drew the old and the new one together.
  Fixture f;
  auto textId = [](const visualization_msgs::MarkerArray& array) {
    for (const Marker& m : array.markers) {
      if (m.ns == "text") return m.id;
    }
    return -1;
  };
  const int before = textId(buildMarkers(f.scene));
  std::vector<core::Disk> more = *f.scene.detected;
  more.push_back(more.front());
  more.push_back(more.front());
  f.scene.detected = &more;
  EXPECT_EQ(textId(buildMarkers(f.scene)), before);
  EXPECT_EQ(before, 0);
}

TEST(Markers, ShowEveryElementTheIssueLists) {
  Fixture f;
  const auto m = byNamespace(buildMarkers(f.scene));
  for (const char* ns : {"rho", "target", "target_velocity", "offset_point", "body", "safety_disk", "laser_obstacles",
                         "virtual_obstacles", "virtual_obstacle_ids", "u_c", "diamond", "diamond_u", "diamond_u_d",
                         "text", "legend"}) {
    EXPECT_EQ(m.count(ns), ns == std::string("laser_obstacles") ? 2u : 1u) << ns;
  }
  EXPECT_EQ(m.find("virtual_obstacle_ids")->second.text, "box");
  // The rho circle has radius rho around the target.
  const Marker& rho = m.find("rho")->second;
  for (const auto& p : rho.points) EXPECT_NEAR(std::hypot(p.x - 1.0, p.y - 1.0), f.scene.output.rho, 1e-9);
  EXPECT_NE(m.find("text")->second.text.find("rho"), std::string::npos);
}

TEST(Markers, ObstaclesWithinTheDetectionDistanceStandOut) {
  Fixture f;
  const auto m = byNamespace(buildMarkers(f.scene));
  auto range = m.equal_range("laser_obstacles");
  std::vector<Marker> laser;
  for (auto it = range.first; it != range.second; ++it) laser.push_back(it->second);
  ASSERT_EQ(laser.size(), 2u);
  const Marker& near = laser[0].pose.position.x < 5.0 ? laser[0] : laser[1];
  const Marker& far = laser[0].pose.position.x < 5.0 ? laser[1] : laser[0];
  EXPECT_FALSE(near.color.r == far.color.r && near.color.g == far.color.g && near.color.b == far.color.b);
  EXPECT_DOUBLE_EQ(near.scale.x, 0.2);  // diameter
}

TEST(Markers, WithoutAControllerStepOnlyTheRobotAndObstacles) {
  Fixture f;
  f.scene.have_output = false;
  f.scene.status = "disabled";
  const auto m = byNamespace(buildMarkers(f.scene));
  EXPECT_EQ(m.count("rho"), 0u);
  EXPECT_EQ(m.count("u_c"), 0u);
  EXPECT_EQ(m.count("body"), 1u);
  EXPECT_NE(m.find("text")->second.text.find("disabled"), std::string::npos);
}

// rostest: the Localization nodelet in mapping mode (its default method, the pose graph) driven
// through the synthetic room: the latched `map` grows with its `map_metadata`, map -> odom
// follows the drive, and ~save_map writes map files that load and whose walls are the room's,
// into a folder that did not exist (created); ~save_map_to writes them to the path it is given.
#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <filesystem>

#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nodelet/loader.h>
#include <std_srvs/Trigger.h>

#include "amigobot_tracking/SaveMap.h"
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "amigobot_tracking/localization/distance_field.h"
#include "synthetic_robot.h"

namespace localization_mapping_test {

using namespace amigobot_test;

TEST(LocalizationMapping, MapsTheRoomAndSavesTheMap) {
  // A folder that does not exist yet, as ~/maps on a fresh account.
  const std::string folder = "/tmp/amigobot_mapping_rostest_" + std::to_string(::getpid());
  const std::string map_file = folder + "/maps/lab.yaml";
  const std::string pgm_file = map_file.substr(0, map_file.size() - 5) + ".pgm";
  ros::NodeHandle nh;
  std::mutex mutex;
  std::vector<std::size_t> known_cells;  // per received map
  ros::Subscriber map_sub = nh.subscribe<nav_msgs::OccupancyGrid>("/map", 5, [&](const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex);
    known_cells.push_back(static_cast<std::size_t>(std::count_if(msg->data.begin(), msg->data.end(), [](std::int8_t v) { return v >= 0; })));
  });
  std::vector<nav_msgs::MapMetaData> metadata;
  ros::Subscriber metadata_sub = nh.subscribe<nav_msgs::MapMetaData>("/map_metadata", 5, [&](const nav_msgs::MapMetaData::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex);
    metadata.push_back(*msg);
  });
  ros::param::set("/mapping/mode", "mapping");
  ros::param::set("/mapping/map_file", map_file);
  ros::param::set("/mapping/map_publish_period", 1.0);
  ros::param::set("/mapping/initial_pose/x", kLoopStart.x);
  ros::param::set("/mapping/initial_pose/y", kLoopStart.y);
  ros::param::set("/mapping/initial_pose/yaw", kLoopStart.theta);
  SyntheticRobot robot(kLoopStart, Pose2{0.5, 0.5, 0.5});
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  nodelet::Loader loader(false);
  ASSERT_TRUE(loader.load("/mapping", "amigobot_tracking/Localization", {}, {}));
  ros::WallDuration(1.0).sleep();
  // Half a loop at 0.3 m/s.
  robot.drive(Pose2{0.03, 0.0, 0.03 / kLoopRadius});
  ros::WallDuration(12.0).sleep();
  robot.drive(Pose2{});
  ros::WallDuration(0.5).sleep();
  const Pose2 truth = robot.truth();
  const auto t = buffer.lookupTransform("map", "base_footprint", ros::Time(0)).transform;
  EXPECT_NEAR(t.translation.x, truth.x, 0.1);
  EXPECT_NEAR(t.translation.y, truth.y, 0.1);
  {
    std::lock_guard<std::mutex> lock(mutex);
    ASSERT_GE(known_cells.size(), 5u) << "the map is republished every map_publish_period";
    EXPECT_GT(known_cells.back(), known_cells.front()) << "and grows as the robot explores";
    ASSERT_GE(metadata.size(), 5u) << "map_metadata with every map, as map_server";
    EXPECT_NEAR(metadata.back().resolution, 0.05, 1e-6);
    EXPECT_GT(metadata.back().width * metadata.back().height, 0u);
  }

  std_srvs::Trigger save;
  ASSERT_TRUE(ros::service::call("/mapping/save_map", save));
  EXPECT_TRUE(save.response.success) << save.response.message;
  const loc::OccupancyMap map = loc::loadMap(map_file);
  const loc::DistanceField room(roomMap(), 2.0);
  int occupied = 0, on_walls = 0;
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      if (!map.occupied(x, y)) continue;
      ++occupied;
      const Eigen::Vector2d c = map.cellCenter(x, y);
      on_walls += room.distance(c.x(), c.y()) <= 0.1;
    }
  }
  EXPECT_GT(occupied, 200);
  EXPECT_GT(static_cast<double>(on_walls) / std::max(1, occupied), 0.9) << on_walls << " of " << occupied;
  // ~save_map_to: a path of its own (map_saver's -f NAME: ".yaml" added), its folder created.
  amigobot_tracking::SaveMap save_to;
  save_to.request.path = folder + "/elsewhere/lab2";
  ASSERT_TRUE(ros::service::call("/mapping/save_map_to", save_to));
  EXPECT_TRUE(save_to.response.success) << save_to.response.message;
  EXPECT_EQ(loc::loadMap(folder + "/elsewhere/lab2.yaml").width, map.width);
  EXPECT_TRUE(std::filesystem::exists(folder + "/elsewhere/lab2.pgm"));
  save_to.request.path = pgm_file + "/under_a_file.yaml";  // a folder that cannot be made: named
  ASSERT_TRUE(ros::service::call("/mapping/save_map_to", save_to));
  EXPECT_FALSE(save_to.response.success);
  EXPECT_NE(save_to.response.message.find("cannot create the folder " + pgm_file), std::string::npos) << save_to.response.message;
  EXPECT_TRUE(loader.unload("/mapping"));
  std::filesystem::remove_all(folder);
}

}  // namespace localization_mapping_test

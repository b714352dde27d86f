// ICP-SLAM (MRPT's CMetricMapBuilderICP) driving through the synthetic room with drifting
// odometry: the map's walls are where the room's are, its pose stays near the truth, and the
// map it builds, saved and loaded, localises the robot.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include "amigobot_tracking/localization/distance_field.h"
#include "amigobot_tracking/localization/localizer.h"
#include "amigobot_tracking/localization/mapper.h"
#include "synthetic_room.h"

using namespace amigobot_tracking;
using namespace amigobot_tracking::localization;
using amigobot_test::scanAt;

namespace {

struct Drive {
  OccupancyMap map;
  double worst_position = 0.0;
  int loops = 0;
};

// 1.2 loops through the room with odometry 4 % long and 3 % over-turning.
Drive driveAndMap(const std::string& method = "icp") {
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  LocalizationConfig c;
  c.mode = "mapping";
  c.mapping_method = method;
  c.initial_pose = amigobot_test::kLoopStart;
  Mapper mapper(c);
  core::Pose2 truth = c.initial_pose, odom{};
  Drive drive;
  for (int step = 0; step < 300; ++step) {
    const double v = 0.03, w = v / amigobot_test::kLoopRadius;
    const PoseEstimate& e = mapper.update(scanAt(truth, 360, &random), odom);
    drive.worst_position = std::max(drive.worst_position, std::hypot(e.pose.x - truth.x, e.pose.y - truth.y));
    truth = compose(truth, core::Pose2{v, 0.0, w});
    odom = compose(odom, core::Pose2{v * 1.04 + 0.002 * noise(random), 0.0, w * 1.03 + 0.002 * noise(random)});
  }
  EXPECT_EQ(mapper.estimate().scans, 300);
  drive.map = mapper.map();
  drive.loops = mapper.loopClosures();
  return drive;
}

void expectTheRoomsWalls(const Drive& drive) {
  EXPECT_LT(drive.worst_position, 0.1);
  const OccupancyMap& map = drive.map;
  ASSERT_FALSE(map.empty());
  // Every occupied cell lies on a wall or pillar of the room ...
  const DistanceField truth(amigobot_test::roomMap(), 2.0);
  int occupied = 0, on_walls = 0, free = 0;
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      if (map.at(x, y) == OccupancyMap::kFree) ++free;
      if (!map.occupied(x, y)) continue;
      ++occupied;
      const Eigen::Vector2d c = map.cellCenter(x, y);
      on_walls += truth.distance(c.x(), c.y()) <= 0.1;
    }
  }
  ASSERT_GT(occupied, 200);
  EXPECT_GT(static_cast<double>(on_walls) / occupied, 0.95) << on_walls << " of " << occupied;
  EXPECT_GT(free * map.resolution * map.resolution, 10.0) << "most of the 24 m^2 room is seen free";
  // ... and the room's four walls are in the map, along their whole length.
  const DistanceField built(map, 2.0);
  int wall_points = 0, found = 0;
  for (double t = 0.0; t <= 1.0; t += 0.01) {
    for (const Eigen::Vector2d& p : {Eigen::Vector2d(-1.0 + 6.0 * t, -1.0), Eigen::Vector2d(-1.0 + 6.0 * t, 3.0),
                                     Eigen::Vector2d(-1.0, -1.0 + 4.0 * t), Eigen::Vector2d(5.0, -1.0 + 4.0 * t)}) {
      ++wall_points;
      found += built.distance(p.x(), p.y()) <= 0.1;
    }
  }
  EXPECT_GT(static_cast<double>(found) / wall_points, 0.85) << found << " of " << wall_points;
}

}  // namespace

TEST(Mapper, BuildsAMapWhoseWallsAreWhereTheRoomsAre) { expectTheRoomsWalls(driveAndMap()); }

// The pose graph (mapping_method graph) in the same room: it closes the loop after one turn.
TEST(Mapper, TheGraphMethodBuildsTheRoomToo) {
  const Drive drive = driveAndMap("graph");
  expectTheRoomsWalls(drive);
  EXPECT_GT(drive.loops, 0);
}

// The default method (localization:=slam, make map) is the one that closes loops
// (docs/localization.md: measured on the emulated lab's make map and demo).
TEST(Mapper, TheDefaultMethodClosesLoops) {
  const Drive drive = driveAndMap(LocalizationConfig().mapping_method);
  expectTheRoomsWalls(drive);
  EXPECT_GT(drive.loops, 0) << "mapping_method " << LocalizationConfig().mapping_method;
}

TEST(Mapper, ItsSavedMapLocalisesTheRobot) {
  const Drive drive = driveAndMap();
  const std::string yaml = "/tmp/amigobot_mapper_test_" + std::to_string(::getpid()) + ".yaml";
  saveMap(yaml, drive.map);
  const OccupancyMap loaded = loadMap(yaml);
  std::filesystem::remove(yaml);
  std::filesystem::remove(yaml.substr(0, yaml.size() - 5) + ".pgm");
  LocalizationConfig c;
  c.map_file = yaml;
  Localizer localizer(c, loaded);
  std::mt19937 random(8);
  const core::Pose2 truth{3.0, 1.5, 2.0};
  localizer.setPose(core::Pose2{2.7, 1.3, 1.8}, core::Pose2());
  for (int i = 0; i < 10; ++i) localizer.update(scanAt(truth, 360, &random), core::Pose2());
  EXPECT_LT(std::hypot(localizer.estimate().pose.x - truth.x, localizer.estimate().pose.y - truth.y), 0.05);
  EXPECT_GT(localizer.estimate().match, 0.8);
}

// The online correction: at every scan, also the scans where a loop closes, the published pose
// is the current keyframe's optimised pose plus the motion since (the smoothed trajectory's
// last pose), and map -> odom carries it to the odometry (the pose tf gives between scans).
TEST(Mapper, AClosedLoopReachesThePublishedPoseAndMapToOdom) {
  std::mt19937 random(7);
  LocalizationConfig c;
  c.mode = "mapping";
  c.mapping_method = "graph";
  c.initial_pose = amigobot_test::kLoopStart;
  Mapper mapper(c);
  core::Pose2 truth = c.initial_pose, odom{};
  int closing_scans = 0;
  for (int step = 0; step < 300; ++step) {
    const int loops = mapper.loopClosures();
    const PoseEstimate& e = mapper.update(scanAt(truth, 360, &random), odom);
    const core::Pose2 smoothed = mapper.trajectory().back(), via_odom = compose(e.map_to_odom, odom);
    ASSERT_NEAR(e.pose.x, smoothed.x, 1e-9) << "scan " << step;
    ASSERT_NEAR(e.pose.y, smoothed.y, 1e-9) << "scan " << step;
    ASSERT_NEAR(e.pose.theta, smoothed.theta, 1e-9) << "scan " << step;
    ASSERT_NEAR(via_odom.x, e.pose.x, 1e-9);
    ASSERT_NEAR(via_odom.y, e.pose.y, 1e-9);
    if (mapper.loopClosures() > loops) {
      ++closing_scans;
      EXPECT_LT(std::hypot(e.pose.x - truth.x, e.pose.y - truth.y), 0.1) << "scan " << step;
    }
    const double v = 0.03, w = v / amigobot_test::kLoopRadius;
    truth = compose(truth, core::Pose2{v, 0.0, w});
    odom = compose(odom, core::Pose2{v * 1.04, 0.0, w * 1.03});
  }
  EXPECT_GT(closing_scans, 0);
}

// sim_laser: the scan of a known world (disks, walls, polygons) from a known pose, REP 117 values, noise bounds,
// and configuration errors naming the field.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "amigobot_tracking/ros/sim_laser.h"

using namespace amigobot_tracking;

namespace {

ros_layer::SimLaserConfig config() {
  ros_layer::SimLaserConfig c;
  c.world_file = "world.yaml";
  c.beams = 361;
  c.angle_min = -M_PI;
  c.angle_max = M_PI;
  c.range_max = 5.0;
  c.noise_std = 0.0;
  return c;
}

std::size_t beamAt(const sensor_msgs::LaserScan& scan, double angle) {
  return static_cast<std::size_t>(std::lround((angle - scan.angle_min) / scan.angle_increment));
}

}  // namespace

TEST(SimLaser, SeesDiskAheadAtItsSurfaceAndNothingBehind) {
  core::Disk disk;
  disk.center = {2.0, 1.0};
  disk.radius = 0.25;
  core::Pose2 laser{1.0, 1.0, 0.0};
  const auto scan = ros_layer::simulateScan(laser, world::disksOnly({disk}), config(), nullptr);
  ASSERT_EQ(scan.ranges.size(), 361u);
  EXPECT_NEAR(scan.ranges[beamAt(scan, 0.0)], 0.75, 1e-4);
  EXPECT_TRUE(std::isinf(scan.ranges[beamAt(scan, M_PI / 2)]) && scan.ranges[beamAt(scan, M_PI / 2)] > 0);
  EXPECT_EQ(scan.header.frame_id, "laser");
  EXPECT_FLOAT_EQ(scan.angle_max, static_cast<float>(M_PI));
  EXPECT_NEAR(scan.angle_min + 360 * scan.angle_increment, scan.angle_max, 1e-5);
}

TEST(SimLaser, SeesAWallAndATableAtTheirSurfaces) {
  world::World room;
  room.walls = {{{-5.0, 2.0}, {5.0, 2.0}}};                                   // 2 m to the left
  room.polygons = {{{{1.0, -0.5}, {1.5, -0.5}, {1.5, 0.5}, {1.0, 0.5}}}};     // 1 m ahead
  const auto scan = ros_layer::simulateScan({0.0, 0.0, 0.0}, room, config(), nullptr);
  EXPECT_NEAR(scan.ranges[beamAt(scan, M_PI / 2)], 2.0, 1e-4);
  EXPECT_NEAR(scan.ranges[beamAt(scan, M_PI / 4)], 2.0 * std::sqrt(2.0), 1e-4);
  EXPECT_NEAR(scan.ranges[beamAt(scan, 0.0)], 1.0, 1e-4);
  EXPECT_TRUE(std::isinf(scan.ranges[beamAt(scan, -M_PI / 2)]));
}

TEST(SimLaser, BeamsAreInTheLaserFrame) {
  core::Disk disk;
  disk.center = {0.0, 2.0};
  disk.radius = 0.5;
  core::Pose2 laser{0.0, 0.0, M_PI / 2};  // facing the disk: it is straight ahead
  const auto scan = ros_layer::simulateScan(laser, world::disksOnly({disk}), config(), nullptr);
  EXPECT_NEAR(scan.ranges[beamAt(scan, 0.0)], 1.5, 1e-4);
  EXPECT_TRUE(std::isinf(scan.ranges[beamAt(scan, M_PI / 2)]));
}

TEST(SimLaser, NoiseStaysInsideTheRangeLimitsAndLeavesInfAlone) {
  auto c = config();
  c.noise_std = 0.5;
  c.range_min = 0.7;
  core::Disk disk;
  disk.center = {1.0, 0.0};
  disk.radius = 0.2;
  std::mt19937 rng(3);
  double sum = 0.0;
  int n = 0;
  for (int i = 0; i < 200; ++i) {
    const auto scan = ros_layer::simulateScan({0, 0, 0}, world::disksOnly({disk}), c, &rng);
    const float r = scan.ranges[beamAt(scan, 0.0)];
    ASSERT_GE(r, static_cast<float>(c.range_min));
    ASSERT_LE(r, static_cast<float>(c.range_max));
    ASSERT_TRUE(std::isinf(scan.ranges[beamAt(scan, M_PI)]));
    sum += r;
    ++n;
  }
  EXPECT_GT(sum / n, 0.7);  // noisy, yet around the 0.8 m surface
  EXPECT_LT(sum / n, 1.0);
}

TEST(SimLaser, ValidateNamesTheBadField) {
  auto c = config();
  EXPECT_EQ(c.validate(), "");
  c.beams = 1;
  EXPECT_NE(c.validate().find("beams"), std::string::npos);
  c = config();
  c.range_max = 0.01;
  EXPECT_NE(c.validate().find("range_max"), std::string::npos);
  c = config();
  c.world_file.clear();
  EXPECT_NE(c.validate().find("world_file"), std::string::npos);
  c = config();
  c.angle_max = c.angle_min;
  EXPECT_NE(c.validate().find("angle_max"), std::string::npos);
}

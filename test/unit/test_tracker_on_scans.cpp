// The laser tracker on scans a laser would take (world::raycastScan): a person walking in a
// room, seen from a moving robot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "amigobot_tracking/core/perception/obstacle_tracker.h"
#include "amigobot_tracking/core/perception/scan_obstacles.h"
#include "amigobot_tracking/world/raycast.h"

using namespace amigobot_tracking;
using namespace amigobot_tracking::core;

namespace {

// A SICK TiM5xx: 270 deg at 0.333 deg (811 beams), 0.05 .. 10 m.
const ScanGeometry kTim{-0.75 * M_PI, M_PI / 540.0, 0.05, 10.0};

}  // namespace

// A SICK TiM (270 deg, 0.333 deg, 15 Hz, 1 cm noise) on a robot driving at 0.15 m/s sees a
// person (r 0.25) cross 1.3 m ahead at 0.6 m/s, in a room whose walls it sees too. The laser
// cuts the person into 3-4 disks and where it cuts moves as they walk; tracked disk by disk,
// the pieces slid along the person's arc and the wall's pieces beside the person's shadow
// along the wall: a wall piece reported 2 m/s (max_speed), and the person's pieces were off
// by 0.35 m/s at worst. Tracked as objects, the walls stand still and the person's pieces all
// carry the person's velocity (0.10 m/s off on average, 0.21 at worst).
TEST(ObstacleTracker, APersonCutIntoPiecesIsOneObjectAndTheWallsStandStill) {
  const ScanGeometry& tim = kTim;
  ScanObstacleConfig scan;
  ObstacleTracker tracker(ObstacleTrackerConfig(), scan.cluster_tolerance);
  world::World room;
  room.walls = {{{-3.5, 2.4}, {4.5, 2.4}}, {{-3.5, -2.4}, {4.5, -2.4}}, {{4.5, -2.4}, {4.5, 2.4}}};
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0.0, 0.01);
  const Eigen::Vector2d walk(0.0, 0.6);
  double fastest_wall = 0.0, worst_person = 0.0, person_error = 0.0;
  int person_pieces = 0;
  for (int k = 0; k < 90; ++k) {
    const double t = k / 15.0;
    const Eigen::Vector2d robot(0.5 + 0.15 * t, 0.0), person = Eigen::Vector2d(1.8, -1.5) + walk * t;
    room.obstacles = {{person, 0.25}};
    std::vector<float> ranges = world::raycastScan({robot.x(), robot.y(), 0.0}, room, tim, 811);
    for (float& r : ranges)
      if (std::isfinite(r)) r = static_cast<float>(r + noise(rng));
    Eigen::Affine2d sensor = Eigen::Affine2d::Identity();
    sensor.translation() = robot;
    std::vector<Disk> disks;
    std::vector<ScanCluster> clusters;
    ASSERT_TRUE(scanToObstacles(tim, ranges, sensor, scan, &disks, nullptr, &clusters));
    tracker.update(t, disks, &clusters);
    if (t < 1.0) continue;  // the filter settles
    for (const Disk& d : tracker.obstaclesAt(t)) {
      if ((d.center - person).norm() > 0.4) {
        fastest_wall = std::max(fastest_wall, d.velocity.norm());
      } else {
        worst_person = std::max(worst_person, (d.velocity - walk).norm());
        person_error += (d.velocity - walk).norm();
        ++person_pieces;
      }
    }
  }
  ASSERT_GT(person_pieces, 150);
  person_error /= person_pieces;
  std::printf("walls' fastest piece %.3f m/s; the person's pieces off by %.3f m/s on average, %.3f at worst\n",
              fastest_wall, person_error, worst_person);
  EXPECT_EQ(fastest_wall, 0.0) << "a wall moved";
  EXPECT_LT(person_error, 0.15);
  EXPECT_LT(worst_person, 0.3);
}


// The room of the avoidance e2e test (test/e2e/worlds/avoidance.yaml: an alcove in the east
// wall, a doorway in the south wall, a cabinet, a pillar), nothing in it moving, seen by the
// TiM (1 cm noise, 1 % dropouts) of a robot driving a 2.3 m circle round it at 0.23 m/s and then
// south to the doorway. Walls seen at a grazing angle fall apart into short pieces, and where an
// occluding corner cuts a wall moves as the robot moves: tracked as objects, such pieces walked
// at up to 1.9 m/s (1.8 on the robot with moving_obstacles, and the law yielded to them). A
// piece whose end is hidden (the next return nearer, or the scan's edge) is not evidence of
// motion. The pillar's outline shifts as the robot circles it: it may jitter, never walk.
TEST(ObstacleTracker, AStillRoomStaysStillSeenFromAMovingRobot) {
  const ScanGeometry& tim = kTim;
  ScanObstacleConfig scan;
  const ObstacleTrackerConfig config;
  ObstacleTracker tracker(config, scan.cluster_tolerance);
  world::World room;
  const std::vector<Eigen::Vector2d> outline = {{0.5, -4.5}, {-4.5, -4.5}, {-4.5, 4.5}, {4.5, 4.5}, {4.5, 1.5},
                                                {5.3, 1.5},  {5.3, -0.2},  {4.5, -0.2}, {4.5, -4.5}, {1.4, -4.5}};
  for (size_t i = 0; i + 1 < outline.size(); ++i) room.walls.push_back({outline[i], outline[i + 1]});
  room.polygons = {{{{-4.5, 3.6}, {-3.6, 3.6}, {-3.6, 4.5}, {-4.5, 4.5}}}};
  const Eigen::Vector2d pillar(1.0, 1.7320508);
  room.obstacles = {{pillar, 0.1}};
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double fastest_wall = 0.0, fastest_pillar = 0.0;
  int walls = 0;
  const double radius = 2.3, lap = 2.0 * M_PI / 0.1, down = 2.0 / 0.2;  // 0.1 rad/s round, then 2 m south
  for (int k = 0; k < static_cast<int>((lap + down) * 15.0); ++k) {
    const double t = k / 15.0;
    core::Pose2 robot;
    if (t < lap) {
      const double a = -M_PI / 3.0 + 0.1 * t;  // from 300 deg, counter-clockwise
      robot = {radius * std::cos(a), radius * std::sin(a), a + M_PI / 2.0};
    } else {
      robot = {0.5 * radius, -0.866 * radius - 0.2 * (t - lap), -M_PI / 2.0};
    }
    std::vector<float> ranges = world::raycastScan(robot, room, tim, 811);
    for (float& r : ranges) {
      if (uniform(rng) < 0.01) r = std::numeric_limits<float>::quiet_NaN();
      else if (std::isfinite(r)) r = static_cast<float>(r + noise(rng));
    }
    Eigen::Affine2d sensor = Eigen::Translation2d(robot.x, robot.y) * Eigen::Rotation2Dd(robot.theta);
    std::vector<Disk> disks;
    std::vector<ScanCluster> clusters;
    ASSERT_TRUE(scanToObstacles(tim, ranges, sensor, scan, &disks, nullptr, &clusters));
    tracker.update(t, disks, &clusters);
    for (const Disk& d : tracker.obstaclesAt(t)) {
      const double speed = std::max(d.velocity.norm(), d.resume_velocity.norm());
      if ((d.center - pillar).norm() < 0.3) {
        fastest_pillar = std::max(fastest_pillar, speed);
      } else {
        ++walls;
        fastest_wall = std::max(fastest_wall, speed);
      }
    }
  }
  std::printf("the walls' fastest disk %.3f m/s, the pillar's %.3f m/s\n", fastest_wall, fastest_pillar);
  ASSERT_GT(walls, 10000);
  EXPECT_EQ(fastest_wall, 0.0) << "a wall moved";
  EXPECT_LT(fastest_pillar, config.walking_speed) << "the pillar walked";
}

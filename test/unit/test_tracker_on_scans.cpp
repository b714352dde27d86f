// The laser tracker on scans a laser would take (world::raycastScan): a person walking in a
// room, seen from a moving robot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "amigobot_tracking/core/perception/obstacle_tracker.h"
#include "amigobot_tracking/core/perception/scan_obstacles.h"
#include "amigobot_tracking/world/raycast.h"

using namespace amigobot_tracking;
using namespace amigobot_tracking::core;

// A SICK TiM (270 deg, 0.333 deg, 15 Hz, 1 cm noise) on a robot driving at 0.15 m/s sees a
// person (r 0.25) cross 1.3 m ahead at 0.6 m/s, in a room whose walls it sees too. The laser
// cuts the person into 3-4 disks and where it cuts moves as they walk; tracked disk by disk,
// the pieces slid along the person's arc and the wall's pieces beside the person's shadow
// along the wall: a wall piece reported 2 m/s (max_speed), and the person's pieces were off
// by 0.35 m/s at worst. Tracked as objects, the walls stand still and the person's pieces all
// carry the person's velocity (0.10 m/s off on average, 0.21 at worst).
TEST(ObstacleTracker, APersonCutIntoPiecesIsOneObjectAndTheWallsStandStill) {
  ScanGeometry tim;
  tim.angle_min = -0.75 * M_PI;
  tim.angle_increment = M_PI / 540.0;
  tim.range_min = 0.05;
  tim.range_max = 10.0;
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
    ASSERT_TRUE(scanToObstacles(tim, ranges, sensor, scan, &disks));
    tracker.update(t, disks);
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


// The clutter classes of issue 20 as small scenes for the recommended law's tests
// (test_recommended_law.cpp): the experiment's gains and diamond (v_bar 0.3 m/s, w_bar 0.8
// rad/s), body-safe radius, 20 Hz, the robot at the origin facing +x and the target's spline
// starting 0.3 m ahead of p_r. Layouts are ours (not the audit's).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/support/types.h"

namespace clutter_scenes {

using amigobot_tracking::core::Disk;

struct Scene {
  std::string name;
  std::vector<Disk> disks;
  std::vector<Eigen::Vector2d> velocities;  // empty: static
  std::vector<Eigen::Vector2d> waypoints;   // the target's spline
  double spline_duration = 30.0;            // [s] then the target parks
  double duration = 40.0;                   // [s] simulated
  double v_max = 0.3, w_max = 0.8;
};

inline Disk disk(double x, double y, double r) { return Disk{Eigen::Vector2d(x, y), r, Eigen::Vector2d::Zero()}; }

inline std::vector<Scene> clutterScenes() {
  std::vector<Scene> s;
  // Parks 0.5 m behind a 0.3 m pillar: inside its zone (0.48 + 0.3), unreachable.
  s.push_back({"pillar_park", {disk(3.0, 0.0, 0.3)}, {}, {{0.6, 0.0}, {3.5, 0.0}}, 20.0, 40.0});
  // A cup of 9 disks (radius 1 m around (3.5, 0)) open toward the robot.
  std::vector<Disk> cup;
  for (int k = -4; k <= 4; ++k) {
    const double a = k * M_PI / 8.0;
    cup.push_back(disk(3.5 + std::cos(a), std::sin(a), 0.2));
  }
  s.push_back({"u_behind", cup, {}, {{0.6, 0.0}, {2.2, 0.0}, {5.8, -1.5}, {5.8, 1.5}}, 45.0, 60.0});
  s.push_back({"u_through", cup, {}, {{0.6, 0.0}, {7.0, 0.0}}, 40.0, 70.0});  // 30 s to arrive after the target parks
  // Two 0.1 m disks whose zones leave a 0.14 m corridor for p_r.
  s.push_back({"gap", {disk(2.5, 0.65, 0.1), disk(2.5, -0.65, 0.1)}, {}, {{0.6, 0.0}, {5.5, 0.0}}, 30.0, 35.0});
  for (double d : {1.75, 1.77})
    s.push_back({"neighbour_" + std::to_string(static_cast<int>(std::lround(d * 100))),
                 {disk(2.5, 0.5 * d, 0.15), disk(2.5, -0.5 * d, 0.15)}, {}, {{0.6, 0.0}, {5.5, 0.0}}, 30.0, 35.0});
  s.push_back({"corner", {}, {}, {{0.6, 0.0}, {3.0, 0.0}, {3.0, 3.0}}, 30.0, 35.0});
  s.push_back({"fast_target", {}, {}, {{0.6, 0.0}, {12.6, 0.0}}, 20.0, 20.0});  // 0.6 m/s against v_bar 0.3
  s.push_back({"saddle", {disk(2.0, 0.0, 0.3)}, {}, {{0.6, 0.0}, {6.6, 0.0}}, 40.0, 40.0});
  std::vector<Disk> ring;
  for (int k = 0; k < 6; ++k) {
    const double a = M_PI / 6.0 + k * M_PI / 3.0;
    ring.push_back(disk(3.5 + 1.5 * std::cos(a), 1.5 * std::sin(a), 0.2));
  }
  s.push_back({"ring", ring, {}, {{0.6, 0.0}, {6.6, 0.0}}, 40.0, 45.0});
  // A wall of 0.1 m disks across the target's line, with a door between y = 0.4 and y = 2.6.
  std::vector<Disk> wall;
  for (int k = 0; k <= 17; ++k) wall.push_back(disk(2.5, -3.0 + 0.2 * k, 0.1));
  for (int k = 0; k <= 12; ++k) wall.push_back(disk(2.5, 2.6 + 0.2 * k, 0.1));
  s.push_back({"doorway", wall, {}, {{0.6, 0.0}, {5.0, 0.0}}, 25.0, 50.0});
  // A disk crossing the target's line at 0.2 m/s.
  s.push_back({"moving", {disk(3.0, -2.5, 0.25)}, {Eigen::Vector2d(0.0, 0.2)}, {{0.6, 0.0}, {6.6, 0.0}}, 35.0, 40.0});
  return s;
}

}  // namespace clutter_scenes

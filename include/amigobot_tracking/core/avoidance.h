// The repulsive collision-avoidance term u_c of eq. (10) and clearance helpers.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/types.h"

namespace amigobot_tracking {
namespace core {

struct AvoidanceResult {
  Eigen::Vector2d u_c = Eigen::Vector2d::Zero();  // [m/s] per unit gain k_o
  int detected = 0;                               // obstacles within the detection distance
  // Smallest distance from the disk of radius robot_radius around p_r to any obstacle
  // surface [m] (negative: overlap); +inf without obstacles.
  double min_clearance = 0.0;
};

// u_c = sum over detected j of [1/(|p_r - p_j| - (R + r_j)) - 1/delta] (p_r - p_j),
// detected when |p_r - p_j| <= delta + R + r_j. R is the effective robot radius (R, or
// R + r for a body-safe margin). At or inside contact the margin is floored at
// min_margin so the term stays finite and pushes straight out; when p_r sits on an
// obstacle centre the push is along -heading_hint (back the way the robot faces).
AvoidanceResult repulsiveTerm(const Eigen::Vector2d& p_r, const std::vector<Disk>& obstacles,
                              double robot_radius, double delta, const Eigen::Vector2d& heading_hint,
                              double min_margin = 1e-4);

// Distance from a disk (centre, radius) to the nearest obstacle surface [m]; +inf if none.
double clearance(const Eigen::Vector2d& center, double radius, const std::vector<Disk>& obstacles);

}  // namespace core
}  // namespace amigobot_tracking

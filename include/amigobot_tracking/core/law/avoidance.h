// The repulsive collision-avoidance term u_c of eq. (10) and clearance helpers.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/support/types.h"

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

// Moving obstacles (beyond the paper). With a_j = max(0, v_j . n_j) the speed at which
// obstacle j approaches p_r along n_j = (p_r - p_j)/|p_r - p_j|, the term for j becomes
//     [1/(d_j) - 1/delta_j] (p_r - p_j) + a_j n_j,   delta_j = delta + a_j * horizon,
// detected when d_j <= delta_j (d_j = distance to contact). Why: in the obstacle's frame
// the distance changes at n_j^T (p_r' - v_j); the feed-forward a_j n_j (with k_o = 1)
// cancels the approach, so the static barrier argument of (10) holds again, and the
// longer detection band starts the push `horizon` seconds of approach earlier. Static
// obstacles (v_j = 0) give exactly (10).
AvoidanceResult movingRepulsiveTerm(const Eigen::Vector2d& p_r, const std::vector<Disk>& obstacles,
                                    double robot_radius, double delta, double horizon,
                                    const Eigen::Vector2d& heading_hint, double min_margin = 1e-4);

// Tangential escape (beyond the paper): the radial term (10) and the attraction can cancel
// on the line through a disk's centre (a saddle).
// - A disk on its own (its detection zone, the disk grown by R + delta, overlaps no other disk's):
//   when it opposes tracking (w = max(0, -e_hat . n) > 0) the term is w |u_c| along the tangent
//   side * perp(n), perpendicular to n, so it never pushes into the obstacle and leaves the radial
//   barrier and its clearance guarantee untouched; zero without conflict.
// - A group (two or more disks detected at once, or one whose zone overlaps a neighbour's: the
//   offset point can feel both): the disks are one obstacle. The direction is the tangent of the
//   summed repulsion u_c (the level line of the group's barrier, perpendicular to u_c, so the term
//   still adds nothing against the barrier) and the term is released when u_c does not oppose
//   tracking; it acts at full strength (`full_strength`: the controller applies its cap).
// side (+1 = counter-clockwise, -1 = clockwise) is the one that turns toward the target; it is
// latched (`previous_side`) and only switches when the sine of the angle between -n and e_hat
// exceeds `hysteresis` on the other side, so an exactly symmetric case does not chatter. 0 = no
// conflict (released). The controller caps k_o |u_t| at k_t times the attraction of (9)
// (controller.cpp: near contact an uncapped escape crowds the radial barrier out of the
// saturated command).
struct TangentialResult {
  Eigen::Vector2d u_t = Eigen::Vector2d::Zero();  // with full_strength: the unit direction
  int side = 0;
  bool full_strength = false;
};
TangentialResult tangentialTerm(const Eigen::Vector2d& p_r, const std::vector<Disk>& obstacles,
                                double robot_radius, double delta, const Eigen::Vector2d& e_hat,
                                int previous_side, double hysteresis = 0.6, double min_margin = 1e-4);

// Distance from a disk (centre, radius) to the nearest obstacle surface [m]; +inf if none.
double clearance(const Eigen::Vector2d& center, double radius, const std::vector<Disk>& obstacles);

}  // namespace core
}  // namespace amigobot_tracking

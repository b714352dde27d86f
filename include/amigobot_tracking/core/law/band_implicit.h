// Backward-Euler treatment of the repulsive term (10) over one held command (offline
// simulation only; the robot's controller keeps the explicit term).
//
// Inside the detection band (10) is stiff: its coefficient grows like 1/margin, so a command
// computed from the margin at the start of a step and held for h overshoots once h exceeds
// roughly margin^2 / (R + r_j) / (offset-point speed), and the offset point chatters across
// the band (the explicit loop needs ~0.5 ms steps there). Here the term of one obstacle j is
// evaluated at the clearance m' the offset point has at the END of the step:
//     m' = clearance_j(end of the step holding u(m')),
//     u(m') = sigma(G(theta_c)^-1 (rest + k_o c(m') (m' + R + r_j) n)),  c(m') = max(0, 1/max(m', min_margin) - 1/delta)
// with n the outward normal at the start of the step, `rest` everything else of (9) and
// theta_c the heading the command is computed with (the pose's, unless told otherwise).
// The end of the step is the exact unicycle arc under the held command, so the clearance the
// loop reaches is m' (to the solver's tolerance): with m > 0 at the start, the root is > 0 and
// the step never ends inside the disk, whatever h. The residual
// clearance_j(end(m')) - m' is positive at m' = 0 (the floored term pushes straight out)
// and negative at m + h * (fastest offset-point speed), so a root is bracketed; it is found by
// a secant iteration started at the start clearance (sliding along a disk the end clearance is
// close to it: 3-5 evaluations), bisecting whenever a secant step would leave the bracket.
#pragma once

#include <limits>

#include <Eigen/Core>

#include "amigobot_tracking/core/robot/diamond.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

struct BandImplicitProblem {
  Pose2 pose;                                         // at the start of the step
  double offset = 0.0;                                // r [m]
  Eigen::Vector2d rest = Eigen::Vector2d::Zero();     // u_r of (9) without obstacle j's term [m/s]
  double k_o = 1.0;
  Disk obstacle;                                      // j (static)
  double robot_radius = 0.0;                          // effective R [m]
  double delta = 0.0;                                 // detection band [m]
  double min_margin = 1e-4;                           // floor of the margin in (10) [m]
  double h = 0.0;                                     // how long the command is held [s]
  // Heading whose G(theta)^-1 turns u_r into the command in (11); NaN: pose.theta. (The
  // simulator's midpoint evaluation computes the command at a pose half a step ahead.)
  double command_theta = std::numeric_limits<double>::quiet_NaN();
  // (cos, sin) of pose.theta and of the command's heading when the caller has them (NaN:
  // computed here): saves the sin/cos pairs the controller step already evaluated.
  Eigen::Vector2d start_heading = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector2d command_heading = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
};

struct BandImplicitResult {
  Eigen::Vector2d u_c = Eigen::Vector2d::Zero();  // obstacle j's term of (10), per unit k_o
  double end_clearance = 0.0;                     // m' [m]
  int iterations = 0;
  bool solved = false;  // false: no bracket (already in contact or h <= 0); u_c is the explicit term
};

// Solves the end-of-step clearance above; pure. `diamond` is the input set of (12).
BandImplicitResult solveBandImplicit(const BandImplicitProblem& problem, const DiamondSet& diamond);

// The fastest the offset point can move with a command inside the diamond [m/s].
double maxOffsetSpeed(const DiamondSet& diamond, double offset);

}  // namespace core
}  // namespace amigobot_tracking

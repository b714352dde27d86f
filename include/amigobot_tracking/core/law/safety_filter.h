// The recommended law's safety filter: the command closest to a nominal one that stays inside
// the diamond and keeps every disk's control-barrier condition, as a small QP solved exactly.
//
// Decision (v, w, s), s >= 0 a slack shared by the barrier rows so the QP is always feasible:
//   minimise  (v - v_n)^2 + r^2 (w - w_n)^2 + slack_weight s^2
//             (= |G(th) (u - u_n)|^2: the offset point's velocity error, G of (8))
//   subject to  |v|/v_bar + |w|/w_bar <= 1                    (the diamond's four edges)
//               n_j^T (G u - v_j) >= -gamma (h_j - m) - s      (one row per disk j)
//               |v - v_p| <= dv + K s,  |w - w_p| <= dw + K (w_bar / v_bar) s   (the rate box,
//               with max_change: solved after the box-free QP, over barrier rows loosened by
//               that QP's slack s0, so the box holds while the barriers hold as well as they
//               can and gives way K = kRateBoxGiveWay times faster than a barrier row is short)
// with h_j = |p_r - c_j| - (R_eff + r_j) the clearance of the offset point's disk, n_j its
// outward normal, v_j the disk's velocity and m = min_margin. With `body_rows`, each disk
// also gets the row of the body disk itself (centre c, radius R_eff):
//               n_c^T (v heading - v_j) >= -gamma (h_c - m) - s,  h_c = |c - c_j| - (R_eff + r_j)
// (for a person, c_j is the nearest point of the stretch they walk while the base stops:
// personSpan below) which holds the body exactly instead of through the disk of radius R + r around p_r that
// encloses it at every heading (the body may pass a disk sideways, where that disk keeps r
// too much); and a moving disk (v_j != 0: a person) then has the body's row only, not p_r's:
// with v_j in it, p_r's row was met most cheaply by turning in place to swing p_r ahead of a
// person walking at it, which moves no part of the robot away. Its clearance is taken less a
// look-ahead L (1 - n_c^T heading) (L =
// kBodyLookahead: 0 heading away, 2L facing the disk), so omega enters the row and, at
// contact, the robot is turned along the disk rather than pinned; the true clearance stays >= m. The objective is strictly
// convex, so the minimiser is unique and continuous in the state and in the geometry; a disk
// whose row cannot bind inside the diamond (gamma (h_j - m) - n_j^T v_j >= the diamond's
// largest |G u|) is left out, which changes nothing, so there is no detection threshold.
#pragma once

#include <limits>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/robot/actuator_limits.h"
#include "amigobot_tracking/core/robot/diamond.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

// A convex QP in three variables: minimise sum_i weight_i (x_i - target_i)^2 subject to
// rows a^T x <= b. Solved by enumerating active sets of at most three rows (the minimiser is
// the equality-constrained minimiser of some such set): the feasible candidate of least cost.
struct SmallQp {
  Eigen::Vector3d weight = Eigen::Vector3d::Ones();  // > 0
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> a;
  std::vector<double> b;
};
struct SmallQpResult {
  bool solved = false;  // false: no feasible candidate (the rows contradict each other)
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  double cost = 0.0;
};
SmallQpResult solveSmallQp(const SmallQp& qp, double tolerance = 1e-9);

struct SafetyFilterInput {
  Pose2 pose;
  double offset = 0.3;          // r [m]
  double robot_radius = 0.48;   // R_eff [m]
  double gamma = 2.0;           // [1/s] barrier rate
  double min_margin = 1e-3;     // m [m]: the barrier keeps h_j >= m
  bool obstacle_velocities = false;  // use Disk::velocity in the rows
  bool body_rows = false;       // also hold the body disk (centre, robot_radius) clear
  Twist2 nominal;
  // The command may change by at most (max_change.v, max_change.omega) from `previous` (the
  // robot's acceleration over one period), while the barrier rows hold; +inf: no bound. A
  // `previous` outside the diamond (it shrank under a held command) is first scaled into it.
  Twist2 previous;
  Twist2 max_change{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  // With `braking`, each barrier row's clearance rate is also bounded by what the base can still
  // undo: the approach speed s from which it stops within the room x = h - m when it reacts
  // after tau = e (latency + cycle) + hold and then decelerates at a (brakingSpeed below), so a
  // row reads  n^T (G u - v_j) >= -min(gamma x, s_brake(x)) - s  (x > 0; inside m: -gamma x as
  // before). a = min(trans_decel, r rot_decel) for p_r's disk (its speed has a v and an r w
  // part), trans_decel for the body's. Ideal dynamics (infinite decelerations, no delays): off.
  // Why e: the base follows the command D = latency + cycle late, and near contact the curve
  // is s = x / tau, so the room obeys x'(t) = -x(t - D) / tau, which overshoots through 0 (an
  // oscillating solution) unless D / tau <= 1/e; planned with tau = D + hold the ramped base
  // grazed its disks by 6 mm (kDelayedBrakingFactor).
  bool braking = false;
  ActuatorLimits limits;
  double hold = 0.0;  // [s] how long the command is held (the control period)
};

// [m/s] the largest approach speed s from which a base that reacts after `delay` [s] and then
// decelerates at `decel` [m/s^2] stops within `room` [m]: delay s + s^2 / (2 decel) = room.
// 0 for room <= 0; +inf for room > 0 with an infinite decel and no delay.
double brakingSpeed(double room, double decel, double delay);

struct SafetyFilterResult {
  bool solved = false;
  Twist2 u;                // inside the diamond
  double slack = 0.0;      // > 0 only when the barrier rows could not all hold
  int rows = 0;            // barrier rows that entered the QP
  int active = 0;          // barrier rows active at the solution
};

// The least clearance of the disks the filter holds (the disk of robot_radius around p_r and,
// with body_rows, the body disk; a moving disk's from the body only), +inf without obstacles.
double safetyClearance(const SafetyFilterInput& in, const std::vector<Disk>& obstacles);

// [s] how far ahead a person's walk is held off the body: the time the base needs to stop from
// v_bar (v_bar / trans_decel after the braking curve's reaction time e (latency + cycle) +
// hold); 0 without obstacle velocities. A person's body row is taken from the nearest point of
// the stretch c_j .. c_j + span v_j (the capsule they sweep while the robot could still stop),
// not from c_j: the capsule holds the disk, so its clearance >= m keeps the true one >= m, and
// its rate is still -n^T v_j (n is normal to v_j where the nearest point is inside the
// stretch). From c_j alone, a person walking at 1 m/s across the robot's way 0.4 m ahead of it
// closed on the body at 0.87 m/s along the line of centres, and the row made the robot back at
// -0.3 m/s from a path it was 0.38 m clear of (pedestrian benchmark, crossing_ahead variant 044).
double personSpan(const SafetyFilterInput& in, const DiamondSet& diamond);
// The point of o's walk c_j .. c_j + span v_j nearest `point` (c_j for a still disk).
Eigen::Vector2d nearestOnWalk(const Disk& o, const Eigen::Vector2d& point, double span);

// [m] the body row's look-ahead L (above).
constexpr double kBodyLookahead = 0.05;

// [-] how many times the firmware's delay (latency + cycle) counts in the braking curve's
// reaction time: e, the largest D / tau for which x'(t) = -x(t - D) / tau has a
// non-oscillating solution (its characteristic equation mu e^mu = -D / tau has a real root
// only then), so a base that follows the command D late creeps up to the margin instead of
// overshooting it (docs/recommended_law.md).
constexpr double kDelayedBrakingFactor = 2.718281828459045;

// [m] the braking curve stops the base this far outside the margin m (its room is h - m -
// reserve; between m and m + reserve the row allows no approach and pushes nothing out). The
// delay equation above is one-dimensional: a base turning in place near a disk while it stops
// (its omega lags the command as its v does) still crept 1.1 mm past the curve's end in the
// clutter benchmark's U classes. 5 mm cost the doorway class 10 % more true ASE than 2 mm and
// let test_recommended_law's doorway jump 0.34 of the diamond in one step (the rate box gave way).
constexpr double kBrakingReserve = 0.002;

// The slack's weight: large, so a slack appears only where nothing else is feasible.
constexpr double kSafetySlackWeight = 1e6;
// [-] K: the rate box opens by K m/s per m/s a barrier row is short (the box's rows carry -K s).
constexpr double kRateBoxGiveWay = 10.0;

SafetyFilterResult safetyFilter(const SafetyFilterInput& in, const DiamondSet& diamond,
                                const std::vector<Disk>& obstacles);

}  // namespace core
}  // namespace amigobot_tracking

#include "amigobot_tracking/core/law/safety_filter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace amigobot_tracking {
namespace core {
namespace {

// A moving disk (a person) is held off the body only: the disk of radius R around p_r is the
// law's point, not the robot's, and its row, with the person's velocity in it, was met most
// cheaply by turning in place to swing p_r ahead of them (the body does not move when it
// turns): the robot turned 1.8 rad and lost 1.5 m to a person pacing across its way.
bool bodyOnly(const SafetyFilterInput& in, const Disk& o) { return in.body_rows && o.velocity.squaredNorm() > 0.0; }

double costOf(const SmallQp& qp, const Eigen::Vector3d& x) {
  return qp.weight.dot((x - qp.target).cwiseAbs2());
}

// The rows held as equalities (`rows`) are met up to round-off only, which the slack's weight
// (kSafetySlackWeight: A W^-1 A^T's condition number reaches ~4e7) makes larger than
// `tolerance`: a barrier row met with 2.2e-9 against a tolerance of 2e-9 left a QP with no
// candidate while a person stood in the robot (an invalid step, the command zeroed). They are
// checked against kActiveRowTolerance instead, which still rejects a set solved badly.
constexpr double kActiveRowTolerance = 1e-6;

bool feasible(const SmallQp& qp, const Eigen::Vector3d& x, double tolerance, const int* rows, int count) {
  for (size_t i = 0; i < qp.a.size(); ++i) {
    const bool active = std::find(rows, rows + count, static_cast<int>(i)) != rows + count;
    const double allowed = active ? std::max(tolerance, kActiveRowTolerance) : tolerance;
    if (qp.a[i].dot(x) > qp.b[i] + allowed * (1.0 + std::abs(qp.b[i]))) return false;
  }
  return true;
}

// The minimiser with the rows `rows` held as equalities: x = target - W^-1 A^T mu with
// (A W^-1 A^T) mu = A target - b. False when the rows are (nearly) dependent.
bool equalityMinimiser(const SmallQp& qp, const int* rows, int count, Eigen::Vector3d* x) {
  const Eigen::Vector3d inverse_weight = qp.weight.cwiseInverse();
  if (count == 0) {
    *x = qp.target;
    return true;
  }
  Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d& ai = qp.a[rows[i]];
    rhs(i) = ai.dot(qp.target) - qp.b[rows[i]];
    for (int j = 0; j < count; ++j) m(i, j) = ai.cwiseProduct(inverse_weight).dot(qp.a[rows[j]]);
  }
  const Eigen::MatrixXd block = m.topLeftCorner(count, count);
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(block);
  if (lu.rank() < count) return false;
  const Eigen::VectorXd mu = lu.solve(rhs.head(count));
  *x = qp.target;
  for (int i = 0; i < count; ++i) *x -= mu(i) * qp.a[rows[i]].cwiseProduct(inverse_weight);
  return true;
}

// [s] the braking curve's reaction time: the firmware's delay counts e times
// (kDelayedBrakingFactor): a base that follows the curve's command that late otherwise
// overshoots it into the disk; then the command is held for `hold`.
double reactionTime(const SafetyFilterInput& in) {
  return kDelayedBrakingFactor * (in.limits.latency + in.limits.cycle) + in.hold;
}

}  // namespace

double personSpan(const SafetyFilterInput& in, const DiamondSet& diamond) {
  if (!in.obstacle_velocities) return 0.0;
  const double braking = std::isfinite(in.limits.trans_decel) && in.limits.trans_decel > 0.0 ? diamond.vMax() / in.limits.trans_decel : 0.0;
  return braking + reactionTime(in);
}

Eigen::Vector2d nearestOnWalk(const Disk& o, const Eigen::Vector2d& point, double span) {
  const Eigen::Vector2d walk = span * o.velocity;
  const double length2 = walk.squaredNorm();
  if (!(length2 > 0.0) || !std::isfinite(length2)) return o.center;
  return o.center + std::clamp((point - o.center).dot(walk) / length2, 0.0, 1.0) * walk;
}

double brakingSpeed(double room, double decel, double delay) {
  if (!(room > 0.0)) return 0.0;
  if (!std::isfinite(decel)) return delay > 0.0 ? room / delay : std::numeric_limits<double>::infinity();
  // The positive root of s^2 / (2 a) + tau s - x = 0, written without cancellation.
  return 2.0 * room / (delay + std::sqrt(delay * delay + 2.0 * room / decel));
}

SmallQpResult solveSmallQp(const SmallQp& qp, double tolerance) {
  SmallQpResult best;
  best.cost = std::numeric_limits<double>::infinity();
  const int m = static_cast<int>(qp.a.size());
  auto consider = [&](const int* rows, int count) {
    Eigen::Vector3d x;
    if (!equalityMinimiser(qp, rows, count, &x) || !feasible(qp, x, tolerance, rows, count)) return;
    const double cost = costOf(qp, x);
    if (cost < best.cost) {
      best.solved = true;
      best.cost = cost;
      best.x = x;
    }
  };
  consider(nullptr, 0);
  if (best.solved) return best;  // the unconstrained minimiser is feasible: it is the answer
  for (int i = 0; i < m; ++i) {
    int one[1] = {i};
    consider(one, 1);
    for (int j = i + 1; j < m; ++j) {
      int two[2] = {i, j};
      consider(two, 2);
      for (int k = j + 1; k < m; ++k) {
        int three[3] = {i, j, k};
        consider(three, 3);
      }
    }
  }
  return best;
}

SafetyFilterResult safetyFilter(const SafetyFilterInput& in, const DiamondSet& diamond,
                                const std::vector<Disk>& obstacles) {
  const double r = in.offset;
  const Eigen::Vector2d heading(std::cos(in.pose.theta), std::sin(in.pose.theta));
  const Eigen::Vector2d side(-heading.y(), heading.x());
  const Eigen::Vector2d p_r = in.pose.position() + r * heading;
  SmallQp qp;
  qp.weight = Eigen::Vector3d(1.0, r * r, kSafetySlackWeight);
  qp.target = Eigen::Vector3d(in.nominal.v, in.nominal.omega, 0.0);
  // The diamond's four edges, and s >= 0.
  for (double sv : {-1.0, 1.0})
    for (double sw : {-1.0, 1.0}) {
      qp.a.emplace_back(sv / diamond.vMax(), sw / diamond.wMax(), 0.0);
      qp.b.push_back(1.0);
    }
  qp.a.emplace_back(0.0, 0.0, -1.0);
  qp.b.push_back(0.0);
  // |G u| inside the diamond is at most max(v_bar, r w_bar) (|G u|^2 = v^2 + r^2 w^2, convex,
  // largest at a vertex).
  const double reach = std::max(diamond.vMax(), r * diamond.wMax());
  // gamma (h - m), bounded by the braking curve when the base ramps (safety_filter.h).
  const double delay = reactionTime(in);
  auto allowedApproach = [&](double h, double decel) {
    const double room = h - in.min_margin;
    const double rate = in.gamma * room;
    return in.braking && room > 0.0 ? std::min(rate, brakingSpeed(room - kBrakingReserve, decel, delay)) : rate;
  };
  const double offset_decel = std::min(in.limits.trans_decel, r * in.limits.rot_decel);
  SafetyFilterResult result;
  for (const Disk& o : obstacles) {
    if (bodyOnly(in, o)) continue;  // a person: the body's row below
    Eigen::Vector2d away = p_r - o.center;
    double distance = away.norm();
    if (distance < 1e-9) {  // on the centre: back off along -heading
      away = -heading;
      distance = 1.0;
    }
    const Eigen::Vector2d n = away / distance;
    const double h = away.norm() - (in.robot_radius + o.radius);
    const double bound = allowedApproach(h, offset_decel) - (in.obstacle_velocities ? n.dot(o.velocity) : 0.0);
    if (bound >= reach) continue;  // cannot bind inside the diamond
    // -n^T G u - s <= gamma (h - m) - n^T v_j, with G u = v heading + r w side.
    qp.a.emplace_back(-n.dot(heading), -r * n.dot(side), -1.0);
    qp.b.push_back(bound);
    ++result.rows;
  }
  if (in.body_rows) {
    const double walked = personSpan(in, diamond);
    for (const Disk& o : obstacles) {
      const Eigen::Vector2d away = in.pose.position() - nearestOnWalk(o, in.pose.position(), walked);
      const double distance = std::max(away.norm(), 1e-9);
      const Eigen::Vector2d n = away.norm() < 1e-9 ? Eigen::Vector2d(-heading) : Eigen::Vector2d(away / distance);
      const double facing = n.dot(heading);  // 1: heading away from the disk, -1: at it
      // h = |c - c_j| - (R + r_j) - L (1 - n^T heading): the body's clearance less a look-ahead
      // L that grows as the robot faces the disk, so h >= m keeps the true clearance >= m and
      // dh/dt has omega in it: at contact the filter turns the robot along the disk instead
      // of holding v = 0 while omega flips (v-only rows pinned a body on a ring's disk 24 s).
      const double h = distance - (in.robot_radius + o.radius) - kBodyLookahead * (1.0 - facing);
      const double bound = allowedApproach(h, in.limits.trans_decel) - (in.obstacle_velocities ? n.dot(o.velocity) : 0.0);
      // dh/dt = v (n^T heading + L (1 - (n^T heading)^2) / |c - c_j|) + L omega n^T side.
      const double a_v = facing + kBodyLookahead * (1.0 - facing * facing) / distance;
      const double a_w = kBodyLookahead * n.dot(side);
      if (bound >= std::max(std::abs(a_v) * diamond.vMax(), std::abs(a_w) * diamond.wMax())) continue;  // cannot bind
      qp.a.emplace_back(-a_v, -a_w, -1.0);
      qp.b.push_back(bound);
      ++result.rows;
    }
  }
  SmallQpResult solution = solveSmallQp(qp);
  if (!solution.solved) return result;
  double slack = std::max(0.0, solution.x(2));
  const size_t barrier_end = qp.a.size();
  SmallQp boxed;                 // the rate box's QP, when it has one
  const SmallQp* used = &qp;     // the QP whose rows `solution` is judged against
  // A command held from a larger diamond (reconfigure) is first brought inside this one.
  Twist2 previous = in.previous;
  if (const auto inside = diamond.saturate(previous)) previous = *inside;
  // Where the box-free minimiser needs no slack and already lies in the box, it is the boxed
  // QP's minimiser too (that QP only adds rows it meets): the second solve is skipped.
  const bool in_box = slack == 0.0 && std::abs(solution.x(0) - previous.v) <= in.max_change.v &&
                      std::abs(solution.x(1) - previous.omega) <= in.max_change.omega;
  if (!in_box && std::isfinite(in.max_change.v) && std::isfinite(in.max_change.omega) && in.previous.isFinite()) {
    // The rate box, |v - v_prev| <= dv + K s and |w - w_prev| <= dw + K (w_bar / v_bar) s, over
    // the barrier rows loosened by the slack s0 they need without it (0 unless they conflict
    // inside the diamond): the box holds while the barriers hold as well as they can, and gives
    // way K times faster than a barrier row would be short. Safety comes first, and u is
    // continuous (s0 is the slack of a strictly convex QP); without s0 a conflict's slack
    // opened the box, and u jumped between the diamond's vertices in one step.
    boxed = qp;
    for (size_t i = 5; i < barrier_end; ++i) boxed.b[i] += slack;
    const double give_v = kRateBoxGiveWay, give_w = kRateBoxGiveWay * diamond.wMax() / diamond.vMax();
    for (double sign : {-1.0, 1.0}) {
      boxed.a.emplace_back(sign, 0.0, -give_v);
      boxed.b.push_back(sign * previous.v + in.max_change.v);
      boxed.a.emplace_back(0.0, sign, -give_w);
      boxed.b.push_back(sign * previous.omega + in.max_change.omega);
    }
    const SmallQpResult within = solveSmallQp(boxed);
    if (within.solved) {  // always: the slack opens the box
      solution = within;
      used = &boxed;
      slack += std::max(0.0, within.x(2));
    }
  }
  result.solved = true;
  result.u = {solution.x(0), solution.x(1)};
  result.slack = slack;
  for (size_t i = 5; i < barrier_end; ++i)
    if (used->a[i].dot(solution.x) > used->b[i] - 1e-9 * (1.0 + std::abs(used->b[i]))) ++result.active;
  // Round-off may leave the vertex a hair outside the diamond: scale it back (sigma of (12)).
  if (const auto inside = diamond.saturate(result.u)) result.u = *inside;
  return result;
}

double safetyClearance(const SafetyFilterInput& in, const std::vector<Disk>& obstacles) {
  const Eigen::Vector2d p_r = in.pose.position() + in.offset * Eigen::Vector2d(std::cos(in.pose.theta), std::sin(in.pose.theta));
  double least = std::numeric_limits<double>::infinity();
  for (const Disk& o : obstacles) {
    if (!bodyOnly(in, o)) least = std::min(least, (p_r - o.center).norm() - in.robot_radius - o.radius);
    if (in.body_rows) least = std::min(least, (in.pose.position() - o.center).norm() - in.robot_radius - o.radius);
  }
  return least;
}

}  // namespace core
}  // namespace amigobot_tracking

// The recommended law's safety filter (core/law/safety_filter.h): the exact small QP against a
// brute-force search, its constraints, and the continuity of its command in the geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "amigobot_tracking/core/robot/actuator_model.h"
#include "amigobot_tracking/core/law/safety_filter.h"

using namespace amigobot_tracking::core;

namespace {

struct Instance {
  SafetyFilterInput in;
  std::vector<Disk> disks;
};

Instance randomInstance(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Instance k;
  k.in.pose = {unit(rng), unit(rng), M_PI * unit(rng)};
  k.in.offset = 0.3;
  k.in.robot_radius = 0.48;
  k.in.gamma = 2.0;
  k.in.body_rows = rng() % 2 == 0;  // half the instances also hold the body disk
  if (k.in.body_rows) k.in.robot_radius = 0.18;
  k.in.nominal = {0.6 * unit(rng), 1.6 * unit(rng)};
  const int disks = 1 + static_cast<int>(rng() % 4);
  const Eigen::Vector2d p_r = k.in.pose.position() + 0.3 * Eigen::Vector2d(std::cos(k.in.pose.theta), std::sin(k.in.pose.theta));
  for (int j = 0; j < disks; ++j) {
    Disk d;
    d.radius = 0.1 + 0.2 * (unit(rng) + 1.0) / 2.0;
    const double angle = M_PI * unit(rng);
    const double clearance = 0.15 * (unit(rng) + 1.0);  // 0 .. 0.3 m: rows that bind
    d.center = p_r + (k.in.robot_radius + d.radius + clearance) * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    k.disks.push_back(d);
  }
  return k;
}

// The cost of (v, w) with the least slack that makes every barrier row hold; +inf outside the diamond.
double bruteCost(const Instance& k, const DiamondSet& diamond, double v, double w) {
  if (std::abs(v) / diamond.vMax() + std::abs(w) / diamond.wMax() > 1.0) return INFINITY;
  const Eigen::Vector2d heading(std::cos(k.in.pose.theta), std::sin(k.in.pose.theta));
  const Eigen::Vector2d side(-heading.y(), heading.x());
  const Eigen::Vector2d p_r = k.in.pose.position() + k.in.offset * heading;
  const Eigen::Vector2d u_r = v * heading + k.in.offset * w * side;
  double slack = 0.0;
  for (const Disk& d : k.disks) {
    const Eigen::Vector2d n = (p_r - d.center).normalized();
    const double h = (p_r - d.center).norm() - k.in.robot_radius - d.radius;
    slack = std::max(slack, -k.in.gamma * (h - k.in.min_margin) - n.dot(u_r));
    if (!k.in.body_rows) continue;
    // The body row, written from its definition: h = |c - c_j| - R - r_j - L (1 - n^T heading),
    // dh/dt by finite differences of h along the motion (v heading, omega).
    const double L = kBodyLookahead;
    auto bodyH = [&](const Eigen::Vector2d& c, double theta) {
      const Eigen::Vector2d n = (c - d.center).normalized();
      return (c - d.center).norm() - k.in.robot_radius - d.radius -
             L * (1.0 - n.dot(Eigen::Vector2d(std::cos(theta), std::sin(theta))));
    };
    const Eigen::Vector2d c = k.in.pose.position();
    const double dt = 1e-7;
    const double h_c = bodyH(c, k.in.pose.theta);
    const double rate = (bodyH(c + dt * v * heading, k.in.pose.theta + dt * w) - h_c) / dt;
    slack = std::max(slack, -k.in.gamma * (h_c - k.in.min_margin) - rate);
  }
  const double dv = v - k.in.nominal.v, dw = w - k.in.nominal.omega;
  return dv * dv + k.in.offset * k.in.offset * dw * dw + kSafetySlackWeight * slack * slack;
}

}  // namespace

TEST(SafetyFilter, MatchesABruteForceSearchOnRandomInstances) {
  std::mt19937 rng(7);
  const DiamondSet diamond(0.3, 0.8);
  for (int trial = 0; trial < 60; ++trial) {
    const Instance k = randomInstance(rng);
    const SafetyFilterResult r = safetyFilter(k.in, diamond, k.disks);
    ASSERT_TRUE(r.solved) << trial;
    ASSERT_TRUE(diamond.contains(r.u, 1e-9)) << trial;
    const double mine = bruteCost(k, diamond, r.u.v, r.u.omega);
    double best = INFINITY, best_v = 0.0, best_w = 0.0;
    const int n = 300;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const double v = diamond.vMax() * (2.0 * i / n - 1.0), w = diamond.wMax() * (2.0 * j / n - 1.0);
        const double c = bruteCost(k, diamond, v, w);
        if (c < best) best = c, best_v = v, best_w = w;
      }
    // No grid point beats the exact solution, and the grid's best lies next to it.
    EXPECT_LE(mine, best * (1.0 + 1e-6) + 1e-9) << trial;  // the brute force differentiates the body row numerically
    if (r.slack > 1e-6) continue;  // a slack's huge weight leaves the cost flat along some (v, w): compare costs only
    // Near in the QP's own metric |G du| (an active row may leave the grid's best some way along it).
    EXPECT_LT(std::hypot(r.u.v - best_v, k.in.offset * (r.u.omega - best_w)), 0.025) << trial;
  }
}

TEST(SafetyFilter, KeepsTheNominalCommandWhenNothingBinds) {
  SafetyFilterInput in;
  in.nominal = {0.1, 0.2};
  const SafetyFilterResult r = safetyFilter(in, DiamondSet(0.3, 0.8), {Disk{Eigen::Vector2d(5.0, 0.0), 0.3, Eigen::Vector2d::Zero()}});
  ASSERT_TRUE(r.solved);
  EXPECT_DOUBLE_EQ(r.u.v, 0.1);
  EXPECT_DOUBLE_EQ(r.u.omega, 0.2);
  EXPECT_EQ(r.rows, 0);  // the far disk cannot bind inside the diamond
}

TEST(SafetyFilter, StopsTheApproachAtTheBarrierAndNeedsNoSlackForStaticDisks) {
  SafetyFilterInput in;  // p_r at (0.3, 0), heading +x, a disk straight ahead 1 cm from contact
  in.nominal = {0.3, 0.0};
  const Disk disk{Eigen::Vector2d(0.3 + 0.48 + 0.2 + 0.01, 0.0), 0.2, Eigen::Vector2d::Zero()};
  const SafetyFilterResult r = safetyFilter(in, DiamondSet(0.3, 0.8), {disk});
  ASSERT_TRUE(r.solved);
  // clearance' = -gamma (h - m), up to the penalised slack: about |du| / slack_weight.
  EXPECT_NEAR(r.u.v, in.gamma * (0.01 - in.min_margin), 1e-6);
  EXPECT_NEAR(r.u.omega, 0.0, 1e-9);
  EXPECT_LT(r.slack, 1e-6);
  EXPECT_EQ(r.active, 1);
}

// A disk sweeping in from far away, then a second disk joining it: the command never jumps.
TEST(SafetyFilter, CommandIsContinuousAsADiskAppearsAndJoinsAnother) {
  SafetyFilterInput in;
  in.nominal = {0.25, 0.3};
  const DiamondSet diamond(0.3, 0.8);
  Twist2 last;
  bool first = true;
  double largest_jump = 0.0;
  for (double x = 2.5; x >= 1.0; x -= 0.0005) {
    const std::vector<Disk> disks = {Disk{Eigen::Vector2d(x, 0.1), 0.2, Eigen::Vector2d::Zero()},
                                     Disk{Eigen::Vector2d(x + 0.2, 0.9 * (x - 1.0) - 0.6), 0.2, Eigen::Vector2d::Zero()}};
    const SafetyFilterResult r = safetyFilter(in, diamond, disks);
    ASSERT_TRUE(r.solved);
    if (!first) largest_jump = std::max(largest_jump, std::hypot(r.u.v - last.v, 0.3 * (r.u.omega - last.omega)));
    last = r.u;
    first = false;
  }
  // Lipschitz in the geometry: a 0.5 mm move changes |G du| by well under 1 cm/s.
  EXPECT_LT(largest_jump, 0.005);
}

TEST(SafetyFilter, SlackKeepsItFeasibleWhenAMovingDiskCannotBeOutrun) {
  SafetyFilterInput in;
  in.obstacle_velocities = true;
  in.nominal = {0.0, 0.0};
  // Two disks closing in from both sides faster than the diamond allows to escape.
  const std::vector<Disk> disks = {Disk{Eigen::Vector2d(0.3, 0.75), 0.2, Eigen::Vector2d(0.0, -1.0)},
                                   Disk{Eigen::Vector2d(0.3, -0.75), 0.2, Eigen::Vector2d(0.0, 1.0)}};
  const SafetyFilterResult r = safetyFilter(in, DiamondSet(0.3, 0.8), disks);
  ASSERT_TRUE(r.solved);
  EXPECT_GT(r.slack, 0.0);
  EXPECT_TRUE(DiamondSet(0.3, 0.8).contains(r.u, 1e-9));
}

// A disk beside and a little behind the body: reversing would graze it. The disk of radius R
// around p_r is far from it, so only the body row (body_rows) limits the motion, to
// h' = -gamma (h - m) with h the body's clearance less its look-ahead; without it the command
// is the nominal one.
TEST(SafetyFilter, BodyRowsHoldTheBodyWhereTheOffsetPointsDiskIsClear) {
  SafetyFilterInput in;
  in.robot_radius = 0.18;
  in.nominal = {-0.3, 0.0};
  const Disk disk{Eigen::Vector2d(-0.05, 0.45), 0.2, Eigen::Vector2d::Zero()};
  const DiamondSet diamond(0.3, 0.8);
  const SafetyFilterResult loose = safetyFilter(in, diamond, {disk});
  ASSERT_TRUE(loose.solved);
  EXPECT_DOUBLE_EQ(loose.u.v, -0.3);
  in.body_rows = true;
  const SafetyFilterResult held = safetyFilter(in, diamond, {disk});
  ASSERT_TRUE(held.solved);
  const Eigen::Vector2d away = in.pose.position() - disk.center;
  const Eigen::Vector2d n = away.normalized();  // heading +x: n^T heading = n.x, n^T side = n.y
  const double h_c = away.norm() - 0.18 - 0.2 - kBodyLookahead * (1.0 - n.x());
  const double a_v = n.x() + kBodyLookahead * (1.0 - n.x() * n.x()) / away.norm(), a_w = kBodyLookahead * n.y();
  // The row binds: a_v v + a_w omega = -gamma (h - m), up to the penalised slack.
  EXPECT_NEAR(a_v * held.u.v + a_w * held.u.omega, -in.gamma * (h_c - in.min_margin), 1e-4);
  EXPECT_GT(held.u.v, -0.3 + 0.02);
  EXPECT_LT(held.slack, 1e-6);
  EXPECT_NEAR(safetyClearance(in, {disk}), away.norm() - 0.18 - 0.2, 1e-12);  // the true clearance
}

// A person walking at p_r from ahead and to the right (the robot stopped, body_rows): p_r's row,
// with the person's velocity in it, was met by turning in place at the diamond's edge to swing
// p_r ahead of them, which moves no part of the robot away. A moving disk holds off the body
// only: the robot backs away from them, hardly turning. A still disk there keeps p_r's row.
TEST(SafetyFilter, APersonWalkingAtTheOffsetPointDoesNotTurnTheRobotInPlace) {
  SafetyFilterInput in;
  in.robot_radius = 0.18;
  in.body_rows = true;
  in.obstacle_velocities = true;
  in.nominal = {0.0, 0.0};
  const DiamondSet diamond(0.3, 0.8);
  const Disk person{Eigen::Vector2d(0.45, -0.45), 0.25, Eigen::Vector2d(0.0, 0.6)};
  const SafetyFilterResult r = safetyFilter(in, diamond, {person});
  ASSERT_TRUE(r.solved);
  EXPECT_LT(std::abs(r.u.omega), 0.1) << "turned in place for a person";
  EXPECT_LE(r.u.v, 0.0) << "drove toward the person";
  EXPECT_NEAR(safetyClearance(in, {person}), person.center.norm() - 0.18 - 0.25, 1e-12) << "the body's clearance";
  Disk still = person;
  still.velocity.setZero();
  EXPECT_NEAR(safetyClearance(in, {still}), (person.center - Eigen::Vector2d(0.3, 0.0)).norm() - 0.18 - 0.25, 1e-12)
      << "a still disk keeps p_r's disk";
}

// A person walking at 1 m/s across the robot's way, their path 0.4 m clear of the body, 1.5 m
// off and closing at 0.87 m/s along the line of centres (the ramped AmigoBot, braking planned):
// a row from their centre made the stopped robot back at the diamond's edge from a path it
// stood clear of. The row from the stretch they walk while the base stops (personSpan) lets it
// stand; one walking straight at the body still makes it back away.
TEST(SafetyFilter, APersonCrossingBesideTheBodyDoesNotMakeItBackButOneWalkingAtItDoes) {
  SafetyFilterInput in;
  in.robot_radius = 0.18;
  in.body_rows = true;
  in.obstacle_velocities = true;
  in.braking = true;
  in.hold = 0.05;
  in.gamma = 5.0;
  in.nominal = {0.0, 0.0};
  const DiamondSet diamond(0.3, 0.8);
  EXPECT_NEAR(personSpan(in, diamond), 0.3 / in.limits.trans_decel + kDelayedBrakingFactor * (in.limits.latency + in.limits.cycle) + 0.05, 1e-12);
  const Disk crossing{Eigen::Vector2d(0.81, -1.3), 0.25, Eigen::Vector2d(0.0, 1.0)};
  const SafetyFilterResult beside = safetyFilter(in, diamond, {crossing});
  ASSERT_TRUE(beside.solved);
  EXPECT_GT(beside.u.v, -0.01) << "backed from a person whose path passes 0.38 m clear of the body";
  const Disk at_it{Eigen::Vector2d(0.0, -1.3), 0.25, Eigen::Vector2d(0.0, 1.0)};
  const Eigen::Vector2d near = nearestOnWalk(at_it, in.pose.position(), personSpan(in, diamond));
  EXPECT_NEAR(near.y(), -1.3 + personSpan(in, diamond), 1e-12) << "the nearest point is where they will be";
  const SafetyFilterResult head_on = safetyFilter(in, diamond, {at_it});
  ASSERT_TRUE(head_on.solved);
  EXPECT_GT(std::abs(head_on.u.v) + std::abs(head_on.u.omega), 0.1) << "stood still while a person walked at the body";
  const Disk still{Eigen::Vector2d(0.81, -1.3), 0.25, Eigen::Vector2d::Zero()};
  EXPECT_EQ(nearestOnWalk(still, in.pose.position(), 1.0), still.center) << "a still disk is its centre";
}

// The braking curve: delay s + s^2 / (2 a) = room at the returned s, 0 without room, room /
// delay without a deceleration limit.
TEST(SafetyFilter, BrakingSpeedStopsWithinTheRoom) {
  for (double room : {0.001, 0.05, 0.3, 2.0}) {
    const double s = brakingSpeed(room, 0.75, 0.25);
    EXPECT_NEAR(0.25 * s + s * s / (2.0 * 0.75), room, 1e-12) << room;
  }
  EXPECT_EQ(brakingSpeed(0.0, 0.75, 0.25), 0.0);
  EXPECT_EQ(brakingSpeed(-0.1, 0.75, 0.25), 0.0);
  EXPECT_NEAR(brakingSpeed(0.1, INFINITY, 0.05), 2.0, 1e-12);
  EXPECT_TRUE(std::isinf(brakingSpeed(0.1, INFINITY, 0.0)));
}

namespace {

// The base as the firmware drives it (actuator_limits.h): a command is sampled once per cycle,
// takes effect `latency` after it was sent, and v slews toward it at trans_accel / trans_decel.
// Head-on at a disk from full speed, under the filter at 20 Hz; returns the least true clearance
// of the disks the filter holds (p_r's disk of radius R, which meets the disk first here, and
// the body's). Only v matters here (the disk is dead ahead: the filter's omega stays 0).
double headOnLeastBodyClearance(bool braking) {
  const ActuatorLimits limits;
  const double period = 0.05, dt = 0.001;
  const Disk disk{Eigen::Vector2d(1.2, 0.0), 0.2, Eigen::Vector2d::Zero()};
  SafetyFilterInput in;
  in.robot_radius = 0.18;
  in.body_rows = true;
  in.gamma = 5.333;  // the shipped barrier_rate
  in.braking = braking;
  in.limits = limits;
  in.hold = period;
  in.nominal = {0.3, 0.0};
  const DiamondSet diamond(0.3, 0.8);
  std::vector<std::pair<double, double>> sent;  // (time, v)
  double x = 0.0, v = 0.3, target = 0.3, least = INFINITY;
  const int per_control = static_cast<int>(std::lround(period / dt)), per_cycle = static_cast<int>(std::lround(limits.cycle / dt));
  for (int k = 0; k * dt < 8.0; ++k) {
    const double t = k * dt;
    if (k % per_control == 0) {
      in.pose = {x, 0.0, 0.0};
      const SafetyFilterResult r = safetyFilter(in, diamond, {disk});
      EXPECT_TRUE(r.solved);
      sent.emplace_back(t, r.u.v);
    }
    if (k % per_cycle == 0)  // the firmware samples the newest command that has arrived
      for (const auto& [stamp, command] : sent)
        if (stamp <= t - limits.latency + 1e-9) target = command;
    const double rate = std::abs(target) > std::abs(v) ? limits.trans_accel : limits.trans_decel;
    v += std::clamp(target - v, -rate * dt, rate * dt);
    x += v * dt;
    in.pose = {x, 0.0, 0.0};
    least = std::min(least, safetyClearance(in, {disk}));  // the body's and p_r's disk, true positions
  }
  return least;
}

}  // namespace

// Planned with the ramps and delays, the ramped base keeps its disks clear (the margin m less
// 5 mm of tolerance); planned with gamma alone, the command brakes later than the base can
// and p_r's disk runs into the disk.
TEST(SafetyFilter, BrakingRowsKeepARampedBaseClear) {
  const double planned = headOnLeastBodyClearance(true);
  const double unplanned = headOnLeastBodyClearance(false);
  // Measured: 3.0 mm with the curve (it aims at m + kBrakingReserve); -2.3 mm while the curve
  // counted the firmware's delay once.
  EXPECT_GE(planned, SafetyFilterInput().min_margin);
  EXPECT_LT(unplanned, 0.0);
}

// The clutter benchmark's graze, reduced: the robot backs at v_bar into a disk behind it, on
// the AmigoBot's firmware (core::ActuatorModel: ramps, 0.1 s cycle and latency), under the
// filter and the law's rate box, at 20 and 10 Hz and from several distances (the encounter
// falls at different phases of the firmware's cycle). The braking curve that counted the delay
// once let the body overshoot its margin by 6.5 mm, into the disk (-5.5 mm; -6.3 mm in the benchmark's
// U classes): the base follows the curve's command a delay late and oscillates through it.
TEST(SafetyFilter, RampedBaseBackingIntoADiskStopsOutsideTheMargin) {
  const DiamondSet diamond(0.3, 0.8);
  double least = INFINITY;
  for (double period : {0.05, 0.1}) {
    for (double start : {0.5, 0.6, 0.73, 0.86, 1.0}) {
      ActuatorModel base(ActuatorLimits{}, kAmigoHalfTrack);
      const Disk disk{Eigen::Vector2d(-(0.18 + 0.2 + start), 0.0), 0.2, Eigen::Vector2d::Zero()};
      SafetyFilterInput in;
      in.robot_radius = 0.18;
      in.body_rows = true;
      in.gamma = 5.333;
      in.braking = true;
      in.hold = period;
      in.nominal = {-0.3, 0.0};
      in.max_change = {0.3 * period / 0.25, 0.8 * period / 0.25};  // command_rise_time 0.25 s
      Pose2 pose{0.0, 0.0, 0.0};
      for (double t = 0.0; t < 8.0; t += period) {
        in.pose = pose;
        const SafetyFilterResult r = safetyFilter(in, diamond, {disk});
        ASSERT_TRUE(r.solved);
        in.previous = r.u;
        for (int k = 0; k < 10; ++k) {  // the body's clearance every tenth of a period
          pose = driveBody(&base, pose, r.u, period / 10.0);
          least = std::min(least, (pose.position() - disk.center).norm() - 0.18 - disk.radius);
        }
      }
    }
  }
  // Measured 3.0 mm (the curve aims at m + kBrakingReserve); -5.5 mm while it counted the delay once.
  EXPECT_GE(least, SafetyFilterInput().min_margin);
}

// A person walking into the robot left p_r's and the body's rows of the same disk nearly
// opposite, and the QP's answer (two diamond edges and a row, slack 3.75) met its active row
// with a round-off of 2.2e-9 against a tolerance of 2e-9: no candidate passed, the filter gave
// up and the step was invalid (the command zeroed). The rows as the pedestrian benchmark met them.
TEST(SafetyFilter, SolvesTheIllConditionedQpOfAPersonInsideTheRobot) {
  SmallQp qp;
  qp.weight = {1.0, 0.09, kSafetySlackWeight};
  qp.target = {1.0009903876408666, -0.30202134328284669, 0.0};
  const double rows[7][4] = {{-3.3333333333333335, -1.25, 0.0, 1.0},
                             {-3.3333333333333335, 1.25, 0.0, 1.0},
                             {3.3333333333333335, -1.25, 0.0, 1.0},
                             {3.3333333333333335, 1.25, 0.0, 1.0},
                             {0.0, 0.0, -1.0, 0.0},
                             {-0.98354224430281512, 0.054203494633283028, -1.0, -2.7392118449701233},
                             {0.99680793991572092, 0.003313198090391828, -1.0, -4.0517711895449748}};
  for (const auto& row : rows) {
    qp.a.emplace_back(row[0], row[1], row[2]);
    qp.b.push_back(row[3]);
  }
  const SmallQpResult r = solveSmallQp(qp);
  ASSERT_TRUE(r.solved);
  // The least-cost feasible vertex (every active set enumerated offline): v = -v_bar, w = 0.
  EXPECT_NEAR(r.x(0), -0.3, 1e-6);
  EXPECT_NEAR(r.x(1), 0.0, 1e-6);
  EXPECT_NEAR(r.x(2), 3.75272881, 1e-6);
  for (size_t i = 0; i < qp.a.size(); ++i) EXPECT_LE(qp.a[i].dot(r.x), qp.b[i] + 1e-6) << "row " << i;
}

// Extensions beyond the paper: tangential escape, moving obstacles, prediction.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "amigobot_tracking/core/law/avoidance.h"
#include "amigobot_tracking/sim/closed_loop.h"
#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/core/robot/unicycle.h"

using namespace amigobot_tracking::core;
using namespace amigobot_tracking::sim;

namespace {

Eigen::Vector2d unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

// Target on the x axis at 0.3 m/s through the centre of a 0.3 m disk at x = 2; the robot
// starts behind it on the same line, facing it (the symmetric saddle (docs/beyond_paper.md)).
class StraightLine : public Reference {
 public:
  ReferenceState at(double t) const override { return {{0.6 + 0.3 * t, 0.0}, {0.3, 0.0}}; }
};

struct SaddleRun {
  double peak_error = 0.0;
  double longest_stall = 0.0;  // [s] p_r slower than 0.02 m/s while |e| > 0.3 m
  double min_clearance = 1e9;
  double final_error = 0.0;
};

SaddleRun runSaddle(bool tangential) {
  ClosedLoopSetup setup;  // real-robot defaults (Section 5.3 gains) with room to catch up:
  setup.controller.v_max = 0.6;  // the target runs at 0.3 m/s, the paper's v_bar
  setup.controller.w_max = 1.6;
  setup.controller.paper.tangential_avoidance = tangential;
  setup.initial_pose = {0.0, 0.0, 0.0};
  setup.obstacles = {{{2.0, 0.0}, 0.3}};
  setup.duration = 40.0;
  setup.control_period = 0.01;
  SaddleRun run;
  double stall = 0.0;
  Eigen::Vector2d last_p_r(0.3, 0.0);
  runClosedLoop(setup, StraightLine(), [&](const ClosedLoopStep& step) {
    const double err = step.output.e.norm();
    run.peak_error = std::max(run.peak_error, err);
    run.min_clearance = std::min(run.min_clearance, step.output.min_clearance);
    const double speed = (step.output.p_r - last_p_r).norm() / setup.control_period;
    last_p_r = step.output.p_r;
    stall = (speed < 0.02 && err > 0.3 && step.t > 1.0) ? stall + setup.control_period : 0.0;
    run.longest_stall = std::max(run.longest_stall, stall);
    run.final_error = err;
  });
  return run;
}

}  // namespace

TEST(Tangential, ZeroWithoutConflict) {
  const Disk disk{{0.0, 0.0}, 0.3};
  for (double angle = 0.0; angle < 2 * M_PI; angle += 0.05) {
    const Eigen::Vector2d p_r = 0.6 * unit(angle);  // inside the band of delta = 0.25
    // Target direction pointing away from the obstacle (or tangentially): no conflict.
    for (double offset : {-1.5, -0.7, 0.0, 0.7, 1.5}) {
      const Eigen::Vector2d e_hat = unit(angle + offset);
      const TangentialResult r = tangentialTerm(p_r, {disk}, 0.18, 0.25, e_hat, 0);
      EXPECT_EQ(r.u_t, Eigen::Vector2d::Zero());
      EXPECT_EQ(r.side, 0);
    }
  }
}

TEST(Tangential, NeverPointsIntoTheObstacleAndTurnsTowardTheTarget) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), dist(0.49, 0.72);
  const Disk disk{{1.0, -1.0}, 0.3};
  int active = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector2d normal = unit(angle(rng));
    const Eigen::Vector2d p_r = disk.center + dist(rng) * normal;
    const Eigen::Vector2d e_hat = unit(angle(rng));
    const TangentialResult r = tangentialTerm(p_r, {disk}, 0.18, 0.25, e_hat, 0);
    EXPECT_NEAR(r.u_t.dot(normal), 0.0, 1e-9 * (1.0 + r.u_t.norm()));  // purely tangential
    if (r.side != 0) {
      ++active;
      EXPECT_LT(e_hat.dot(normal), 0.0);         // only under conflict
      EXPECT_GE(r.u_t.dot(e_hat), -1e-12);       // the side that turns toward the target
    }
  }
  EXPECT_GT(active, 200);
}

TEST(Tangential, SideIsLatchedWithHysteresis) {
  const Disk disk{{0.0, 0.0}, 0.3};
  const Eigen::Vector2d p_r(-0.6, 0.0);
  // Exactly symmetric: counter-clockwise by default (from the disk's left: passing below).
  TangentialResult r = tangentialTerm(p_r, {disk}, 0.18, 0.25, {1.0, 0.0}, 0);
  EXPECT_EQ(r.side, 1);
  EXPECT_LT(r.u_t.y(), 0.0);
  // Target slightly above (sine 0.1 < hysteresis 0.2): the latched side holds.
  r = tangentialTerm(p_r, {disk}, 0.18, 0.25, unit(0.1), 1, 0.2);
  EXPECT_EQ(r.side, 1);
  // Without a latch the same target picks the side that passes above.
  EXPECT_EQ(tangentialTerm(p_r, {disk}, 0.18, 0.25, unit(0.1), 0, 0.2).side, -1);
  // Clearly above (sine 0.5): switches.
  r = tangentialTerm(p_r, {disk}, 0.18, 0.25, unit(0.52), 1, 0.2);
  EXPECT_EQ(r.side, -1);
  // The default margin (0.6) holds the side at sine 0.5 and lets it go at sine 0.7.
  EXPECT_EQ(tangentialTerm(p_r, {disk}, 0.18, 0.25, unit(0.52), 1).side, 1);
  EXPECT_EQ(tangentialTerm(p_r, {disk}, 0.18, 0.25, unit(0.78), 1).side, -1);
}

// Two disks whose detection zones overlap are one obstacle: the term follows the level line of
// their summed barrier (perpendicular to u_c, so nothing against the barrier), at full strength;
// a disk whose zone overlaps no other keeps its own tangent, exactly as before.
TEST(Tangential, APairIsPassedAsOneObstacle) {
  const std::vector<Disk> pair = {Disk{{2.5, 0.45}, 0.15}, Disk{{2.5, -0.45}, 0.15}};
  const double radius = 0.48, delta = 0.25;  // body-safe R + r; the 0.6 m gap is closed (< 0.96 m)
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> x(1.7, 2.6), y(-0.3, 0.3), heading(-1.0, 1.0);
  int active = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector2d p_r(x(rng), y(rng));
    if (clearance(p_r, radius, pair) <= 0.0) continue;
    const Eigen::Vector2d e_hat = unit(heading(rng));  // the target beyond the pair
    const TangentialResult r = tangentialTerm(p_r, pair, radius, delta, e_hat, 0);
    const Eigen::Vector2d u_c = repulsiveTerm(p_r, pair, radius, delta, e_hat).u_c;
    if (r.side == 0) {
      EXPECT_EQ(r.u_t, Eigen::Vector2d::Zero());
      EXPECT_GE(e_hat.dot(u_c), 0.0);  // released only where the barrier does not oppose tracking
      continue;
    }
    ++active;
    EXPECT_TRUE(r.full_strength);
    EXPECT_NEAR(r.u_t.norm(), 1.0, 1e-12);
    EXPECT_NEAR(r.u_t.dot(u_c), 0.0, 1e-9 * u_c.norm());  // along the level line
    EXPECT_LT(e_hat.dot(u_c), 0.0);                        // only under conflict
    EXPECT_GE(r.u_t.dot(e_hat), -1e-12);                   // the side that turns toward the target
  }
  EXPECT_GT(active, 300);
  // Zones apart: each disk is on its own, the single-disk term exactly.
  const std::vector<Disk> apart = {Disk{{2.5, 0.45}, 0.15}, Disk{{6.0, -0.45}, 0.15}};
  const Eigen::Vector2d p_r(2.0, 0.1);
  const TangentialResult both = tangentialTerm(p_r, apart, radius, delta, {1.0, 0.0}, 0);
  EXPECT_FALSE(both.full_strength);
  EXPECT_EQ(both.u_t, tangentialTerm(p_r, {apart[0]}, radius, delta, {1.0, 0.0}, 0).u_t);
}

TEST(MovingObstacles, StaticObstaclesGiveExactlyThePaperTerm) {
  const std::vector<Disk> disks = {{{0.5, 0.2}, 0.2}, {{-0.3, 0.6}, 0.1}};
  for (double x = -1.0; x <= 1.0; x += 0.05) {
    const Eigen::Vector2d p(x, 0.0);
    const AvoidanceResult a = repulsiveTerm(p, disks, 0.2, 0.25, {1.0, 0.0});
    const AvoidanceResult b = movingRepulsiveTerm(p, disks, 0.2, 0.25, 1.0, {1.0, 0.0});
    EXPECT_EQ(a.u_c, b.u_c);
    EXPECT_EQ(a.detected, b.detected);
  }
}

TEST(MovingObstacles, ApproachWidensTheBandAndAddsTheApproachSpeed) {
  Disk incoming{{1.0, 0.0}, 0.2, {-0.5, 0.0}};  // coming at 0.5 m/s toward p_r at the origin
  const Eigen::Vector2d p_r(0.0, 0.0);
  // 0.4 m beyond contact: outside delta = 0.25, inside delta + 0.5 * 1 s.
  const AvoidanceResult moving = movingRepulsiveTerm(p_r, {incoming}, 0.4, 0.25, 1.0, {1.0, 0.0});
  EXPECT_EQ(moving.detected, 1);
  EXPECT_LT(moving.u_c.x(), -0.5);  // at least the approach speed, away from the obstacle
  EXPECT_EQ(repulsiveTerm(p_r, {incoming}, 0.4, 0.25, {1.0, 0.0}).detected, 0);
  // Receding: nothing beyond the static term.
  incoming.velocity = {0.5, 0.0};
  EXPECT_EQ(movingRepulsiveTerm(p_r, {incoming}, 0.4, 0.25, 1.0, {1.0, 0.0}).detected, 0);
}

TEST(Prediction, ExactForAConstantVelocityTarget) {
  ControllerConfig config;
  config.predict_target = true;
  PerformanceController controller(config);
  const Eigen::Vector2d v(0.25, -0.1), p0(1.0, 2.0);
  const double delay = 0.2;
  ControllerOutput out;
  for (int k = 0; k <= 400; ++k) {  // 20 Hz control; 10 Hz samples, each 200 ms old
    const double t = 0.05 * k;
    const double stamp = std::floor((t - delay) / 0.1 + 1e-9) * 0.1;
    out = controller.step(t, Pose2{0.0, 0.0, 0.0}, {stamp, p0 + v * stamp}, {});
  }
  const Eigen::Vector2d truth = p0 + v * out.t;
  EXPECT_LT((out.p_d - truth).norm(), 1e-6);
  EXPECT_LT((out.v_hat - v).norm(), 1e-6);
}

TEST(Prediction, PoseAgeIsCompensatedWithTheLastCommand) {
  ControllerConfig config;
  config.compensate_pose_age = true;
  PerformanceController controller(config);
  const TargetSample target{0.0, {3.0, 0.0}};
  const ControllerOutput first = controller.stepStamped(0.0, PoseSample{0.0, {0.0, 0.0, 0.0}}, target, {});
  ASSERT_GT(first.u.v, 0.0);
  // Same pose measurement, now 0.3 s old: the controller moves it along the last command.
  const ControllerOutput second = controller.stepStamped(0.3, PoseSample{0.0, {0.0, 0.0, 0.0}}, target, {});
  const Pose2 expected = integrateUnicycle({0.0, 0.0, 0.0}, first.u, 0.3);
  EXPECT_NEAR(second.p_r.x(), expected.x + 0.3 * std::cos(expected.theta), 1e-12);
  EXPECT_NEAR(second.p_r.y(), expected.y + 0.3 * std::sin(expected.theta), 1e-12);
}

TEST(Tangential, SymmetricSaddleNoLongerStalls) {
  const SaddleRun paper = runSaddle(false);
  const SaddleRun escape = runSaddle(true);
  std::printf("saddle: paper peak |e| %.3f m, stall %.2f s; tangential peak %.3f m, stall %.2f s\n",
              paper.peak_error, paper.longest_stall, escape.peak_error, escape.longest_stall);
  EXPECT_GT(paper.longest_stall, 0.5);  // the paper's law does stall here
  EXPECT_LE(escape.longest_stall, 0.5);
  EXPECT_LE(escape.peak_error, 0.5 * paper.peak_error);
  EXPECT_GT(escape.min_clearance, 0.0);
  EXPECT_LT(escape.final_error, 0.1);
}

TEST(Tangential, IdenticalResultsWhereNothingConflicts) {
  ClosedLoopSetup setup;
  setup.initial_pose = {2.0, -0.5, M_PI / 2};
  setup.duration = 20.0;
  setup.control_period = 0.01;
  setup.obstacles = {{{0.0, 0.0}, 0.3}};  // inside the circle, never near the path
  const CircleReference circle({0.0, 0.0}, 2.0, 60.0);
  std::vector<ControllerOutput> a, b;
  runClosedLoop(setup, circle, [&](const ClosedLoopStep& s) { a.push_back(s.output); });
  setup.controller.paper.tangential_avoidance = true;
  setup.controller.moving_obstacles = true;  // static obstacle: identical too
  runClosedLoop(setup, circle, [&](const ClosedLoopStep& s) { b.push_back(s.output); });
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) {
    ASSERT_EQ(a[k].u.v, b[k].u.v);
    ASSERT_EQ(a[k].u.omega, b[k].u.omega);
  }
}

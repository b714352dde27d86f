// Extensions beyond the paper in the offline simulator: the robot pose sensor, pose-age replay, the escape cap,
// the stall metric, and closed-loop runs of the shipped scenarios asserting the
// targets (saddle, clearance, moving obstacles, delayed measurements).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/sim/metrics.h"
#include "amigobot_tracking/core/robot/offset_point.h"
#include "amigobot_tracking/sim/target_sensor.h"
#include "amigobot_tracking/core/robot/unicycle.h"
#include "amigobot_tracking/sim/monte_carlo.h"
#include "amigobot_tracking/sim/scenario.h"
#include "amigobot_tracking/sim/simulator.h"

using namespace amigobot_tracking;

namespace {

const char* const kShipped[] = {"paper_5_1", "paper_5_2_rose", "experiment_5_3", "saddle_line", "crossing_obstacles"};

// On the paper's unicycle (robot.dynamics ideal): these are claims about the paper law's
// extensions. On the AmigoBot's ramps (the files' default) the saddle escape stalls 0.68 s and
// ends 1.18 m behind, and over the ring, pair_cluster and experiment variants its worst
// stall exceeds the paper law's (1.65 s against 0.65 s in one): the ramp-aware safety work has to answer those.
sim::Scenario shipped(const std::string& name) {
  sim::Scenario s = sim::loadScenario(std::string(AMIGOBOT_SOURCE_DIR) + "/config/scenarios/" + name + ".yaml");
  s.setup.dynamics.ideal = true;
  return s;
}

sim::RunMetrics run(const sim::Scenario& s) { return sim::runScenario(s, false).summary.metrics; }

sim::RunMetrics withTangential(sim::Scenario s, bool on) {
  s.setup.controller.paper.tangential_avoidance = on;
  return run(s);
}

// "No loss of clearance": as close or farther, or no contact at all.
void expectNoLoss(double on, std::uint64_t on_contacts, double off, const std::string& what) {
  EXPECT_TRUE(on >= off || on_contacts == 0) << what << ": min clearance " << on << " m with the escape, " << off
                                             << " m without, " << on_contacts << " contacts";
}

}  // namespace

TEST(PoseSensor, DeliversPeriodicSamplesLateAndExactlyOnTheArc) {
  sim::PoseSensor sensor({0.1, 0.2});  // 10 Hz, 200 ms late
  const core::Twist2 u{0.3, 0.5};
  core::Pose2 pose{1.0, 2.0, 0.3};
  const core::Pose2 start = pose;
  for (int k = 0; k <= 20; ++k) {  // 20 Hz steps
    const double t = 0.05 * k;
    sensor.record(t, pose);
    const core::PoseSample s = sensor.at(t);
    const double expected_stamp = std::max(0.0, std::floor((t - 0.2) / 0.1 + 1e-9) * 0.1);
    EXPECT_NEAR(s.stamp, expected_stamp, 1e-12) << t;
    const core::Pose2 truth = core::integrateUnicycle(start, u, s.stamp);
    EXPECT_NEAR(s.pose.x, truth.x, 1e-9) << t;
    EXPECT_NEAR(s.pose.y, truth.y, 1e-9) << t;
    EXPECT_NEAR(s.pose.theta, truth.theta, 1e-9) << t;
    sensor.hold(u);
    pose = core::integrateUnicycle(pose, u, 0.05);
  }
  EXPECT_NEAR(sensor.nextDelivery(1.0), 1.1, 1e-9);  // 0.9 taken, delivered at 1.1
  EXPECT_FALSE(sim::PoseSensorConfig{}.active());
  EXPECT_NE(sim::PoseSensorConfig({-0.1, 0.0}).validate().find("pose_sample_period"), std::string::npos);
  EXPECT_NE(sim::PoseSensorConfig({0.0, -0.1}).validate().find("pose_delay"), std::string::npos);
}

// The pose is 200 ms old and the commands change every step: replaying them is exact.
TEST(PoseAgeCompensation, ReplaysEveryCommandSinceTheStamp) {
  core::ControllerConfig config;
  config.compensate_pose_age = true;
  core::PerformanceController controller(config);
  sim::PoseSensor sensor({0.0, 0.2});
  core::Pose2 pose{0.0, 0.0, 0.4};
  double worst = 0.0;
  for (int k = 0; k <= 60; ++k) {
    const double t = 0.05 * k;
    sensor.record(t, pose);
    const core::TargetSample target{t, {2.0 * std::cos(0.3 * t), 1.0 + 2.0 * std::sin(0.3 * t)}};
    const core::ControllerOutput out = controller.stepStamped(t, sensor.at(t), target, {});
    ASSERT_TRUE(out.valid);
    if (t >= 0.2) worst = std::max(worst, (out.p_r - core::offsetPoint(pose, config.offset)).norm());
    sensor.hold(out.u);
    pose = core::integrateUnicycle(pose, out.u, 0.05);
  }
  EXPECT_LT(worst, 1e-9);
}

// Near contact u_c grows like 1/margin; the escape stays bounded by the attraction it redirects.
TEST(TangentialCap, EscapeNeverExceedsTheAttraction) {
  core::ControllerConfig config;
  config.paper.tangential_avoidance = true;
  for (double margin : {0.2, 0.05, 0.005}) {
    core::PerformanceController controller(config);
    const core::Disk disk{{2.0, 0.0}, 0.3};
    // p_r on the line to the disk's centre, `margin` from contact, slightly off-axis target behind it.
    const double px = 2.0 - (0.3 + config.effectiveRadius() + margin) - config.offset;
    const core::ControllerOutput out =
        controller.step(0.0, {px, 0.0, 0.0}, core::TargetSample{0.0, {px + 0.9, 0.05}}, {disk});
    ASSERT_TRUE(out.valid);
    const Eigen::Vector2d attraction = out.u_r - config.k_o * (out.u_c + out.u_t);
    EXPECT_GT(out.u_t.norm(), 0.0) << margin;
    EXPECT_LE(config.k_o * out.u_t.norm(), config.paper.k_t * attraction.norm() + 1e-12) << margin;
    EXPECT_NEAR(out.u_t.dot(out.u_c), 0.0, 1e-9 * out.u_c.norm()) << margin;  // still purely tangential
  }
}

TEST(StallMetric, NetHeadwayNotCommandedSpeed) {
  auto longest = [](auto position, double error) {
    sim::MetricsAccumulator acc;
    for (int k = 0; k <= 300; ++k) {  // 3 s at 100 Hz
      sim::MetricSample m;
      m.t = 0.01 * k;
      m.h = k < 300 ? 0.01 : 0.0;
      m.p_r = position(m.t);
      m.e_true = {error, 0.0};
      acc.add(m);
    }
    return acc.result().longest_stall;
  };
  const auto standing = [](double) { return Eigen::Vector2d(1.0, 1.0); };
  const auto chattering = [](double t) { return Eigen::Vector2d(1.0, 0.02 * std::sin(40.0 * t)); };
  const auto moving = [](double t) { return Eigen::Vector2d(0.1 * t, 0.0); };
  EXPECT_NEAR(longest(standing, 1.0), 3.0, 1e-9);     // the whole run
  EXPECT_NEAR(longest(chattering, 1.0), 3.0, 1e-9);   // moving to and fro in place is standing
  EXPECT_EQ(longest(moving, 1.0), 0.0);               // 0.1 m/s of headway
  EXPECT_EQ(longest(standing, 0.1), 0.0);             // standing at the target is not a stall
}

// Targets on the symmetric saddle: the paper's law stalls, the escape does not.
TEST(SaddleScenario, EscapeMeetsTheIssueTargets) {
  const sim::Scenario s = shipped("saddle_line");
  ASSERT_FALSE(s.setup.controller.paper.tangential_avoidance) << "the file ships the paper's law";
  const sim::RunMetrics paper = withTangential(s, false);
  const sim::RunMetrics escape = withTangential(s, true);
  EXPECT_GT(paper.longest_stall, 0.5);  // the case is the deadlock it is meant to be
  EXPECT_LE(escape.longest_stall, 0.5);
  EXPECT_LE(escape.max_true_error, 0.5 * paper.max_true_error);
  EXPECT_EQ(escape.side_flips, 0u);
  EXPECT_GT(escape.escape_steps, 0u);
  EXPECT_EQ(escape.offset_collisions + escape.body_collisions, 0u);
  EXPECT_LT(escape.final_error, 0.2);  // caught up again
}

// The same with SLAM-like measurements (1 cm noise at 10 Hz), which free the paper's law after a while.
TEST(SaddleScenario, EscapeMeetsTheTargetsWithNoisySamples) {
  sim::Scenario s = shipped("saddle_line");
  s.setup.sample_period = 0.1;
  s.setup.sensor.noise_std = 0.01;
  s.setup.sensor.seed = 3;
  const sim::RunMetrics paper = withTangential(s, false);
  const sim::RunMetrics escape = withTangential(s, true);
  EXPECT_GT(paper.longest_stall, 0.5);
  EXPECT_LE(escape.longest_stall, 0.5);
  EXPECT_LE(escape.max_true_error, 0.5 * paper.max_true_error);
  EXPECT_EQ(escape.side_flips, 0u);
  EXPECT_EQ(escape.offset_collisions + escape.body_collisions, 0u);
}

// The clearance the law guarantees (offset point, R) on every shipped scenario as shipped,
// and the body's with the body-safe radius. (With the paper's radius on 5.1 and 5.2 the body
// touches with and without the escape: docs/beyond_paper.md.)
TEST(ShippedScenarios, EscapeLosesNoClearance) {
  for (const char* name : kShipped) {
    sim::Scenario s = shipped(name);
    const sim::RunMetrics off = withTangential(s, false), on = withTangential(s, true);
    expectNoLoss(on.min_clearance_offset, on.offset_collisions, off.min_clearance_offset, std::string(name) + " offset");
    EXPECT_EQ(on.diamond_violations + on.nan_count, 0u) << name;
    s.setup.controller.body_safe = true;
    const sim::RunMetrics safe_off = withTangential(s, false), safe_on = withTangential(s, true);
    expectNoLoss(safe_on.min_clearance_body, safe_on.body_collisions, safe_off.min_clearance_body,
                 std::string(name) + " body (body_safe)");
    expectNoLoss(safe_on.min_clearance_offset, safe_on.offset_collisions, safe_off.min_clearance_offset,
                 std::string(name) + " offset (body_safe)");
  }
}

TEST(ShippedScenarios, EscapeChangesNothingWithoutConflict) {
  for (const char* name : kShipped) {
    sim::Scenario s = shipped(name);
    for (core::Disk& d : s.setup.obstacles) d.center += Eigen::Vector2d(100.0, 100.0);  // never near
    const sim::RunMetrics off = withTangential(s, false), on = withTangential(s, true);
    EXPECT_EQ(on.escape_steps, 0u) << name;
    EXPECT_EQ(on.ase, off.ase) << name;
    EXPECT_EQ(on.tec, off.tec) << name;
    EXPECT_EQ(on.final_error, off.final_error) << name;
  }
}

// Moving obstacles: a fixed-seed Monte Carlo of people crossing at up to the robot's speed.
TEST(MovingObstacles, FewerCollisionsWhenTheVelocityIsUsed) {
  sim::MonteCarloOptions options;
  options.seed = 1;
  options.obstacle_speed = 0.3;  // v_bar of the scenario
  for (const bool body_safe : {false, true}) {
    sim::Scenario base = shipped("crossing_obstacles");
    base.setup.controller.body_safe = body_safe;
    int runs_hit[2] = {0, 0}, offset_hit[2] = {0, 0};
    for (int i = 0; i < 30; ++i) {
      sim::Scenario s = sim::randomVariant(base, options, static_cast<std::uint64_t>(i));
      for (const bool moving : {false, true}) {
        s.setup.controller.moving_obstacles = moving;
        const sim::RunMetrics m = run(s);
        runs_hit[moving] += m.body_collisions > 0;
        offset_hit[moving] += m.offset_collisions > 0;
      }
    }
    if (!body_safe) {
      EXPECT_LT(runs_hit[1], runs_hit[0]) << "paper radius";
    }
    EXPECT_LE(runs_hit[1], runs_hit[0]) << "body_safe " << body_safe;
    EXPECT_LE(offset_hit[1], offset_hit[0]) << "body_safe " << body_safe;
    EXPECT_EQ(offset_hit[1], 0) << "body_safe " << body_safe;
  }
}

TEST(MonteCarlo, CrossingObstaclesKeepTheirEncounterPointAndStayWithinTheSpeed) {
  const sim::Scenario base = shipped("crossing_obstacles");
  sim::MonteCarloOptions options;
  options.obstacle_speed = 0.3;
  const auto reference = base.makeReference();
  for (std::uint64_t i = 0; i < 10; ++i) {
    const sim::Scenario s = sim::randomVariant(base, options, i);
    for (size_t j = 0; j < s.setup.obstacles.size(); ++j) {
      Eigen::Vector2d v_base, v_drawn;
      ASSERT_TRUE(sim::isConstantMotion(base.setup.obstacle_motions[j], &v_base));
      ASSERT_TRUE(sim::isConstantMotion(s.setup.obstacle_motions[j], &v_drawn));
      const double t_meet = sim::encounterTime(base.setup.obstacles[j], v_base, *reference, base.setup.duration);
      const Eigen::Vector2d nominal = base.setup.obstacles[j].center + v_base * t_meet;
      const Eigen::Vector2d drawn = s.setup.obstacles[j].center + v_drawn * t_meet;
      EXPECT_LE((drawn - nominal).norm(), options.obstacle_shift + 1e-9);
      EXPECT_TRUE(s.setup.obstacle_motions[j].positionAt(t_meet).isApprox(drawn, 1e-9));
      EXPECT_LE(v_drawn.norm(), options.obstacle_speed + 1e-12);
      EXPECT_NEAR(std::abs(v_drawn.normalized().dot(v_base.normalized())), 1.0, 1e-9);
    }
  }
  // The nominal crossings meet the target where the file says: x / 0.15 s.
  Eigen::Vector2d v0;
  ASSERT_TRUE(sim::isConstantMotion(base.setup.obstacle_motions[0], &v0));
  EXPECT_NEAR(sim::encounterTime(base.setup.obstacles[0], v0, *reference, 59.0), 2.0 / 0.15, 0.02);
}

// Delayed and slow measurements: target and robot pose both 10 Hz and equally late.
TEST(DelayedMeasurements, CompensationKeepsTheTrueErrorNearTheUndelayedOne) {
  auto trueAse = [](double delay, bool compensate) {
    sim::Scenario s = shipped("experiment_5_3");
    s.setup.sensor.delay = delay;
    s.setup.pose_sensor = {0.1, delay};
    s.setup.controller.predict_target = s.setup.controller.compensate_pose_age = compensate;
    return run(s).true_ase;
  };
  const double fresh = trueAse(0.0, true);
  for (double delay : {0.1, 0.3}) {
    const double raw = trueAse(delay, false), compensated = trueAse(delay, true);
    EXPECT_LT(compensated, raw) << delay;
    EXPECT_LT(compensated, 1.25 * fresh) << delay;
  }
  EXPECT_LT(trueAse(0.3, true), 0.5 * trueAse(0.3, false));
}

// Groups of disks (a ring of small disks, a closed pair, a cluster, a wall, the experiment's square
// of nine): over randomised variants the escape tracks at least as well as the paper's law on
// average, its worst stall is shorter, and the body never touches (body-safe radius).
TEST(GroupsOfDisks, EscapeBeatsThePaperLawOverVariants) {
  sim::MonteCarloOptions options;
  options.runs = 12;
  options.seed = 1;
  for (const char* name : {"ring", "pair_cluster", "experiment_5_3"}) {
    sim::Scenario s = shipped(name);
    s.setup.controller.body_safe = true;
    s.setup.controller.paper.tangential_avoidance = false;
    const sim::MonteCarloSummary paper = sim::summarizeMonteCarlo(s, options);
    s.setup.controller.paper.tangential_avoidance = true;
    const sim::MonteCarloSummary escape = sim::summarizeMonteCarlo(s, options);
    EXPECT_LE(escape.mean_true_ase, paper.mean_true_ase) << name;
    EXPECT_LT(escape.worst_stall, paper.worst_stall) << name;
    EXPECT_EQ(escape.runs_with_body_collision, 0) << name;
    EXPECT_EQ(escape.runs_with_diamond_violation + escape.runs_with_nan, 0) << name;
  }
}

// RecordedRun: scoring a recorded run from its messages (ground truth, states, commands,
// virtual obstacles) with the offline simulator's metrics.
#include <gtest/gtest.h>

#include <cmath>

#include "amigobot_tracking/ros/recorded_run.h"

#include "amigobot_tracking/core/law/controller_config.h"

using namespace amigobot_tracking;

namespace {

TrackingState state(double t, bool enabled, double e, double rho, double v = 0.2, double w = 0.0) {
  TrackingState s;
  s.header.stamp = ros::Time(100.0 + t);
  s.enabled = enabled;
  s.valid = enabled;
  s.e.x = e;
  s.e_norm = e;
  s.rho = rho;
  s.v = v;
  s.omega = w;
  s.p_d.x = 0.1 * t;  // target moving at 0.1 m/s along x
  return s;
}

core::Disk disk(double x, double y, double r) {
  core::Disk d;
  d.center = {x, y};
  d.radius = r;
  return d;
}

// 4 s at 20 Hz driving along x at 0.1 m/s from (0, 0); `error` the tracking error.
void drive(ros_layer::RecordedRun* run, double error, double rho) {
  for (int k = 0; k <= 80; ++k) {
    const double t = 0.05 * k;
    run->addTruth(100.0 + t, core::Pose2{0.1 * t, 0.0, 0.0});
    run->addCommand(0.2, 0.0);
    run->addState(state(t, true, error, rho));
  }
  run->finish();
}

}  // namespace

TEST(RecordedRun, ScoresACleanRunLikeTheSimulator) {
  ros_layer::RecordedRunConfig config;
  config.world.obstacles = {disk(0.0, 3.0, 0.2)};
  ros_layer::RecordedRun run(config);
  run.addTruth(99.0, core::Pose2{0, 0, 0});
  run.addState(state(-1.0, false, 5.0, 1.0));  // disabled: not scored
  drive(&run, 0.05, 0.1);
  const auto s = run.summary();
  EXPECT_EQ(s.metrics.steps, 81u);
  EXPECT_NEAR(s.metrics.sim_time, 4.0, 1e-6);
  EXPECT_NEAR(s.metrics.aae, 0.05, 1e-9);
  EXPECT_NEAR(s.metrics.max_e_over_rho, 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(s.within_rho_fraction, 1.0);
  EXPECT_NEAR(s.path_length, 0.4, 1e-9);
  EXPECT_NEAR(s.min_clearance_world, 3.0 - 0.2 - config.robot_radius, 1e-9);
  EXPECT_EQ(s.metrics.body_collisions, 0u);
  EXPECT_EQ(s.command_violations, 0u);
  EXPECT_TRUE(s.ran());
  EXPECT_FALSE(s.collided());
  ASSERT_EQ(run.rows().size(), 81u);
  EXPECT_NEAR(run.rows()[40][12], 0.1, 1e-9);  // v_d_x: the target's velocity by finite difference
}

TEST(RecordedRun, WallsAndPolygonsCountInTheTrueClearances) {
  // The robot drives along y = 0 from x = 0 to 0.4: a wall along y = 0.5 leaves its body
  // (R = 0.18) 0.32 m; a table whose corner the path enters is a collision.
  ros_layer::RecordedRunConfig config;
  config.world.walls = {{{-1.0, 0.5}, {2.0, 0.5}}};
  {
    ros_layer::RecordedRun run(config);
    drive(&run, 0.05, 0.1);
    EXPECT_NEAR(run.summary().min_clearance_world, 0.5 - config.robot_radius, 1e-9);
    EXPECT_FALSE(run.summary().collided());
  }
  config.world.polygons = {{{{0.35, -0.1}, {1.0, -0.1}, {1.0, 0.1}, {0.35, 0.1}}}};
  ros_layer::RecordedRun run(config);
  drive(&run, 0.05, 0.1);
  // At x = 0.4 the centre is 0.05 m deep inside the table: clearance -(0.05 + R).
  EXPECT_NEAR(run.summary().min_clearance_world, -0.05 - config.robot_radius, 1e-9);
  EXPECT_TRUE(run.summary().collided());
}

TEST(RecordedRun, FillsEveryCsvColumnFromTruthAndState) {
  // The robot drives along y = 1 at 0.1 m/s (heading 0), its true offset point 0.3 m ahead;
  // the state carries a tangential term and a passing side.
  ros_layer::RecordedRun run(ros_layer::RecordedRunConfig{});
  for (int k = 0; k <= 40; ++k) {
    const double t = 0.05 * k;
    run.addTruth(100.0 + t, core::Pose2{0.1 * t, 1.0, 0.0});
    TrackingState s = state(t, true, 0.02, 0.5);
    s.p_d.y = 1.0;
    s.u_t.x = 0.04;
    s.u_t.y = -0.03;
    s.passing_side = -1;
    run.addState(s);
  }
  run.finish();
  ASSERT_EQ(run.rows().size(), 41u);
  ASSERT_EQ(sim::kCsvColumns.size(), 36u);
  const sim::CsvRow& row = run.rows()[20];  // t = 1 s
  auto column = [&](const std::string& name) {
    for (std::size_t i = 0; i < sim::kCsvColumns.size(); ++i) {
      if (name == sim::kCsvColumns[i]) return row[i];
    }
    ADD_FAILURE() << "no column " << name;
    return 0.0;
  };
  EXPECT_NEAR(column("t"), 1.0, 1e-9);
  EXPECT_NEAR(column("x"), 0.1, 1e-9);
  EXPECT_NEAR(column("p_r_true_x"), 0.1 + 0.3, 1e-9);
  EXPECT_NEAR(column("p_r_true_y"), 1.0, 1e-9);
  EXPECT_DOUBLE_EQ(column("u_t_x"), 0.04);
  EXPECT_DOUBLE_EQ(column("u_t_y"), -0.03);
  EXPECT_DOUBLE_EQ(column("passing_side"), -1.0);
  EXPECT_NEAR(column("h"), 0.05, 1e-9);
  EXPECT_NEAR(column("v_d_x"), 0.1, 1e-9);
  EXPECT_NEAR(column("meas_x"), 0.1, 1e-9);
  // The true error: the target (0.1 t, 1) against the true offset point 0.3 m ahead of the robot.
  const auto m = run.summary().metrics;
  EXPECT_NEAR(m.true_aae, 0.3, 1e-9);
  EXPECT_NEAR(m.true_iae, 0.3 * 2.0, 1e-9);
  EXPECT_NEAR(m.iae, 0.02 * 2.0, 1e-9);
  EXPECT_EQ(m.escape_steps, 41u);
}

// 40 s at 20 Hz along x: the target leads the true offset point by 0.05 m, except from 15 to
// 27 s when it is 0.8 m ahead; a virtual disk beside the path (in the detection band of the
// effective disk, clear of the body) is present from 15 to 25 s.
static ros_layer::RecordedRunSummary obstacleRun(const ros_layer::RecordedRunConfig& config) {
  ros_layer::RecordedRun run(config);
  bool placed = false, removed = false;
  for (int k = 0; k <= 800; ++k) {
    const double t = 0.05 * k;
    if (t >= 15.0 - 1e-9 && !placed) {
      run.addVirtualObstacles({disk(2.3, 0.6, 0.1)});
      placed = true;
    }
    if (t >= 25.0 - 1e-9 && !removed) {
      run.addVirtualObstacles({});
      removed = true;
    }
    run.addTruth(100.0 + t, core::Pose2{0.1 * t, 0.0, 0.0});
    TrackingState s = state(t, true, 0.05, 0.5);
    s.p_d.x = 0.1 * t + 0.3 + (t >= 15.0 - 1e-9 && t < 27.0 - 1e-9 ? 0.8 : 0.05);
    if (k == 700) {  // a stale input at t = 35 s: zero command, no output, p_d left at 0 by the node
      s.valid = false;
      s.p_d.x = 0.0;
    }
    run.addState(s);
  }
  run.finish();
  EXPECT_FALSE(run.summary().collided());
  return run.summary();
}

TEST(RecordedRun, JudgesTrackingOnTheTrueErrorAroundAnObstacle) {
  ros_layer::RecordedRunConfig config;
  config.verdict.recovery_time = 5.0;
  config.law = "escape";
  const auto summary = obstacleRun(config);
  const sim::TrackingVerdict& v = summary.tracking;
  EXPECT_TRUE(v.tracked) << v.reason;
  ASSERT_EQ(v.episodes.size(), 1u);
  EXPECT_NEAR(v.episodes[0].start, 15.0, 1e-6);
  EXPECT_NEAR(v.episodes[0].end, 25.0, 1e-6);
  EXPECT_NEAR(v.episodes[0].peak_error, 0.8, 1e-9);
  EXPECT_NEAR(v.episodes[0].recovered_after, 2.0, 1e-6);
  EXPECT_NEAR(v.max_judged_error, 0.05, 1e-9);
  const nlohmann::json j = nlohmann::json::parse(ros_layer::recordedRunJson(summary, config, {}, "verdict"));
  EXPECT_EQ(j["law"], "escape");
  EXPECT_EQ(j["scenario"]["variant"], "escape");
  EXPECT_EQ(j["tracking"]["tracked"], true);
  EXPECT_DOUBLE_EQ(j["tracking"]["bound"].get<double>(), 0.15);
  EXPECT_EQ(j["tracking"]["episodes"].size(), 1u);
  EXPECT_TRUE(j.contains("ise") && j.contains("iae") && j.contains("true_iae"));

  // Judged 1 s after the obstacle, the robot is still 0.8 m behind.
  config.verdict.recovery_time = 1.0;
  const sim::TrackingVerdict early = obstacleRun(config).tracking;
  EXPECT_FALSE(early.tracked);
  EXPECT_NEAR(early.max_judged_error, 0.8, 1e-9);
}

TEST(RecordedRun, CountsContactWithAVirtualObstacleFromTheGroundTruth) {
  ros_layer::RecordedRun run(ros_layer::RecordedRunConfig{});
  run.addVirtualObstacles({disk(0.3, 0.0, 0.1)});  // on the path
  drive(&run, 0.05, 0.1);
  const auto s = run.summary();
  EXPECT_EQ(s.metrics.body_collisions, 1u);
  EXPECT_LT(s.min_clearance_virtual, 0.0);
  EXPECT_TRUE(s.collided());
  EXPECT_EQ(s.virtual_obstacles, 1u);
  EXPECT_EQ(run.allObstacles().size(), 1u);
}

TEST(RecordedRun, FlagsCommandsOutsideTheDiamond) {
  ros_layer::RecordedRun run(ros_layer::RecordedRunConfig{});
  run.addCommand(0.3, 0.0);   // on the edge: inside
  run.addCommand(0.2, 0.5);   // 0.667 + 0.625 > 1
  const auto s = run.summary();
  EXPECT_EQ(s.commands, 2u);
  EXPECT_EQ(s.command_violations, 1u);
  EXPECT_NEAR(s.max_command_norm, 0.2 / 0.3 + 0.5 / 0.8, 1e-12);
}

TEST(RecordedRun, ANeverEnabledRunDidNotRun) {
  ros_layer::RecordedRun run(ros_layer::RecordedRunConfig{});
  run.addTruth(0.0, core::Pose2{});
  for (int k = 0; k < 50; ++k) run.addState(state(0.05 * k, false, 0.0, 1.0));
  run.finish();
  EXPECT_FALSE(run.summary().ran());
  EXPECT_EQ(run.summary().states, 50u);
}

TEST(RecordedRun, ValidateNamesTheBadField) {
  ros_layer::RecordedRunConfig c;
  EXPECT_EQ(c.validate(), "");
  c.v_max = 0.0;
  EXPECT_NE(c.validate().find("v_max"), std::string::npos);
  c = ros_layer::RecordedRunConfig{};
  c.world.obstacles = {disk(0, 0, -1)};
  EXPECT_NE(c.validate().find("world: obstacles[0].radius"), std::string::npos) << c.validate();
  c = ros_layer::RecordedRunConfig{};
  c.world.walls = {{{1.0, 1.0}, {1.0, 1.0}}};
  EXPECT_NE(c.validate().find("world: walls[0]: degenerate"), std::string::npos) << c.validate();
}

// make demo scores the law the node ran with: every value of the controller's `law` (the
// shipped default is "recommended") and "escape" must be accepted, anything else named.
TEST(RecordedRun, AcceptsEveryLawTheControllerRuns) {
  ros_layer::RecordedRunConfig c;
  for (const std::string& law : core::controlLawNames()) {
    c.law = law;
    EXPECT_EQ(c.validate(), "") << law;
  }
  c.law = "escape";
  EXPECT_EQ(c.validate(), "");
  c.law = "recommend";
  const std::string error = c.validate();
  // The list is the registry's robot laws and its aliases.
  EXPECT_NE(error.find("law must be one of recommended, paper, fixed_rho, escape, got 'recommend'"), std::string::npos)
      << error;
}

TEST(RecordedRun, JsonEscapesTheRunNameAndKeepsTheSharedKeys) {
  ros_layer::RecordedRunConfig config;
  config.world.obstacles = {disk(0.0, 3.0, 0.2)};
  ros_layer::RecordedRun run(config);
  drive(&run, 0.05, 0.5);
  const std::string name = "demo \"quoted\" C:\\runs\\1";
  const std::string text = ros_layer::recordedRunJson(run.summary(), config, run.allObstacles(), name);
  const nlohmann::json j = nlohmann::json::parse(text);  // throws on invalid JSON
  EXPECT_EQ(j["scenario"]["name"], name);
  EXPECT_EQ(j["safe"], true);
  EXPECT_EQ(j["ran"], true);
  EXPECT_EQ(j["steps"], run.summary().metrics.steps);
  EXPECT_TRUE(j["min_clearance_virtual"].is_null()) << "no virtual obstacle: an infinite clearance is null";
  EXPECT_DOUBLE_EQ(j["scenario"]["obstacles"][0]["center"][1].get<double>(), 3.0);
  EXPECT_TRUE(j["scenario"]["walls"].empty());
  config.world.walls = {{{0.0, -1.0}, {4.0, -1.0}}};
  const nlohmann::json room = nlohmann::json::parse(ros_layer::recordedRunJson(run.summary(), config, {}, name));
  EXPECT_DOUBLE_EQ(room["scenario"]["walls"][0][1][0].get<double>(), 4.0) << "the plots draw the walls";
}

TEST(RecordedRun, APersonOfTheWorldIsJudgedWhereItIsOnTheEmulatorClock) {
  // The robot drives along y = 0 from x = 0 to 0.4 (truth at ROS 100..104 s). A person
  // (r 0.25) walks down x = 0.2 across the path, at y = 0 at emulator time 52 s: with the
  // emulator's clock 50 s behind ROS time (t = stamp - 50) it is there while the body is
  // (a contact); with the clock 40 s behind it crossed 8 s earlier and is 1.6 m south.
  ros_layer::RecordedRunConfig config;
  world::Person person;
  person.radius = 0.25;
  person.motion.start = {0.2, 5.2};
  person.motion.start_time = 50.0 - 24.0;
  person.motion.legs = {{40.0, {0.0, -0.2}}};  // y = 0 at 52 s, on to y = -2.8 m at 66 s
  config.world.people = {person};
  for (const double behind : {50.0, 40.0}) {
    ros_layer::RecordedRun run(config);
    for (int k = 0; k <= 80; ++k) {
      const double t = 0.05 * k;
      run.addTruth(100.0 + t, core::Pose2{0.1 * t, 0.0, 0.0}, 100.0 + t - behind);
      run.addCommand(0.2, 0.0);
      run.addState(state(t, true, 0.05, 0.1));
    }
    run.finish();
    const auto s = run.summary();
    if (behind == 50.0) {
      EXPECT_TRUE(s.collided()) << "the person crossed the robot's body";
      EXPECT_LT(s.min_clearance_people, 0.0);
      EXPECT_DOUBLE_EQ(s.min_clearance_world, s.min_clearance_people) << "a person is part of the world";
    } else {
      EXPECT_FALSE(s.collided());
      EXPECT_NEAR(s.min_clearance_people, std::hypot(0.2, 1.6) - 0.43, 1e-9) << "at the first sample (60 s)";
    }
  }
}

// Scenario files: the minimal scenario is accepted as is; every bad input is refused with a
// message naming the file and the key, before anything runs.
#include <gtest/gtest.h>

#include <string>

#include "amigobot_tracking/sim/scenario.h"

using namespace amigobot_tracking;

namespace {

// The minimal scenario (README), verbatim.
const std::string kMinimum = R"(
robot:      {radius: 0.2, offset: 0.3, v_max: 5.0, w_max: 5.0, initial_pose: [2.0, -0.5, 1.5708]}
controller: {k_d: 3, k_o: 1, k_r: 0.5, lambda: 5, rho_inf: 0.1, rho_0: 1.84, delta: 0.016,
             a1: 1, a2: 1, lambda_o: 30, rho_o: 0.01, rho_o0: 1.0, body_safe: false}
reference:  {type: rose, amplitude: 3.0, k: 3, period_scale: 1.0}
obstacles:  [{center: [1.5, 0.0], radius: 0.15}]
simulation: {duration: 6.283}
)";

std::string replaced(const std::string& text, const std::string& from, const std::string& to) {
  std::string out = text;
  const size_t at = out.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: '" << from << "' not in the scenario";
  if (at != std::string::npos) out.replace(at, from.size(), to);
  return out;
}

// Parsing must fail with a message that names the file and contains `key`.
void expectRefused(const std::string& text, const std::string& key) {
  try {
    sim::parseScenario(text, "bad.yaml");
    ADD_FAILURE() << "accepted a scenario with a bad " << key;
  } catch (const sim::ScenarioError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("bad.yaml", 0), 0u) << "message does not start with the file: " << msg;
    EXPECT_NE(msg.find(key), std::string::npos) << "message does not name '" << key << "': " << msg;
  }
}

}  // namespace

TEST(SimScenario, AcceptsTheIssueMinimumExactly) {
  const sim::Scenario s = sim::parseScenario(kMinimum, "min.yaml");
  EXPECT_EQ(s.reference.type, "rose");
  EXPECT_DOUBLE_EQ(s.setup.controller.v_max, 5.0);
  EXPECT_DOUBLE_EQ(s.setup.controller.rho_0, 1.84);
  EXPECT_DOUBLE_EQ(s.setup.controller.estimator.lambda_o, 30.0);
  EXPECT_FALSE(s.setup.controller.body_safe);
  ASSERT_EQ(s.setup.obstacles.size(), 1u);
  EXPECT_DOUBLE_EQ(s.setup.obstacles[0].radius, 0.15);
  EXPECT_DOUBLE_EQ(s.setup.duration, 6.283);
  EXPECT_DOUBLE_EQ(s.setup.initial_pose.theta, 1.5708);
  EXPECT_EQ(s.setup.law, "paper");
  EXPECT_EQ(s.name, "min");
}

TEST(SimScenario, AcceptsCircleAndSplineReferences) {
  const auto circle = sim::parseScenario(
      replaced(kMinimum, "{type: rose, amplitude: 3.0, k: 3, period_scale: 1.0}", "{type: circle, center: [0, 0], radius: 2, period: 20}"),
      "c.yaml");
  EXPECT_EQ(circle.reference.type, "circle");
  EXPECT_NEAR(circle.makeReference()->at(0.0).position.x(), 2.0, 1e-12);
  const auto spline = sim::parseScenario(
      replaced(kMinimum, "{type: rose, amplitude: 3.0, k: 3, period_scale: 1.0}",
               "{type: spline, waypoints: [[3, 0], [2, 1], [0, 2]], duration: 60}"),
      "s.yaml");
  ASSERT_EQ(spline.reference.waypoints.size(), 3u);
  EXPECT_NEAR(spline.makeReference()->at(60.0).position.y(), 2.0, 1e-12);
}

// Every curve of core::referenceCurves() is a scenario's too (waypoints was the publisher's only).
TEST(SimScenario, AcceptsEveryCurveOfTheReferenceList) {
  const auto walk = sim::parseScenario(replaced(kMinimum, "{type: rose, amplitude: 3.0, k: 3, period_scale: 1.0}",
                                                "{type: waypoints, waypoints: [[3, 0], [3, 2]], speed: 0.5, loop: true}"),
                                       "w.yaml");
  EXPECT_EQ(walk.reference.type, "waypoints");
  EXPECT_TRUE(walk.reference.loop);
  EXPECT_NEAR(walk.makeReference()->at(2.0).position.y(), 1.0, 1e-9);
}

// A key of another curve is not this curve's: named as unknown, not silently ignored.
TEST(SimScenario, RefusesAnotherCurvesKeyNamingIt) {
  expectRefused(replaced(kMinimum, "period_scale: 1.0", "period_scale: 1.0, radius: 2"), "reference.radius");
  expectRefused(replaced(kMinimum, "{type: rose, amplitude: 3.0, k: 3, period_scale: 1.0}",
                         "{type: circle, center: [0, 0], radius: 2, period: 20, duration: 5}"),
                "reference.duration");
  expectRefused(replaced(kMinimum, "{type: rose, amplitude: 3.0, k: 3, period_scale: 1.0}",
                         "{type: circle, center: [0, 0], period: 20}"),
                "reference.radius");
}

TEST(SimScenario, RefusesASplineStepNearZero) {
  // A step of 1e-320 m made the knot spacing underflow: std::invalid_argument escaped
  // without the file's name.
  const std::string rose = "{type: rose, amplitude: 3.0, k: 3, period_scale: 1.0}";
  expectRefused(replaced(kMinimum, rose, "{type: spline, waypoints: [[3, 0], [3, 1e-320], [0, 2]], duration: 60}"),
                "reference.waypoints[1]: within 1 mm of the previous waypoint");
  expectRefused(replaced(kMinimum, rose, "{type: spline, waypoints: [[3, 0], [3, 0.0005], [0, 2]], duration: 60}"),
                "reference.waypoints[1]");
}

TEST(SimScenario, ReadsOptionalKeys) {
  std::string text = replaced(kMinimum, "body_safe: false}", "body_safe: true, variant: proportional, estimator: kalman, k_p: 7}");
  text = replaced(text, "{duration: 6.283}", "{duration: 6.283, control_period: 0.002, max_step: 0.01, seed: 5}");
  text += "target: {sample_period: 0.1, noise_std: 0.01, delay: 0.05, jumps: [{t: 2, offset: [0.3, 0]}]}\n";
  text = replaced(text, "center: [1.5, 0.0]", "center: [1.5, 0.5]");  // p_r(0) outside the body-safe zone
  const sim::Scenario s = sim::parseScenario(text, "opt.yaml");
  EXPECT_TRUE(s.setup.controller.body_safe);
  EXPECT_EQ(s.setup.law, "proportional");
  EXPECT_EQ(s.setup.velocity_source, sim::VelocitySource::kKalman);
  EXPECT_DOUBLE_EQ(s.setup.baseline.k_p, 7.0);
  EXPECT_DOUBLE_EQ(s.setup.control_period, 0.002);
  EXPECT_DOUBLE_EQ(s.setup.max_step, 0.01);
  EXPECT_EQ(s.setup.sensor.seed, 5u);
  EXPECT_EQ(s.setup.integrator, sim::Integrator::kExplicit);  // the default
  EXPECT_DOUBLE_EQ(s.setup.sample_period, 0.1);
  EXPECT_DOUBLE_EQ(s.setup.sensor.noise_std, 0.01);
  EXPECT_DOUBLE_EQ(s.setup.sensor.delay, 0.05);
  ASSERT_EQ(s.setup.sensor.jumps.size(), 1u);
  EXPECT_DOUBLE_EQ(s.setup.sensor.jumps[0].offset.x(), 0.3);
}

TEST(SimScenario, ReadsTheIntegrator) {
  for (const auto& [name, integrator] : {std::pair<const char*, sim::Integrator>{"explicit", sim::Integrator::kExplicit},
                                         {"band_implicit", sim::Integrator::kBandImplicit},
                                         {"second_order", sim::Integrator::kSecondOrder}}) {
    const sim::Scenario s = sim::parseScenario(
        replaced(kMinimum, "{duration: 6.283}", std::string("{duration: 6.283, integrator: ") + name + "}"), "i.yaml");
    EXPECT_EQ(s.setup.integrator, integrator) << name;
    EXPECT_EQ(sim::toString(s.setup.integrator), name);
  }
}

TEST(SimScenario, RefusesAnUnknownIntegratorNamingTheKeyAndTheChoices) {
  expectRefused(replaced(kMinimum, "{duration: 6.283}", "{duration: 6.283, integrator: rk45}"), "simulation.integrator");
  expectRefused(replaced(kMinimum, "{duration: 6.283}", "{duration: 6.283, integrator: rk45}"), "band_implicit");
  expectRefused(replaced(kMinimum, "{duration: 6.283}", "{duration: 6.283, integrator: [explicit]}"),
                "simulation.integrator");
}

TEST(SimScenario, ProportionalGainDefaultsToTheLinearisedPaperGain) {
  const sim::Scenario s = sim::parseScenario(replaced(kMinimum, "body_safe: false}", "body_safe: false, variant: proportional}"), "p.yaml");
  EXPECT_DOUBLE_EQ(s.setup.baseline.k_p, 3.0 / 0.1);  // k_d / rho_inf
}

TEST(SimScenario, RefusesABaselineSettingOutOfItsBoundsNamingTheKey) {
  // The baselines' keys are rows of the scenario's table (scenario_fields.cpp): its bounds, its message.
  expectRefused(replaced(kMinimum, "body_safe: false}", "body_safe: false, k_p: -1}"), "controller.k_p");
  expectRefused(replaced(kMinimum, "body_safe: false}", "body_safe: false, lowpass_tau: 0}"), "controller.lowpass_tau");
  expectRefused(replaced(kMinimum, "body_safe: false}", "body_safe: false, kalman_accel_std: yes}"),
                "controller.kalman_accel_std");
  const sim::Scenario s = sim::parseScenario(
      replaced(kMinimum, "body_safe: false}", "body_safe: false, kalman_measurement_std: 0.5}"), "b.yaml");
  EXPECT_DOUBLE_EQ(s.setup.baseline.kalman_measurement_std, 0.5);
}

TEST(SimScenario, RefusesMissingKeys) {
  expectRefused(replaced(kMinimum, "v_max: 5.0, ", ""), "robot.v_max");
  expectRefused(replaced(kMinimum, "k_d: 3, ", ""), "controller.k_d");
  expectRefused(replaced(kMinimum, "body_safe: false", "a3: 1"), "controller.body_safe");
  expectRefused(replaced(kMinimum, "type: rose, ", ""), "reference.type");
  expectRefused(replaced(kMinimum, "amplitude: 3.0, ", ""), "reference.amplitude");
  expectRefused(replaced(kMinimum, "obstacles:  [{center: [1.5, 0.0], radius: 0.15}]\n", ""), "obstacles");
  expectRefused(replaced(kMinimum, "{duration: 6.283}", "{seed: 1}"), "simulation.duration");
  expectRefused(replaced(kMinimum, "{center: [1.5, 0.0], radius: 0.15}", "{center: [1.5, 0.0]}"), "obstacles[0].radius");
  expectRefused(replaced(kMinimum, "simulation: {duration: 6.283}\n", ""), "simulation");
}

TEST(SimScenario, RefusesWrongTypes) {
  expectRefused(replaced(kMinimum, "k_d: 3", "k_d: fast"), "controller.k_d");
  expectRefused(replaced(kMinimum, "body_safe: false", "body_safe: maybe"), "controller.body_safe");
  expectRefused(replaced(kMinimum, "initial_pose: [2.0, -0.5, 1.5708]", "initial_pose: [2.0, -0.5]"), "robot.initial_pose");
  expectRefused(replaced(kMinimum, "initial_pose: [2.0, -0.5, 1.5708]", "initial_pose: [2.0, x, 1]"), "robot.initial_pose[1]");
  expectRefused(replaced(kMinimum, "v_max: 5.0", "v_max: [5.0]"), "robot.v_max");
  expectRefused(replaced(kMinimum, "v_max: 5.0", "v_max: .nan"), "robot.v_max");
  expectRefused(replaced(kMinimum, "robot:      {", "robot: [1, 2]\nunused: {"), "robot");
  expectRefused(replaced(kMinimum, "[{center: [1.5, 0.0], radius: 0.15}]", "{center: [1.5, 0.0]}"), "obstacles");
}

TEST(SimScenario, RefusesUnknownReferenceTypeAndUnknownKeys) {
  expectRefused(replaced(kMinimum, "type: rose", "type: lemniscate"), "reference.type");
  // The rose's own time scale is period_scale, as reference_publisher names it; the old key is refused.
  expectRefused(replaced(kMinimum, "period_scale: 1.0", "time_scale: 1.0"), "reference.time_scale");
  // The reference factory's own bounds are checked at parse time, naming the key.
  expectRefused(replaced(kMinimum, "{type: rose, amplitude: 3.0, k: 3, period_scale: 1.0}",
                         "{type: circle, center: [0, 0], radius: 200, period: 20}"),
                "reference.radius");
  expectRefused(replaced(kMinimum, "k_o: 1", "k_o: 1, k_oo: 2"), "controller.k_oo");
  expectRefused(replaced(kMinimum, "simulation:", "simulaton: {duration: 1}\nsimulation:"), "simulaton");
  expectRefused(replaced(kMinimum, "body_safe: false}", "body_safe: false, variant: pid}"), "controller.variant");
  expectRefused(replaced(kMinimum, "body_safe: false}", "body_safe: false, estimator: magic}"), "controller.estimator");
}

TEST(SimScenario, RefusesRho0TooSmallForTheInitialError) {
  // p_r(0) = (2, -0.2), p_d(0) = (3, 0): |e(0)| = 1.02 m.
  expectRefused(replaced(kMinimum, "rho_0: 1.84", "rho_0: 1.0"), "controller.rho_0");
  expectRefused(replaced(kMinimum, "rho_0: 1.84", "rho_0: 0.05"), "controller.rho_0");  // <= rho_inf
}

TEST(SimScenario, RefusesOutOfRangeValues) {
  expectRefused(replaced(kMinimum, "radius: 0.15", "radius: -0.15"), "obstacles[0].radius");
  expectRefused(replaced(kMinimum, "v_max: 5.0", "v_max: 0"), "robot.v_max");
  expectRefused(replaced(kMinimum, "k_r: 0.5", "k_r: -1"), "controller.k_r");
  expectRefused(replaced(kMinimum, "lambda_o: 30", "lambda_o: 0"), "controller.lambda_o");
  expectRefused(replaced(kMinimum, "{duration: 6.283}", "{duration: -1}"), "simulation.duration");
  expectRefused(replaced(kMinimum, "{type: rose, amplitude: 3.0, k: 3, period_scale: 1.0}",
                         "{type: spline, waypoints: [[0, 0]], duration: 10}"),
                "reference.waypoints");
  expectRefused(replaced(kMinimum, "{type: rose, amplitude: 3.0, k: 3, period_scale: 1.0}",
                         "{type: spline, waypoints: [[3, 0], [3, 0]], duration: 10}"),
                "reference.waypoints[1]");
  expectRefused(kMinimum + "target: {delay: -0.1}\n", "target.delay");
}

TEST(SimScenario, RefusesBrokenYamlAndMissingFiles) {
  expectRefused("robot: {radius: 0.2\n", "not valid YAML");
  try {
    sim::loadScenario("/nonexistent/scenario.yaml");
    ADD_FAILURE() << "loaded a missing file";
  } catch (const sim::ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scenario.yaml"), std::string::npos);
  }
}

TEST(SimScenario, ShippedScenariosLoad) {
  for (const char* name : {"paper_5_1", "paper_5_2_rose", "experiment_5_3", "saddle_line", "crossing_obstacles", "ring",
                           "pair_cluster"}) {
    const std::string path = std::string(AMIGOBOT_SOURCE_DIR) + "/config/scenarios/" + name + ".yaml";
    EXPECT_NO_THROW(sim::loadScenario(path)) << path;
  }
}

// A start inside a disk's R + r zone is refused naming the pose, the obstacle and the depth
// (ring.yaml's old start [2.0, -0.6] was 5.9 cm inside: rho went 1 -> 24 -> 74 m in two steps).
TEST(SimScenario, StartInsideAnObstacleZoneIsRefused) {
  std::string ring = R"(
robot:      {radius: 0.18, offset: 0.3, v_max: 1.0, w_max: 2.0, initial_pose: [2.0, -0.6, 1.5708]}
controller: {k_d: 0.15, k_o: 1, k_r: 0.5, lambda: 0.5, rho_inf: 0.1, rho_0: 1.0, delta: 0.25,
             a1: 1, a2: 1, lambda_o: 30, rho_o: 0.01, rho_o0: 1.0, body_safe: true}
reference:  {type: circle, center: [0.0, 0.0], radius: 2.0, period: 29.92}
obstacles:  [{center: [1.848, 0.765], radius: 0.08}, {center: [1.709, -0.708], radius: 0.08}]
simulation: {duration: 1.0}
)";
  expectRefused(ring, "robot.initial_pose");
  try {
    sim::parseScenario(ring, "bad.yaml");
  } catch (const sim::ScenarioError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("obstacles[1]"), std::string::npos) << msg;
    EXPECT_NE(msg.find("0.0588"), std::string::npos) << msg;  // 0.56 - 0.5011 m
  }
  EXPECT_NO_THROW(sim::parseScenario(replaced(ring, "[2.0, -0.6, 1.5708]", "[2.2, -0.45, 1.5708]"), "ok.yaml"));
}

// The switches beyond the paper, the robot pose's timing, moving obstacles.
TEST(SimScenario, BeyondThePaperSwitchesDefaultToThePaper) {
  const sim::Scenario s = sim::parseScenario(kMinimum, "min.yaml");
  const core::ControllerConfig defaults;
  EXPECT_FALSE(s.setup.controller.paper.tangential_avoidance);
  EXPECT_FALSE(s.setup.controller.moving_obstacles);
  EXPECT_FALSE(s.setup.controller.predict_target);
  EXPECT_FALSE(s.setup.controller.compensate_pose_age);
  EXPECT_EQ(s.setup.controller.paper.k_t, defaults.paper.k_t);
  EXPECT_EQ(s.setup.controller.paper.tangential_hysteresis, defaults.paper.tangential_hysteresis);
  EXPECT_FALSE(s.setup.pose_sensor.active());
  EXPECT_TRUE(s.setup.obstacle_motions.empty());
}

TEST(SimScenario, ReadsBeyondThePaperKeys) {
  std::string text = replaced(kMinimum, "body_safe: false}",
                              "body_safe: false, tangential_avoidance: true, k_t: 2.5, tangential_hysteresis: 0.4,\n"
                              "             moving_obstacles: true, obstacle_horizon: 1.5, predict_target: true,\n"
                              "             compensate_pose_age: true, max_prediction: 0.8}");
  text = replaced(text, "{center: [1.5, 0.0], radius: 0.15}", "{center: [1.5, 0.0], radius: 0.15, velocity: [0.1, -0.2]}");
  text += "localization: {sample_period: 0.1, delay: 0.2}\n";
  const sim::Scenario s = sim::parseScenario(text, "beyond.yaml");
  const core::ControllerConfig& c = s.setup.controller;
  EXPECT_TRUE(c.paper.tangential_avoidance);
  EXPECT_DOUBLE_EQ(c.paper.k_t, 2.5);
  EXPECT_DOUBLE_EQ(c.paper.tangential_hysteresis, 0.4);
  EXPECT_TRUE(c.moving_obstacles);
  EXPECT_DOUBLE_EQ(c.paper.obstacle_horizon, 1.5);
  EXPECT_TRUE(c.predict_target);
  EXPECT_TRUE(c.compensate_pose_age);
  EXPECT_DOUBLE_EQ(c.max_prediction, 0.8);
  EXPECT_DOUBLE_EQ(s.setup.pose_sensor.sample_period, 0.1);
  EXPECT_DOUBLE_EQ(s.setup.pose_sensor.delay, 0.2);
  ASSERT_EQ(s.setup.obstacle_motions.size(), 1u);
  EXPECT_EQ(s.setup.obstacle_motions[0].velocityAt(3.0), Eigen::Vector2d(0.1, -0.2));
  EXPECT_TRUE(s.setup.obstacle_motions[0].positionAt(2.0).isApprox(Eigen::Vector2d(1.7, -0.4)));
}

TEST(SimScenario, RefusesBadBeyondThePaperKeys) {
  const auto with = [](const std::string& keys) { return replaced(kMinimum, "body_safe: false}", "body_safe: false, " + keys + "}"); };
  expectRefused(with("tangential_avoidance: maybe"), "controller.tangential_avoidance");
  expectRefused(with("moving_obstacles: 1.5"), "controller.moving_obstacles");
  expectRefused(with("predict_target: [true]"), "controller.predict_target");
  expectRefused(with("compensate_pose_age: yes please"), "controller.compensate_pose_age");
  expectRefused(with("k_t: fast"), "controller.k_t");
  expectRefused(with("k_t: -1"), "controller.k_t");
  expectRefused(with("tangential_hysteresis: 1.0"), "controller.tangential_hysteresis");
  expectRefused(with("obstacle_horizon: -0.5"), "controller.obstacle_horizon");
  expectRefused(with("max_prediction: [0.5]"), "controller.max_prediction");
  expectRefused(with("tangential: true"), "controller.tangential");  // misspelt switch
  expectRefused(kMinimum + "localization: {delay: -0.1}\n", "localization.delay");
  expectRefused(kMinimum + "localization: {sample_period: soon}\n", "localization.sample_period");
  expectRefused(kMinimum + "localization: {dleay: 0.1}\n", "localization.dleay");
  expectRefused(kMinimum + "localization: 0.1\n", "localization");
  expectRefused(replaced(kMinimum, "radius: 0.15}", "radius: 0.15, velocity: [0.3]}"), "obstacles[0].velocity");
  expectRefused(replaced(kMinimum, "radius: 0.15}", "radius: 0.15, velocity: fast}"), "obstacles[0].velocity");
}

// amigobot_sim --set section.key=value: applied to the file's tree and checked like the file.
TEST(SimScenario, OverridesAreCheckedLikeTheFile) {
  const sim::Scenario s = sim::parseScenario(kMinimum, "min.yaml", {"controller.k_d=2", "target.delay=0.1",
                                                                   "controller.tangential_avoidance=true"});
  EXPECT_EQ(s.setup.controller.k_d, 2.0);
  EXPECT_EQ(s.setup.sensor.delay, 0.1);
  EXPECT_TRUE(s.setup.controller.paper.tangential_avoidance);
  const auto refused = [](const std::string& assignment, const std::string& key) {
    try {
      sim::parseScenario(kMinimum, "bad.yaml", {assignment});
      ADD_FAILURE() << "accepted --set " << assignment;
    } catch (const sim::ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  refused("controller.k_d=-1", "controller.k_d: must be a finite number > 0");
  refused("controller.k_dd=1", "controller.k_dd: unknown key");
  refused("controller.body_safe=maybe", "controller.body_safe");
  refused("simulation.duration", "expected section.key=value");
  refused("reference.amplitude=0", "reference.amplitude");
}

// An obstacle that walks, stops and turns (motion: legs); the closed loop moves it along them
// and hands the laws its velocity of the moment.
TEST(SimScenario, ObstaclesWalkTheirLegsInTheClosedLoop) {
  const std::string text = replaced(kMinimum, "{center: [1.5, 0.0], radius: 0.15}",
                                    "{center: [1.5, 0.0], radius: 0.15, motion: {start_time: 1.0, legs: [\n"
                                    "  {duration: 2.0, velocity: [0.5, 0.0]}, {duration: 1.0, velocity: [0.0, 0.0]},\n"
                                    "  {duration: 1.0, velocity: [0.0, -0.4]}]}}");
  sim::Scenario s = sim::parseScenario(text, "walk.yaml");
  ASSERT_EQ(s.setup.obstacle_motions.size(), 1u);
  const core::ObstacleMotion& m = s.setup.obstacle_motions[0];
  EXPECT_DOUBLE_EQ(m.start_time, 1.0);
  EXPECT_FALSE(m.repeat);
  ASSERT_EQ(m.legs.size(), 3u);
  s.setup.duration = 6.0;
  s.setup.control_period = 0.01;
  const auto reference = s.makeReference();
  int checked = 0;
  sim::runClosedLoop(s.setup, *reference, [&](const sim::ClosedLoopStep& step) {
    const core::Disk& d = step.obstacles->at(0);
    const double t = step.t;
    // Stands, walks 1 m along x, stands 1 s, walks 0.4 m down, stands.
    const Eigen::Vector2d expected = t < 1.0   ? Eigen::Vector2d(1.5, 0.0)
                                     : t < 3.0 ? Eigen::Vector2d(1.5 + 0.5 * (t - 1.0), 0.0)
                                     : t < 4.0 ? Eigen::Vector2d(2.5, 0.0)
                                     : t < 5.0 ? Eigen::Vector2d(2.5, -0.4 * (t - 4.0))
                                               : Eigen::Vector2d(2.5, -0.4);
    EXPECT_LT((d.center - expected).norm(), 1e-9) << "t = " << t;
    const Eigen::Vector2d velocity = t > 1.5 && t < 2.5   ? Eigen::Vector2d(0.5, 0.0)
                                     : t > 4.5 && t < 4.9 ? Eigen::Vector2d(0.0, -0.4)
                                                          : d.velocity;  // (near a leg's change: not checked)
    EXPECT_EQ(d.velocity, velocity) << "t = " << t;
    if (t > 3.2 && t < 3.8) {
      EXPECT_TRUE(d.velocity.isZero()) << "t = " << t;
    }
    ++checked;
  });
  EXPECT_GT(checked, 500);
}

TEST(SimScenario, RefusesBadMotions) {
  const auto with = [](const std::string& obstacle) {
    return replaced(kMinimum, "{center: [1.5, 0.0], radius: 0.15}", obstacle);
  };
  expectRefused(with("{center: [1.5, 0.0], radius: 0.15, velocity: [0.1, 0.0], motion: {legs: "
                     "[{duration: 1.0, velocity: [0.1, 0.0]}]}}"),
                "obstacles[0].motion");
  expectRefused(with("{center: [1.5, 0.0], radius: 0.15, motion: {legs: []}}"), "obstacles[0].motion.legs");
  expectRefused(with("{center: [1.5, 0.0], radius: 0.15, motion: {legs: [{duration: 0.0, velocity: [1, 0]}]}}"),
                "obstacles[0].motion.legs[0].duration");
  expectRefused(with("{center: [1.5, 0.0], radius: 0.15, motion: {legs: [{duration: 1.0, velocity: [1]}]}}"),
                "obstacles[0].motion.legs[0].velocity");
  expectRefused(with("{center: [1.5, 0.0], radius: 0.15, motion: {repeat: true, legs: "
                     "[{duration: 1.0, velocity: [1, 0]}]}}"),
                "obstacles[0].motion.repeat");
  expectRefused(with("{center: [1.5, 0.0], radius: 0.15, motion: {legs: [{duration: 1.0, velocity: [1, 0]}], "
                     "pace: 2}}"),
                "obstacles[0].motion.pace");
}

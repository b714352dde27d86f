// Google Benchmark figures for the core (`make bench`). Printed, never asserted.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "amigobot_tracking/sim/closed_loop.h"
#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/core/law/estimator.h"
#include "amigobot_tracking/core/law/yield_rollout.h"
#include "amigobot_tracking/core/perception/scan_obstacles.h"
#include "amigobot_tracking/core/supervision/tracking_loop.h"
#include "amigobot_tracking/core/robot/unicycle.h"

using namespace amigobot_tracking::core;
using namespace amigobot_tracking::sim;

namespace {

std::vector<Disk> obstaclesAround(int count) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> pos(-3.0, 3.0), radius(0.05, 0.3);
  std::vector<Disk> disks;
  for (int i = 0; i < count; ++i) disks.push_back({{pos(rng), pos(rng)}, radius(rng)});
  return disks;
}

// One controller step (estimator update, avoidance over N disks, law, saturation, rho) at
// 1 kHz along the rose curve, the robot moving with the command.
void BM_ControllerStep(benchmark::State& state) {
  ControllerConfig config;
  config.v_max = config.w_max = 15.0;
  PerformanceController controller(config);
  const std::vector<Disk> obstacles = obstaclesAround(static_cast<int>(state.range(0)));
  const RoseReference rose(3.0, 3.0, 1.0);
  Pose2 pose{2.0, -0.5, M_PI / 2};
  double t = 0.0;
  for (auto _ : state) {
    const ControllerOutput out = controller.step(t, pose, {t, rose.at(t).position}, obstacles);
    benchmark::DoNotOptimize(out);
    pose = integrateUnicycle(pose, out.u, 1e-3);
    t += 1e-3;
  }
}
BENCHMARK(BM_ControllerStep)->Arg(0)->Arg(10)->Arg(100);

// The recommended law's look-ahead when it searches (yield_rollout.h): a person 2 m behind at
// 0.8 m/s on the robot's line, a wall of N static disks beside; every call judges the held
// command, a stop and every manoeuvre on the actuator model. The worst case of a control step
// among people (20 Hz gives 50 ms).
void BM_YieldSearch(benchmark::State& state) {
  YieldInput in;
  in.pose = {0.0, 0.0, 0.0};
  in.previous = in.filtered = {0.3, 0.0};
  in.target = {1.3, 0.0};
  in.horizon = 5.0;
  in.enough = 0.15;
  std::vector<Disk> disks = {{{-2.0, 0.05}, 0.25, {0.8, 0.0}}};
  for (int i = 0; i < state.range(0); ++i) disks.push_back({{-1.0 + 0.3 * i, -0.9}, 0.2});
  const DiamondSet diamond(0.3, 0.8);
  for (auto _ : state) {
    const YieldResult r = yieldToMovingDisks(in, diamond, disks);
    if (!r.acted) state.SkipWithError("the search did not run");
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_YieldSearch)->Arg(0)->Arg(20)->Unit(benchmark::kMillisecond);

// One whole control cycle of the tracking nodelet without ROS (what TrackingNode::controlCycle
// runs between its tf lookups and its publishes): a new 720-beam scan of a 6 x 4 m room ->
// disks, 3 virtual disks, the target's disk dropped, supervisor, controller step, ramp; at
// 20 Hz, the robot and target circling. Target: <= 0.5 ms per cycle (with the ROS around it).
void BM_LoopStep(benchmark::State& state) {
  TrackingLoopConfig config;
  config.target_exclusion_radius = 0.3;
  TrackingLoop loop(config);
  loop.enable();
  ScanGeometry geometry;
  geometry.angle_min = -M_PI;
  geometry.angle_increment = 2.0 * M_PI / 720;
  geometry.range_min = 0.05;
  geometry.range_max = 8.0;
  std::vector<float> ranges;
  for (int i = 0; i < 720; ++i) {
    const double a = geometry.angle_min + i * geometry.angle_increment, c = std::cos(a), s = std::sin(a);
    double r = std::numeric_limits<double>::infinity();
    if (std::abs(c) > 1e-9) r = std::min(r, 3.0 / std::abs(c));
    if (std::abs(s) > 1e-9) r = std::min(r, 2.0 / std::abs(s));
    ranges.push_back(static_cast<float>(r));
  }
  const std::vector<Disk> virtuals = {{{-1.0, 1.2}, 0.2}, {{0.0, 1.2}, 0.2}, {{1.0, 1.2}, 0.2}};
  const ScanObstacleConfig scan_config;
  std::vector<Disk> laser;
  double t = 0.0;
  for (auto _ : state) {
    t += 0.05;
    const Pose2 robot{0.5 * std::cos(0.1 * t), 0.5 * std::sin(0.1 * t), 0.1 * t + M_PI / 2};
    Eigen::Affine2d sensor_to_global = Eigen::Translation2d(robot.x, robot.y) * Eigen::Rotation2Dd(robot.theta);
    laser.clear();
    scanToObstacles(geometry, ranges, sensor_to_global, scan_config, &laser);
    TrackingLoopInputs in;
    in.t = t;
    in.supervisor.have_pose = in.supervisor.have_target = true;
    in.pose = {t, robot};
    in.target = {t, Eigen::Vector2d(std::cos(0.1 * t + 0.5), std::sin(0.1 * t + 0.5))};
    in.supervisor.scan_age = 0.01;
    in.scan_disks = &laser;
    in.virtual_disks = &virtuals;
    const TrackingLoopResult r = loop.step(in);
    benchmark::DoNotOptimize(r);
  }
  if (loop.supervisor().status() != "tracking") state.SkipWithError(("not tracking: " + loop.supervisor().status()).c_str());
}
BENCHMARK(BM_LoopStep)->Unit(benchmark::kMicrosecond);

void BM_EstimatorUpdate(benchmark::State& state) {
  VelocityEstimator estimator;
  const RoseReference rose(3.0, 3.0, 1.0);
  double t = 0.0;
  for (auto _ : state) {
    estimator.update(t, rose.at(t).position);
    benchmark::DoNotOptimize(estimator.velocity());
    t += 1e-2;
  }
}
BENCHMARK(BM_EstimatorUpdate);

// The Section 5.2 run (rose, 2 pi s at 1 kHz): the counter realtime_factor is simulated
// time over wall time.
void BM_ClosedLoopRose(benchmark::State& state) {
  ClosedLoopSetup setup;
  setup.controller.robot_radius = 0.2;
  setup.controller.v_max = setup.controller.w_max = 15.0;
  setup.controller.k_d = 3.0;
  setup.controller.lambda = 5.0;
  setup.controller.rho_0 = 1.84;
  setup.controller.delta = 0.016;
  setup.initial_pose = {2.0, -0.5, M_PI / 2};
  setup.duration = 2 * M_PI;
  const RoseReference rose(3.0, 3.0, 1.0);
  for (auto _ : state) benchmark::DoNotOptimize(runClosedLoop(setup, rose));
  state.counters["realtime_factor"] =
      benchmark::Counter(setup.duration * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ClosedLoopRose)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

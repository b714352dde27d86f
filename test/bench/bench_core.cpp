// Google Benchmark figures for the core (`make bench`). Printed, never asserted.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "amigobot_tracking/sim/closed_loop.h"
#include "amigobot_tracking/core/controller.h"
#include "amigobot_tracking/core/estimator.h"
#include "amigobot_tracking/core/unicycle.h"

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

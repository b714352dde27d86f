// Google Benchmark: the world layer's hot paths, printed, never asserted. Ray casting a
// TiM5xx-like scan (811 beams over 270 deg, 10 m) and the 8 sonars against the demo's room
// (config/worlds/lab.yaml: 9 wall segments, 2 polygons, 6 disks) from the robot's start, and
// one ground-truth clearance. Budget: an 811-beam scan at 15 Hz should cost < 1 % of a core
// (< 0.6 ms per scan).
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "amigobot_tracking/world/geometry.h"
#include "amigobot_tracking/world/raycast.h"

using namespace amigobot_tracking;

namespace {

const world::World& lab() {
  static const world::World room = world::loadWorld(std::string(AMIGOBOT_SOURCE_DIR) + "/config/worlds/lab.yaml");
  return room;
}

void BM_RaycastLab(benchmark::State& state) {
  const int beams = static_cast<int>(state.range(0));
  const core::ScanGeometry geometry{-0.75 * M_PI, 1.5 * M_PI / (beams - 1), 0.05, 10.0};
  const core::Pose2 sensor{-0.49, -0.3, 0.2};
  int finite = 0;
  for (auto _ : state) {
    const std::vector<float> ranges = world::raycastScan(sensor, lab(), geometry, beams);
    benchmark::DoNotOptimize(ranges.data());
    finite = 0;
    for (float r : ranges) finite += std::isfinite(r) ? 1 : 0;
  }
  state.counters["segments"] = static_cast<double>(world::surfaceSegments(lab()).size());
  state.counters["finite_beams"] = finite;
}
BENCHMARK(BM_RaycastLab)->Arg(271)->Arg(811)->Arg(1621)->Unit(benchmark::kMicrosecond);

void BM_SonarConesLab(benchmark::State& state) {
  for (auto _ : state) {
    double sum = 0.0;
    for (int i = 0; i < 8; ++i) sum += world::coneRange(lab(), {-0.5, -0.3, i * M_PI / 4}, 0.2);
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_SonarConesLab)->Unit(benchmark::kMicrosecond);

void BM_ClearanceLab(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(world::clearance(lab(), {1.0, 1.0}, 0.18));
}
BENCHMARK(BM_ClearanceLab);

}  // namespace

BENCHMARK_MAIN();

// Google Benchmark: laser scan -> bounded disks (core/perception/scan_obstacles.h). Printed, never
// asserted. Target: <= 30 us for a 720-beam scan.
#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "amigobot_tracking/core/perception/scan_obstacles.h"

using namespace amigobot_tracking::core;

namespace {

// A 360-degree scan of a 6 x 4 m room with a few pillars, 1 cm noise, and 5 % dropouts
// (NaN / +inf) to exercise the REP 117 paths.
std::vector<float> roomScan(int beams, ScanGeometry* geometry) {
  *geometry = {-M_PI, 2.0 * M_PI / beams, 0.05, 8.0};
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const Eigen::Vector2d pillars[] = {{1.0, 0.8}, {-1.5, -1.0}, {2.0, -1.2}};
  std::vector<float> ranges(beams);
  for (int i = 0; i < beams; ++i) {
    const double a = geometry->angle_min + i * geometry->angle_increment;
    const Eigen::Vector2d d(std::cos(a), std::sin(a));
    double r = std::numeric_limits<double>::infinity();
    if (std::abs(d.x()) > 1e-9) r = std::min(r, (d.x() > 0 ? 3.0 : -3.0) / d.x());
    if (std::abs(d.y()) > 1e-9) r = std::min(r, (d.y() > 0 ? 2.0 : -2.0) / d.y());
    for (const Eigen::Vector2d& c : pillars) {
      const double b = d.dot(c), disc = b * b - (c.squaredNorm() - 0.15 * 0.15);
      if (disc >= 0.0 && b - std::sqrt(disc) > 0.0) r = std::min(r, b - std::sqrt(disc));
    }
    const double u = uniform(rng);
    ranges[i] = u < 0.025 ? std::numeric_limits<float>::quiet_NaN()
                : u < 0.05 ? std::numeric_limits<float>::infinity()
                           : static_cast<float>(r + noise(rng));
  }
  return ranges;
}

// Arg 0: beams; arg 1: 1 = as the tracking node calls it, with the clusters and how they end
// (for the obstacle tracker), 0 = disks only.
void BM_ScanToObstacles(benchmark::State& state) {
  ScanGeometry geometry;
  const std::vector<float> ranges = roomScan(static_cast<int>(state.range(0)), &geometry);
  const Eigen::Affine2d pose = Eigen::Translation2d(1.0, 2.0) * Eigen::Rotation2Dd(0.3);
  const ScanObstacleConfig config;
  std::vector<Disk> disks;
  disks.reserve(ranges.size());
  std::vector<ScanCluster> clusters;
  clusters.reserve(ranges.size());
  std::vector<ScanCluster>* ends = state.range(1) ? &clusters : nullptr;
  ScanObstacleStats stats;
  for (auto _ : state) {
    scanToObstacles(geometry, ranges, pose, config, &disks, &stats, ends);
    benchmark::DoNotOptimize(disks.data());
  }
  state.counters["disks"] = static_cast<double>(stats.disks);
  state.counters["clusters"] = static_cast<double>(stats.clusters);
}
BENCHMARK(BM_ScanToObstacles)->ArgsProduct({{360, 720, 1440}, {0, 1}})->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();

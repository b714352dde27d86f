// Localisation CPU per scan on the synthetic room: the Localizer's ICP match (360 and 720
// beams; target <= 5 ms), the odometry-only update between matches, a global relocalisation,
// and an ICP-SLAM (Mapper) update. Figures are printed, never asserted.
#include <benchmark/benchmark.h>

#include <random>

#include "amigobot_tracking/localization/localizer.h"
#include "amigobot_tracking/localization/mapper.h"
#include "synthetic_room.h"

using namespace amigobot_tracking;
using namespace amigobot_tracking::localization;

namespace {

// Scans along the loop, one per 3 cm, so that every update is due (min_travel 0.05 m is
// crossed every other scan; min_travel 0 here makes each one a match).
std::vector<RangeScan> loopScans(int beams, int count, std::vector<core::Pose2>* truths) {
  std::mt19937 random(11);
  std::vector<RangeScan> scans;
  core::Pose2 truth = amigobot_test::kLoopStart;
  for (int i = 0; i < count; ++i) {
    scans.push_back(amigobot_test::scanAt(truth, beams, &random));
    truths->push_back(truth);
    truth = compose(truth, core::Pose2{0.03, 0.0, 0.03 / amigobot_test::kLoopRadius});
  }
  return scans;
}

// Args: beams, scan points used (icp/max_points; the default is 240).
void BM_LocalizationMatch(benchmark::State& state) {
  const int beams = static_cast<int>(state.range(0));
  std::vector<core::Pose2> truths;
  const std::vector<RangeScan> scans = loopScans(beams, 100, &truths);
  LocalizationConfig c;
  c.map_file = "room.yaml";
  c.min_travel = 0.0;
  c.min_rotation = 0.0;
  c.icp.max_points = static_cast<int>(state.range(1));
  c.initial_pose = amigobot_test::kLoopStart;
  Localizer localizer(c, amigobot_test::roomMap());
  // Odometry = truth, off by 2 cm and 0.6 deg at every scan so that ICP has work to do.
  const core::Pose2 odometry_error{0.02, -0.01, 0.01};
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(localizer.update(scans[i % scans.size()], compose(truths[i % truths.size()], odometry_error)));
    if (++i % scans.size() == 0) localizer.setPose(truths[0], compose(truths[0], odometry_error));
  }
  state.counters["match"] = localizer.estimate().match;
}
BENCHMARK(BM_LocalizationMatch)->Args({360, 360})->Args({720, 720})->Args({360, 240})->Args({720, 240})->Unit(benchmark::kMillisecond);

void BM_GlobalRelocalisation(benchmark::State& state) {
  std::vector<core::Pose2> truths;
  const std::vector<RangeScan> scans = loopScans(360, 1, &truths);
  LocalizationConfig c;
  c.map_file = "room.yaml";
  Localizer localizer(c, amigobot_test::roomMap());
  int candidates = 0;
  for (auto _ : state) candidates = localizer.relocalize(scans[0], core::Pose2()).candidates;
  state.counters["candidates"] = candidates;
}
BENCHMARK(BM_GlobalRelocalisation)->Unit(benchmark::kMillisecond);

void BM_MappingUpdate(benchmark::State& state) {
  const int beams = static_cast<int>(state.range(0));
  std::vector<core::Pose2> truths;
  const std::vector<RangeScan> scans = loopScans(beams, 250, &truths);
  LocalizationConfig c;
  c.mode = "mapping";
  c.initial_pose = amigobot_test::kLoopStart;
  std::unique_ptr<Mapper> mapper = std::make_unique<Mapper>(c);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(mapper->update(scans[i % scans.size()], truths[i % truths.size()]));
    if (++i % scans.size() == 0) {
      state.PauseTiming();
      mapper = std::make_unique<Mapper>(c);
      state.ResumeTiming();
    }
  }
}
BENCHMARK(BM_MappingUpdate)->Arg(360)->Arg(720)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

// The real laser chain in one process: laser_emulator's server on one thread, the driver
// and the LaserScan conversion on the benchmark's thread. Per iteration: one scan.
//   CPU time: the driver's CPU per scan (read, decode, convert), the emulator excluded;
//   latency_ms: from the emulator writing a scan to the LaserScan message being ready.
#include <benchmark/benchmark.h>

#include <atomic>
#include <thread>

#include "amigobot_tracking/ros/laser_scan.h"
#include "amigobot_tracking/sensors/laser_emulator_server.h"

using namespace amigobot_tracking;
using namespace amigobot_tracking::sensors;

namespace {

void BM_LaserChain(benchmark::State& state, const std::string& model_name) {
  const LaserModel model = laserModel(model_name);
  std::vector<core::Disk> room(8);
  for (std::size_t i = 0; i < room.size(); ++i) {
    room[i].center = {2.0 * std::cos(0.8 * i), 2.0 * std::sin(0.8 * i)};
    room[i].radius = 0.2;
  }
  // The emulator sends a scan one sweep after casting it, and casts the next one a scan
  // period after that cast: a scan that arrives within the gap belongs to the last cast.
  std::atomic<double> last_cast{0.0};
  PoseSource pose = [&](core::Pose2* base, double* t) {
    *base = core::Pose2{};
    *t = systemSeconds();
    last_cast = *t;
    return true;
  };
  const double sweep = model.timeIncrement() * (model.beams() - 1);
  LaserServerOptions options;
  options.tcp_port = 0;
  LaserEmulatorServer server(model, ScanSource(model, world::disksOnly(room), ScanSourceOptions{}), pose, options);
  server.open();
  std::atomic<bool> stop{false};
  std::thread io([&] { server.run(stop); });
  ros_layer::LaserParams params;
  params.driver.model = model_name;
  params.driver.port = "127.0.0.1:" + std::to_string(server.tcpPort());
  LaserDriver driver(params.driver);
  LaserScanData scan;
  sensor_msgs::LaserScan msg;
  while (!driver.poll(&scan, 0.5)) {
  }
  double latency = 0.0;
  for (auto _ : state) {
    while (!driver.poll(&scan, 0.5)) {
    }
    ros_layer::toLaserScan(scan, params, &msg);
    latency += systemSeconds() - (last_cast + sweep);
    benchmark::DoNotOptimize(msg.ranges.data());
  }
  state.counters["latency_ms"] = 1000.0 * latency / static_cast<double>(state.iterations());
  state.counters["beams"] = static_cast<double>(msg.ranges.size());
  stop = true;
  io.join();
}

}  // namespace

BENCHMARK_CAPTURE(BM_LaserChain, hokuyo_urg_scip_tcp, std::string("hokuyo_urg"))->Iterations(50)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LaserChain, sick_tim5xx_cola_a_tcp, std::string("sick_tim5xx"))->Iterations(50)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

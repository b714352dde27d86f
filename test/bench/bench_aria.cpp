// Google Benchmark figures of the ARIA layer: parser throughput on a SIP stream (whole
// buffers and 1-byte reads), SIP decoding and command quantisation. Printed, never asserted.
#include <benchmark/benchmark.h>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/aria/packet.h"
#include "amigobot_tracking/aria/sip.h"
#include "amigobot_tracking/aria/wheel_command.h"

using namespace amigobot_tracking::aria;

namespace {
std::vector<std::uint8_t> sipStream(int count) {
  Sip sip;
  sip.sonars = {{0, 1000}, {1, 2000}, {2, 3000}, {3, 4000}};
  std::vector<std::uint8_t> out;
  for (int i = 0; i < count; ++i) {
    sip.x = static_cast<std::uint16_t>(i);
    const auto bytes = encodeSip(sip, 12);
    out.insert(out.end(), bytes.begin(), bytes.end());
  }
  return out;
}
}  // namespace

static void BM_ParseSipStream(benchmark::State& state) {
  const auto stream = sipStream(1000);
  const std::size_t chunk = static_cast<std::size_t>(state.range(0));
  for (auto _ : state) {
    PacketParser parser;
    Packet p;
    std::size_t n = 0;
    for (std::size_t i = 0; i < stream.size(); i += chunk) {
      parser.feed(stream.data() + i, std::min(chunk, stream.size() - i));
      while (parser.next(p)) ++n;
    }
    benchmark::DoNotOptimize(n);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * stream.size()));
}
BENCHMARK(BM_ParseSipStream)->Arg(1)->Arg(64)->Arg(4096);

static void BM_DecodeSip(benchmark::State& state) {
  PacketParser parser;
  parser.feed(sipStream(1));
  Packet p;
  parser.next(p);
  for (auto _ : state) benchmark::DoNotOptimize(decodeSip(p));
}
BENCHMARK(BM_DecodeSip);

static void BM_QuantizeCommand(benchmark::State& state) {
  const RobotParams robot = RobotParams::amigo();
  const amigobot_tracking::core::DiamondSet diamond(0.3, 0.8);
  const auto mode = state.range(0) ? CommandMode::kVel2 : CommandMode::kVelRvel;
  double v = 0.0;
  for (auto _ : state) {
    v = v > 0.5 ? -0.5 : v + 0.001;
    benchmark::DoNotOptimize(quantizeCommand({v, 0.7 - v}, mode, robot, diamond));
  }
}
BENCHMARK(BM_QuantizeCommand)->Arg(0)->Arg(1);

BENCHMARK_MAIN();

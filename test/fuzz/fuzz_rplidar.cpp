// libFuzzer target: the RPLIDAR decoders on arbitrary bytes: descriptor, info, health, and
// the measurement-node stream with the driver's resynchronisation (drop a byte on a bad
// node), then the revolution binning. Invariants: no crash or UB; a decoded node has an
// angle below 360 deg and re-encodes to the same 5 bytes; every bin is a range or +inf.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "amigobot_tracking/sensors/rplidar.h"
#include "fuzz_support.h"

using namespace amigobot_tracking::sensors;
using fuzz_support::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const int bins = 1 + data[0] * 8;
  const std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (bytes.size() >= rplidar::kDescriptorSize) {
    rplidar::Descriptor d;
    rplidar::decodeDescriptor(bytes.substr(0, rplidar::kDescriptorSize), &d);
  }
  if (bytes.size() >= rplidar::kInfoSize) rplidar::decodeInfo(bytes.substr(0, rplidar::kInfoSize));
  if (bytes.size() >= rplidar::kHealthSize) rplidar::decodeHealth(bytes.substr(0, rplidar::kHealthSize));
  std::vector<rplidar::Sample> samples;
  for (std::size_t i = 0; i + rplidar::kNodeSize <= bytes.size();) {
    rplidar::Node node;
    const auto* at = reinterpret_cast<const std::uint8_t*>(bytes.data()) + i;
    if (!rplidar::decodeNode(at, &node).empty()) {
      ++i;  // resynchronise, as the driver does
      continue;
    }
    check(node.angle_q6 < 360 * 64);
    check(rplidar::encodeNode(node) == bytes.substr(i, rplidar::kNodeSize));
    const double angle = rplidar::nodeAngle(node.angle_q6);
    check(angle >= -M_PI && angle < M_PI);
    samples.push_back({angle, node.distance_q2 == 0 ? INFINITY : node.distance_q2 / 4000.0f});
    i += rplidar::kNodeSize;
  }
  for (const float range : rplidar::binRevolution(samples, bins)) check(range >= 0.0f);
  return 0;
}

#include "amigobot_tracking/aria/emulator_line.h"

#include <algorithm>

#include "amigobot_tracking/aria/packet.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr double kBitsPerByte = 10.0;  // start bit, 8 data bits, stop bit
constexpr double kMaxBacklog = 1.0;    // [s] of output the firmware buffers

}  // namespace

std::uint8_t garble(std::uint8_t byte) {
  // Rotate and invert: different bytes stay different, but no header byte survives, so
  // garbage never frames a packet.
  const auto g = static_cast<std::uint8_t>(~((byte << 3) | (byte >> 5)));
  return g == kHeader0 ? 0x00 : g;
}

std::vector<std::uint8_t> SerialLineModel::receive(const std::uint8_t* data, std::size_t size, int line_baud,
                                                   int robot_baud) {
  std::vector<std::uint8_t> out(data, data + size);
  if (line_baud != robot_baud) std::transform(out.begin(), out.end(), out.begin(), garble);
  return out;
}

void SerialLineModel::transmit(const std::vector<std::uint8_t>& bytes, int robot_baud, double now) {
  if (bytes.empty() || robot_baud <= 0) return;
  const double start = std::max(now, busy_until_);
  if (start - now > kMaxBacklog) {
    dropped_ += bytes.size();
    return;
  }
  busy_until_ = start + kBitsPerByte * static_cast<double>(bytes.size()) / robot_baud;
  queue_.push_back({busy_until_, robot_baud, bytes});
}

std::vector<std::uint8_t> SerialLineModel::due(double now, int line_baud) {
  std::vector<std::uint8_t> out;
  while (!queue_.empty() && queue_.front().done <= now) {
    const Chunk& chunk = queue_.front();
    for (std::uint8_t b : chunk.bytes) out.push_back(chunk.baud == line_baud ? b : garble(b));
    queue_.pop_front();
  }
  sent_ += out.size();
  return out;
}

}  // namespace aria
}  // namespace amigobot_tracking

// The robot's UART behind a pseudo-terminal. A pty moves bytes instantly whatever speed its
// termios say, so the emulator models the line: the robot's bytes leave at its own baud (10
// bits a byte) and bytes whose two ends disagree on the baud arrive as garbage, as framing
// errors on a real UART do. The garbage is deterministic and never holds a packet header.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

namespace amigobot_tracking {
namespace aria {

// (The speed the pty's termios hold, which both its ends share: link::lineBaud.)

// One byte as a UART at another baud decodes it.
std::uint8_t garble(std::uint8_t byte);

class SerialLineModel {
 public:
  // What the robot's UART at `robot_baud` makes of bytes the host sent at `line_baud`.
  static std::vector<std::uint8_t> receive(const std::uint8_t* data, std::size_t size, int line_baud,
                                           int robot_baud);
  // Queues bytes the robot sends at `robot_baud` at wall time `now` [s]. When more than a
  // second of output already waits they are dropped, as the firmware's buffer would.
  void transmit(const std::vector<std::uint8_t>& bytes, int robot_baud, double now);
  // The queued bytes fully sent by `now`, garbled where `line_baud` differs from the
  // robot's baud at the time they were sent.
  std::vector<std::uint8_t> due(double now, int line_baud);

  std::uint64_t bytesSent() const { return sent_; }
  std::uint64_t bytesDropped() const { return dropped_; }

 private:
  struct Chunk {
    double done;  // [s] wall time its last bit has left
    int baud;
    std::vector<std::uint8_t> bytes;
  };
  std::deque<Chunk> queue_;
  double busy_until_ = 0.0;
  std::uint64_t sent_ = 0, dropped_ = 0;
};

}  // namespace aria
}  // namespace amigobot_tracking

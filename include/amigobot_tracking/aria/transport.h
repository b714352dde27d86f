// Byte links to the robot: link::SerialPort for a device path, link::TcpClient for
// "host:port" (a robot simulator or a serial-to-TCP bridge); which is which follows the one
// address rule (link/address.h). Errors are thrown as std::runtime_error naming the port.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace amigobot_tracking {
namespace aria {

class Transport {
 public:
  virtual ~Transport() = default;
  virtual void open() = 0;
  virtual void close() = 0;
  virtual bool isOpen() = 0;
  // Waits up to timeout_ms for data and returns what is available (0 on timeout). Throws
  // when the link is gone (socket closed by the peer, device unplugged).
  virtual std::size_t read(std::uint8_t* buffer, std::size_t size, int timeout_ms) = 0;
  // Writes everything or throws.
  virtual void write(const std::vector<std::uint8_t>& bytes) = 0;
  virtual bool isSerial() const = 0;
  // Serial: changes the line speed of the open port (throws naming the port and baud if the
  // device refuses it). TCP has no baud: a no-op.
  virtual void setBaud(int baud) = 0;
  // The line speed now [baud]; 0 on TCP.
  virtual int baud() const = 0;
  virtual std::string describe() const = 0;
};

// Throws std::invalid_argument naming the text for a malformed address (link::parseTcpAddress)
// or a non-positive baud rate.
std::unique_ptr<Transport> makeTransport(const std::string& port, int baud);

}  // namespace aria
}  // namespace amigobot_tracking

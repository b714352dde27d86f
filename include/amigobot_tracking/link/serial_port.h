// The one serial opener: a tty (USB-serial adapter, UART, or an emulator's pseudo-terminal)
// in raw mode, 8N1, no flow control, at any line speed (the standard Bxxx rates, and others
// such as the RPLIDAR A3's 256000 through the kernel's termios2). Non-blocking underneath;
// read() waits with poll(). Every error names the device (and the baud where it matters).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace amigobot_tracking {
namespace link {

class SerialPort {
 public:
  SerialPort() = default;
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  // Opens `device` raw at `baud` and discards what was waiting; throws std::runtime_error.
  void open(const std::string& device, int baud);
  void close();
  bool isOpen() const { return fd_ >= 0; }
  // Changes the speed of the open port and discards the input (bytes heard at the old speed
  // are garbage at the new one); throws naming the device and the baud.
  void setBaud(int baud);
  int baud() const { return baud_; }
  // Waits up to timeout_ms for data; returns what arrived (0 on timeout). Throws when the
  // device is gone (unplugged, pty closed).
  std::size_t read(void* buffer, std::size_t size, int timeout_ms);
  // Writes everything within timeout_ms or throws.
  void write(const void* data, std::size_t size, int timeout_ms = 1000);
  void discardInput();
  int fd() const { return fd_; }
  const std::string& device() const { return device_; }

 private:
  std::runtime_error failure(const std::string& what) const;
  int fd_ = -1;
  int baud_ = 0;
  std::string device_;
};

// Sets the tty `fd` raw, 8N1, no flow control, reads not waiting (VMIN = VTIME = 0), at
// `baud` when > 0 (else its speed stays); false with errno set when the tty refuses.
bool setRawMode(int fd, int baud);

// The output speed a tty is set to [baud]; 0 when it is not a tty or not a standard rate.
// (An emulator reads it off its pty's slave to see at what speed its client talks.)
int lineBaud(int fd);

}  // namespace link
}  // namespace amigobot_tracking

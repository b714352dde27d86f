// A Linux joystick device (/dev/input/jsN, the struct js_event API of linux/joystick.h) read
// without blocking. Anything that delivers js_event bytes works (a FIFO or pty in the tests).
// Every problem is one sentence naming the device: "device /dev/input/js0: No such device".
#pragma once

#include <string>

namespace amigobot_tracking {
namespace teleop {

class JoystickDevice {
 public:
  explicit JoystickDevice(std::string path);
  ~JoystickDevice();
  JoystickDevice(const JoystickDevice&) = delete;
  JoystickDevice& operator=(const JoystickDevice&) = delete;

  // "" when open, else "device PATH: reason".
  std::string open();
  void close();
  bool isOpen() const { return fd_ >= 0; }
  const std::string& path() const { return path_; }
  // "NAME, N axes, M buttons" from the driver's ioctls; "" when the device is no joystick
  // (a FIFO stand-in).
  std::string describe() const;

  // Waits at most timeout_ms for bytes and appends what is there to *bytes. "" while the
  // device is fine; on end of file or an error the device is closed and the reason returned
  // ("device PATH: closed (end of file)", "device PATH: No such device").
  std::string read(int timeout_ms, std::string* bytes);

 private:
  std::string problem(const std::string& reason) const { return "device " + path_ + ": " + reason; }

  std::string path_;
  int fd_ = -1;
};

}  // namespace teleop
}  // namespace amigobot_tracking

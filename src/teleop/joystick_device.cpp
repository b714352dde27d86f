#include "amigobot_tracking/teleop/joystick_device.h"

#include <fcntl.h>
#include <linux/joystick.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstring>
#include <utility>

#include "amigobot_tracking/teleop/joystick.h"

namespace amigobot_tracking {
namespace teleop {

// decodeEvents() reads the kernel's layout; it must be this one.
static_assert(sizeof(js_event) == JoystickEvent::kSize, "struct js_event is 8 bytes");
static_assert(offsetof(js_event, value) == 4 && offsetof(js_event, type) == 6 && offsetof(js_event, number) == 7,
              "struct js_event layout");
static_assert(JS_EVENT_BUTTON == JoystickEvent::kButton && JS_EVENT_AXIS == JoystickEvent::kAxis &&
                  JS_EVENT_INIT == JoystickEvent::kInit,
              "js_event type flags");

JoystickDevice::JoystickDevice(std::string path) : path_(std::move(path)) {}

JoystickDevice::~JoystickDevice() { close(); }

std::string JoystickDevice::open() {
  close();
  fd_ = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  return fd_ < 0 ? problem(std::strerror(errno)) : "";
}

void JoystickDevice::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

std::string JoystickDevice::describe() const {
  char name[128] = {0};
  unsigned char axes = 0, buttons = 0;
  if (fd_ < 0 || ::ioctl(fd_, JSIOCGNAME(sizeof(name) - 1), name) < 0) return "";
  ::ioctl(fd_, JSIOCGAXES, &axes);
  ::ioctl(fd_, JSIOCGBUTTONS, &buttons);
  return std::string(name) + ", " + std::to_string(axes) + " axes, " + std::to_string(buttons) + " buttons";
}

std::string JoystickDevice::read(int timeout_ms, std::string* bytes) {
  if (fd_ < 0) return problem("not open");
  pollfd p{fd_, POLLIN, 0};
  if (::poll(&p, 1, timeout_ms) <= 0) return "";  // nothing yet (or a signal)
  char buffer[JoystickEvent::kSize * 32];
  const ssize_t n = ::read(fd_, buffer, sizeof(buffer));
  if (n > 0) {
    bytes->append(buffer, static_cast<std::size_t>(n));
    return "";
  }
  if (n < 0 && (errno == EAGAIN || errno == EINTR)) return "";
  const std::string reason = n == 0 ? "closed (end of file)" : std::strerror(errno);
  close();
  return problem(reason);
}

}  // namespace teleop
}  // namespace amigobot_tracking

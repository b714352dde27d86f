#include "amigobot_tracking/link/serial_port.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace amigobot_tracking {
namespace link {
namespace {

const std::pair<speed_t, int> kStandardSpeeds[] = {
    {B1200, 1200},     {B2400, 2400},     {B4800, 4800},     {B9600, 9600},       {B19200, 19200},
    {B38400, 38400},   {B57600, 57600},   {B115200, 115200}, {B230400, 230400},   {B460800, 460800},
    {B500000, 500000}, {B921600, 921600}, {B1000000, 1000000}};

// A rate without a Bxxx constant (256000): the kernel's termios2 with BOTHER takes any speed
// (cp210x, the RPLIDAR's adapter, accepts it). <asm/termbits.h> clashes with <termios.h>,
// hence the kernel's layout restated (asm-generic/termbits.h, NCCS 19).
struct KernelTermios2 {
  tcflag_t c_iflag, c_oflag, c_cflag, c_lflag;
  cc_t c_line;
  cc_t c_cc[19];
  speed_t c_ispeed, c_ospeed;
};
constexpr tcflag_t kKernelBother = 0010000;  // BOTHER: the speed is c_ispeed/c_ospeed

bool setCustomSpeed(int fd, int baud) {
  KernelTermios2 t{};
  if (::ioctl(fd, _IOR('T', 0x2A, KernelTermios2), &t) < 0) return false;  // TCGETS2
  t.c_cflag = (t.c_cflag & ~static_cast<tcflag_t>(CBAUD)) | kKernelBother;
  t.c_ispeed = t.c_ospeed = static_cast<speed_t>(baud);
  return ::ioctl(fd, _IOW('T', 0x2B, KernelTermios2), &t) == 0;  // TCSETS2
}

double steadyMs() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

bool setRawMode(int fd, int baud) {
  termios tio{};
  if (::tcgetattr(fd, &tio) < 0) return false;
  ::cfmakeraw(&tio);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | CRTSCTS);
  tio.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  if (baud <= 0) return ::tcsetattr(fd, TCSANOW, &tio) == 0;
  speed_t code = B0;
  for (const auto& [c, rate] : kStandardSpeeds) {
    if (rate == baud) code = c;
  }
  if (code != B0) {
    ::cfsetispeed(&tio, code);
    ::cfsetospeed(&tio, code);
    return ::tcsetattr(fd, TCSANOW, &tio) == 0;
  }
  return ::tcsetattr(fd, TCSANOW, &tio) == 0 && setCustomSpeed(fd, baud);
}

SerialPort::~SerialPort() { close(); }

std::runtime_error SerialPort::failure(const std::string& what) const {
  return std::runtime_error("serial " + device_ + " at " + std::to_string(baud_) + " baud: " + what);
}

void SerialPort::open(const std::string& device, int baud) {
  close();
  device_ = device;
  baud_ = baud;
  if (baud <= 0) throw failure("the baud rate must be positive");
  fd_ = ::open(device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) throw failure(std::string("cannot open: ") + std::strerror(errno));
  if (!::isatty(fd_)) {
    close();
    throw failure("not a serial port (no tty)");
  }
  if (!setRawMode(fd_, baud)) {
    const std::string why = std::strerror(errno);
    close();
    throw failure("cannot set raw 8N1 at this speed: " + why);
  }
  discardInput();
}

void SerialPort::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void SerialPort::setBaud(int baud) {
  if (fd_ < 0) throw failure("not open");
  if (baud <= 0 || !setRawMode(fd_, baud)) {
    throw failure("cannot switch to " + std::to_string(baud) + " baud: " + std::strerror(errno));
  }
  baud_ = baud;
  discardInput();
}

std::size_t SerialPort::read(void* buffer, std::size_t size, int timeout_ms) {
  if (fd_ < 0) throw failure("device closed (unplugged?)");
  pollfd p{fd_, POLLIN, 0};
  const int ready = ::poll(&p, 1, timeout_ms < 0 ? 0 : timeout_ms);
  if (ready < 0 && errno != EINTR) throw failure(std::string("poll: ") + std::strerror(errno));
  if (ready <= 0) return 0;
  if (!(p.revents & POLLIN) && (p.revents & (POLLHUP | POLLERR | POLLNVAL))) throw failure("device closed (unplugged?)");
  const ssize_t n = ::read(fd_, buffer, size);
  if (n < 0 && (errno == EAGAIN || errno == EINTR)) return 0;
  if (n <= 0) throw failure(n == 0 ? "device closed (unplugged?)" : std::string("read: ") + std::strerror(errno));
  return static_cast<std::size_t>(n);
}

void SerialPort::write(const void* data, std::size_t size, int timeout_ms) {
  if (fd_ < 0) throw failure("write: device closed (unplugged?)");
  const auto* bytes = static_cast<const char*>(data);
  const double end = steadyMs() + timeout_ms;
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd_, bytes + done, size - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EINTR) throw failure(std::string("write: ") + std::strerror(errno));
    const int left = static_cast<int>(end - steadyMs());
    pollfd p{fd_, POLLOUT, 0};
    if (left <= 0 || ::poll(&p, 1, left) <= 0) throw failure("write: not drained within " + std::to_string(timeout_ms) + " ms");
  }
}

void SerialPort::discardInput() {
  if (fd_ < 0) return;
  char chunk[4096];
  while (::read(fd_, chunk, sizeof(chunk)) > 0) {
  }
  ::tcflush(fd_, TCIFLUSH);
}

int lineBaud(int fd) {
  termios tio{};
  if (::tcgetattr(fd, &tio) != 0) return 0;
  const speed_t speed = ::cfgetospeed(&tio);
  for (const auto& [code, baud] : kStandardSpeeds) {
    if (code == speed) return baud;
  }
  return 0;
}

}  // namespace link
}  // namespace amigobot_tracking

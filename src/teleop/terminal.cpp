#include "amigobot_tracking/teleop/terminal.h"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace amigobot_tracking {
namespace teleop {

namespace {
// One raw terminal per process: the settings to restore live where a signal handler or an
// atexit hook can reach them.
int g_fd = -1;
termios g_saved{};
volatile bool g_raw = false;
}  // namespace

RawTerminal::RawTerminal(int fd) : fd_(fd) {
  if (!::isatty(fd)) throw std::runtime_error("standard input is not a terminal");
  termios saved{};
  if (::tcgetattr(fd, &saved) != 0) throw std::runtime_error(std::string("tcgetattr: ") + std::strerror(errno));
  termios raw = saved;
  raw.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO);  // ISIG stays: Ctrl-C is SIGINT
  raw.c_iflag &= ~static_cast<tcflag_t>(IXON | ICRNL);   // Ctrl-S / Ctrl-Q and CR are keys too
  raw.c_cc[VMIN] = 0;
  raw.c_cc[VTIME] = 0;
  g_fd = fd;
  g_saved = saved;
  static bool hooked = false;
  if (!hooked) hooked = std::atexit(&RawTerminal::restore) == 0;
  if (::tcsetattr(fd, TCSAFLUSH, &raw) != 0) throw std::runtime_error(std::string("tcsetattr: ") + std::strerror(errno));
  g_raw = true;
}

RawTerminal::~RawTerminal() { restore(); }

void RawTerminal::restore() {
  if (!g_raw) return;
  g_raw = false;
  ::tcsetattr(g_fd, TCSANOW, &g_saved);
}

bool RawTerminal::readKeys(int timeout_ms, std::string* keys) const {
  pollfd p{fd_, POLLIN, 0};
  const int ready = ::poll(&p, 1, timeout_ms);
  if (ready < 0) return errno == EINTR;  // a signal: the caller checks its flag
  if (ready == 0) return true;
  if (p.revents & (POLLHUP | POLLERR | POLLNVAL)) return false;
  char buffer[64];
  const ssize_t n = ::read(fd_, buffer, sizeof(buffer));
  if (n < 0) return errno == EINTR || errno == EAGAIN;
  if (n == 0) return false;  // VMIN 0: POLLIN without bytes means end of input
  keys->append(buffer, static_cast<size_t>(n));
  return true;
}

}  // namespace teleop
}  // namespace amigobot_tracking

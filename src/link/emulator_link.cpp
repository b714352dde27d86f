#include "amigobot_tracking/link/emulator_link.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "amigobot_tracking/link/serial_port.h"

namespace amigobot_tracking {
namespace link {
namespace {

std::atomic<bool> g_stop_requested{false};
std::atomic<int> g_stop_signal{0};
void onStopSignal(int signal) {  // lock-free atomics only: safe in a signal handler
  g_stop_signal = signal;
  g_stop_requested = true;
}

}  // namespace

bool takeLine(std::string& pending, std::string* line) {
  const std::size_t eol = pending.find('\n');
  if (eol == std::string::npos) return false;
  *line = pending.substr(0, eol);
  pending.erase(0, eol + 1);
  return true;
}

const std::atomic<bool>& stopOnSignals() {
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);
  std::signal(SIGPIPE, SIG_IGN);
  return g_stop_requested;
}

int stopSignal() { return g_stop_signal; }

TcpListener::~TcpListener() {
  if (fd_ >= 0) ::close(fd_);
}

void TcpListener::open(const std::string& bind_address, int port, int backlog) {
  if (port < 0 || port > 65535) throw std::runtime_error("listen: port " + std::to_string(port) + " is outside 0..65535");
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::inet_pton(AF_INET, bind_address.c_str(), &addr.sin_addr) != 1) {
    throw std::runtime_error("listen: bind address '" + bind_address + "' is not an IPv4 address");
  }
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);  // accept() never waits
  if (fd < 0) throw systemError("socket");
  const int one = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one));
  if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) < 0 || ::listen(fd, backlog) < 0) {
    const std::runtime_error error = systemError("cannot listen on " + bind_address + ":" + std::to_string(port));
    ::close(fd);
    throw error;
  }
  socklen_t len = sizeof(addr);
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
  if (fd_ >= 0) ::close(fd_);
  fd_ = fd;
  port_ = ntohs(addr.sin_port);
}

int TcpListener::accept() const {
  const int fd = ::accept4(fd_, nullptr, nullptr, SOCK_CLOEXEC | SOCK_NONBLOCK);
  if (fd < 0) return -1;
  const int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
  return fd;
}

PseudoTerminal::~PseudoTerminal() {
  for (int fd : {master_, slave_}) {
    if (fd >= 0) ::close(fd);
  }
  if (!link_path_.empty()) ::unlink(link_path_.c_str());
}

void PseudoTerminal::open(const std::string& link_path, int baud) {
  master_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (master_ < 0 || ::grantpt(master_) < 0 || ::unlockpt(master_) < 0) throw systemError("pty for " + link_path + ": posix_openpt");
  name_ = ::ptsname(master_);
  slave_ = ::open(name_.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (slave_ < 0) throw systemError("pty for " + link_path + ": open " + name_);
  // The held slave is not read: its termios are what matters (raw, and the start speed a
  // client finds).
  if (!setRawMode(slave_, baud)) throw systemError("pty for " + link_path + ": raw mode");
  ::unlink(link_path.c_str());
  if (::symlink(name_.c_str(), link_path.c_str()) < 0) throw systemError("symlink " + link_path + " -> " + name_);
  link_path_ = link_path;
}

LineClients::~LineClients() {
  for (int fd : fds_) {
    if (fd >= 0) ::close(fd);
  }
}

void LineClients::add(int fd) {
  fds_.push_back(fd);
  pending_.emplace_back();
}

void LineClients::read(std::size_t k, const std::function<bool(int fd, const std::string& line)>& serve,
                       std::size_t max_line) {
  char buffer[256];
  const ssize_t n = ::read(fds_[k], buffer, sizeof(buffer));
  if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return;  // non-blocking: nothing yet
  bool open = n > 0;
  if (open) {
    std::string& pending = pending_[k];
    pending.append(buffer, static_cast<std::size_t>(n));
    std::string line;
    while (open && takeLine(pending, &line)) open = serve(fds_[k], line);
    open = open && pending.size() <= max_line;  // a client that sends no line breaks is dropped
  }
  if (!open) {
    ::close(fds_[k]);
    fds_[k] = -1;
  }
}

void LineClients::sweep() {
  for (std::size_t k = fds_.size(); k-- > 0;) {
    if (fds_[k] >= 0) continue;
    fds_.erase(fds_.begin() + static_cast<std::ptrdiff_t>(k));
    pending_.erase(pending_.begin() + static_cast<std::ptrdiff_t>(k));
  }
}

void sendAvailable(int fd, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const char*>(data);
  std::size_t done = 0;
  while (done < size) {
    ssize_t n = ::send(fd, bytes + done, size - done, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && errno == ENOTSOCK) n = ::write(fd, bytes + done, size - done);
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace link
}  // namespace amigobot_tracking

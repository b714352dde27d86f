// Test helpers: the amigobot_emulator executable as a child process (killed on scope exit),
// its ground-truth status socket (aria::StatusClient), and a minimal raw protocol client over a real TCP socket
// or pty. Used by the driver <-> emulator tests; no mocks.
#pragma once

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "amigobot_tracking/aria/client.h"
#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/aria/emulator_status.h"
#include "amigobot_tracking/aria/packet.h"
#include "child_process.h"

namespace amigobot_test {

using namespace amigobot_tracking::aria;

inline double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Polls `predicate` every 20 ms until it holds or `timeout` [s] passes.
// A client for the emulator: quick reconnects, a short link timeout, no command timeout
// (tests drive with sparse setVelocity calls).
inline amigobot_tracking::aria::ClientConfig emulatorClientConfig(const std::string& port) {
  amigobot_tracking::aria::ClientConfig c;
  c.port = port;
  c.reconnect_delay_min = 0.2;
  c.reconnect_delay_max = 1.0;
  c.link_timeout = 1.5;
  c.command_timeout = 0.0;
  return c;
}

inline bool waitFor(const std::function<bool()>& predicate, double timeout) {
  const double end = now() + timeout;
  while (now() < end) {
    if (predicate()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return predicate();
}

inline int connectTcp(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) < 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

using Truth = EmulatorStatus;

class EmulatorProcess {
 public:
  // extra: further command-line options. tcp_port 0 = any free port.
  explicit EmulatorProcess(std::vector<std::string> extra = {}, int tcp_port = 0, std::string pty_link = "") {
    start(std::move(extra), tcp_port, std::move(pty_link));
  }
  ~EmulatorProcess() { kill(SIGTERM); }

  void start(std::vector<std::string> extra, int tcp_port, std::string pty_link) {
    std::vector<std::string> args = {AMIGOBOT_EMULATOR, "--tcp-port", std::to_string(tcp_port), "--status-port", "0"};
    if (!pty_link.empty()) {
      args.push_back("--pty");
      args.push_back(pty_link);
    }
    args.insert(args.end(), extra.begin(), extra.end());
    const std::string line = process_.start(args);
    if (std::sscanf(line.c_str(), "READY tcp=%d status=%d", &tcp_port_, &status_port_) != 2) {
      kill(SIGKILL);
      throw std::runtime_error("amigobot_emulator did not start: '" + line + "'");
    }
    const std::size_t control = line.find(" control=");
    if (control != std::string::npos) control_port_ = std::atoi(line.c_str() + control + 9);
  }

  // Sends `signal` and returns at once (SIGSTOP / SIGCONT freeze and thaw the robot).
  void signal(int signal) { process_.signal(signal); }
  void kill(int signal) {
    process_.stop(signal);
    status_.reset();
  }

  int tcpPort() const { return tcp_port_; }
  int statusPort() const { return status_port_; }
  int controlPort() const { return control_port_; }  // -1 without --control-port
  std::string address() const { return "127.0.0.1:" + std::to_string(tcp_port_); }

  // Ground truth from the status socket; throws when it does not answer.
  Truth truth() {
    if (!status_) status_ = std::make_unique<StatusClient>("127.0.0.1", status_port_, 5.0);
    Truth t;
    const std::string error = status_->query(&t);
    if (!error.empty()) throw std::runtime_error(error);
    return t;
  }

 private:
  ChildProcess process_;
  int tcp_port_ = -1, status_port_ = -1, control_port_ = -1;
  std::unique_ptr<StatusClient> status_;
};

// A bare-bones ARIA client speaking through a file descriptor (TCP socket or pty).
class RawClient {
 public:
  explicit RawClient(int fd) : fd_(fd) {}
  static RawClient tcp(int port) { return RawClient(connectTcp(port)); }
  static RawClient pty(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY);
    if (fd >= 0) {
      termios tio{};
      ::tcgetattr(fd, &tio);
      ::cfmakeraw(&tio);
      ::tcsetattr(fd, TCSANOW, &tio);
    }
    return RawClient(fd);
  }
  RawClient(RawClient&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
  ~RawClient() { closeWithoutGoodbye(); }
  bool ok() const { return fd_ >= 0; }
  void send(const std::vector<std::uint8_t>& bytes) {
    if (::write(fd_, bytes.data(), bytes.size()) != static_cast<ssize_t>(bytes.size())) throw std::runtime_error("write");
  }
  // Next packet within `timeout` [s], or type -1.
  Packet next(double timeout) {
    const double end = now() + timeout;
    Packet p;
    while (!parser_.next(p)) {
      const double left = end - now();
      if (left <= 0) {
        p.type = 0xFF;
        p.payload.clear();
        timed_out_ = true;
        return p;
      }
      pollfd pf{fd_, POLLIN, 0};
      if (::poll(&pf, 1, static_cast<int>(left * 1000) + 1) > 0) {
        std::uint8_t buf[256];
        const ssize_t n = ::read(fd_, buf, sizeof(buf));
        if (n > 0) parser_.feed(buf, static_cast<std::size_t>(n));
      }
    }
    timed_out_ = false;
    return p;
  }
  bool timedOut() const { return timed_out_; }
  // SYNC0/1/2 then OPEN int 1, as ARIA does; true when the robot answered every SYNC.
  bool handshakeAndOpen() {
    for (int n = 0; n < 3; ++n) {
      send(syncPacket(n));
      const Packet reply = next(2.0);
      if (timed_out_ || reply.type != n) return false;
    }
    send(commandPacket(Command::kOpen, 1));
    return true;
  }
  void closeWithoutGoodbye() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_;
  PacketParser parser_;
  bool timed_out_ = false;
};

}  // namespace amigobot_test

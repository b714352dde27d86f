#include "amigobot_tracking/aria/emulator_server.h"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>

#include "amigobot_tracking/link/emulator_link.h"
#include "amigobot_tracking/link/serial_port.h"

namespace amigobot_tracking {
namespace aria {
EmulatorServer::EmulatorServer(RobotEmulator& robot, EmulatorServerOptions options)
    : robot_(robot), options_(std::move(options)), noise_(options_.corrupt_seed) {
  if (!(options_.corrupt_probability >= 0.0 && options_.corrupt_probability <= 1.0)) {
    throw std::invalid_argument("amigobot_emulator: corrupt probability must be within [0, 1]");
  }
  if (!(options_.time_scale > 0.0 && options_.time_scale <= 100.0)) {
    throw std::invalid_argument("amigobot_emulator: time_scale must be within (0, 100]");
  }
}

EmulatorServer::~EmulatorServer() {
  if (tcp_client_.fd >= 0) ::close(tcp_client_.fd);
}

void EmulatorServer::open() {
  try {
    if (options_.tcp_port >= 0) tcp_listen_.open(options_.bind_address, options_.tcp_port);
    if (options_.status_port >= 0) status_listen_.open(options_.bind_address, options_.status_port);
    if (!options_.pty_link.empty()) {
      pty_terminal_.open(options_.pty_link, 9600);  // a robot's UART starts at 9600
      pty_.fd = pty_terminal_.master();
      tcp_active_ = false;
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("amigobot_emulator: ") + e.what());
  }
  start_wall_ = link::steadySeconds();
}

double EmulatorServer::now() const { return (link::steadySeconds() - start_wall_) * options_.time_scale; }

void EmulatorServer::dropTcpClient() {
  if (tcp_client_.fd < 0) return;
  ::close(tcp_client_.fd);
  tcp_client_.fd = -1;
  tcp_client_.parser.reset();
  robot_.clientDisconnected();
}

void EmulatorServer::acceptRobotClient() {
  const int fd = tcp_listen_.accept();
  if (fd < 0) return;
  dropTcpClient();  // one serial port: the newest client takes it over
  tcp_client_.fd = fd;
  tcp_active_ = true;
}

void EmulatorServer::sendToActive(const std::vector<std::uint8_t>& bytes) {
  if (bytes.empty()) return;
  const int fd = tcp_active_ ? tcp_client_.fd : pty_.fd;
  if (fd < 0) return;
  // The pty's bytes go through the robot's UART model; TCP has no baud.
  const auto deliver = [&](const std::vector<std::uint8_t>& out) {
    if (tcp_active_) {
      link::sendAvailable(fd, out);
    } else {
      pty_line_.transmit(out, robot_.baud(), link::steadySeconds());
    }
  };
  if (options_.corrupt_probability <= 0.0) {
    deliver(bytes);
    return;
  }
  // A noisy line: each packet may get a flipped byte, a dropped tail or leading garbage.
  std::vector<std::uint8_t> out = bytes;
  std::uniform_real_distribution<double> chance(0.0, 1.0);
  std::uniform_int_distribution<std::size_t> where(0, out.size() - 1);
  if (chance(noise_) < options_.corrupt_probability) {
    switch (where(noise_) % 3) {
      case 0: out[where(noise_)] ^= 0x5A; break;
      case 1: out.resize(where(noise_)); break;
      default: out.insert(out.begin(), {0x13, kHeader0, 0x37}); break;
    }
    ++corrupted_;
  }
  deliver(out);
}

void EmulatorServer::flushPtyLine() {
  if (pty_.fd < 0) return;
  const std::vector<std::uint8_t> out = pty_line_.due(link::steadySeconds(), link::lineBaud(pty_terminal_.slave()));
  if (!out.empty()) link::sendAvailable(pty_.fd, out);
}

void EmulatorServer::readLink(Link& link, bool is_tcp) {
  std::uint8_t buffer[512];
  const ssize_t n = ::read(link.fd, buffer, sizeof(buffer));
  if (n <= 0) {
    if (is_tcp && (n == 0 || (errno != EAGAIN && errno != EINTR))) dropTcpClient();
    return;
  }
  if (is_tcp) {
    link.parser.feed(buffer, static_cast<std::size_t>(n));
  } else {
    const std::vector<std::uint8_t> heard =
        SerialLineModel::receive(buffer, static_cast<std::size_t>(n), link::lineBaud(pty_terminal_.slave()), robot_.baud());
    link.parser.feed(heard.data(), heard.size());
  }
  Packet packet;
  while (link.parser.next(packet)) {
    tcp_active_ = is_tcp;
    const bool was_open = robot_.isOpen();
    sendToActive(robot_.handle(packet, now()));
    // A simulator closes the connection on CLOSE.
    if (is_tcp && was_open && !robot_.isOpen() && robot_.options().simulator_mode) {
      dropTcpClient();
      return;
    }
  }
}

void EmulatorServer::serveStatus(std::size_t index, bool& quit) {
  status_clients_.read(index, [&](int fd, const std::string& line) {
    if (line.rfind("quit", 0) == 0) quit = true;
    link::sendAvailable(fd, formatStatusLine(robot_.status(now())) + "\n");
    return true;
  });
}

void EmulatorServer::run(const std::atomic<bool>& stop) {
  bool quit = false;
  while (!stop && !quit) {
    std::vector<pollfd> fds;
    auto add = [&](int fd) {
      if (fd >= 0) fds.push_back({fd, POLLIN, 0});
      return fd >= 0 ? static_cast<int>(fds.size()) - 1 : -1;
    };
    const int i_tcp_listen = add(tcp_listen_.fd());
    const int i_status_listen = add(status_listen_.fd());
    const int i_tcp = add(tcp_client_.fd);
    const int i_pty = add(pty_.fd);
    const int i_status0 = static_cast<int>(fds.size());
    for (std::size_t k = 0; k < status_clients_.size(); ++k) fds.push_back({status_clients_.fd(k), POLLIN, 0});
    // Wake often enough for the physics step and the SIP cycle in wall time.
    const int timeout_ms = std::max(1, static_cast<int>(5.0 / options_.time_scale));
    if (::poll(fds.data(), fds.size(), timeout_ms) < 0 && errno != EINTR) throw link::systemError("amigobot_emulator: poll");
    auto ready = [&](int i) { return i >= 0 && (fds[static_cast<std::size_t>(i)].revents & (POLLIN | POLLHUP | POLLERR)); };
    if (ready(i_tcp_listen)) acceptRobotClient();
    if (ready(i_tcp) && tcp_client_.fd == fds[static_cast<std::size_t>(i_tcp)].fd) readLink(tcp_client_, true);
    // POLLHUP on the master only means no client holds the slave: not an error.
    if (i_pty >= 0 && (fds[static_cast<std::size_t>(i_pty)].revents & POLLIN)) readLink(pty_, false);
    // The clients polled above only: a client accepted below has no slot in fds yet (reading
    // fds past its end gave it a garbage revents, and its first read, EAGAIN, closed it).
    const std::size_t n_status = status_clients_.size();
    if (ready(i_status_listen)) {
      const int fd = status_listen_.accept();
      if (fd >= 0) status_clients_.add(fd);
    }
    for (std::size_t k = 0; k < n_status; ++k) {
      if (ready(i_status0 + static_cast<int>(k))) serveStatus(k, quit);
    }
    status_clients_.sweep();
    sendToActive(robot_.advance(now()));
    flushPtyLine();
  }
}

}  // namespace aria
}  // namespace amigobot_tracking

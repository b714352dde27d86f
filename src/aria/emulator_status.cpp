#include "amigobot_tracking/aria/emulator_status.h"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "amigobot_tracking/aria/transport.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr std::size_t kMaxLine = 65536;
constexpr std::size_t kMaxControlLine = 256;  // "teleport" and three %.17g numbers fit in 80
constexpr double kMaxTeleport = 1e4;           // [m] farther is a typo, not a room

// A flag field: exactly 0 or 1.
bool readFlag(std::istringstream& in, bool* flag) {
  int value = -1;
  if (!(in >> value) || (value != 0 && value != 1)) return false;
  *flag = value == 1;
  return true;
}

}  // namespace

std::string formatStatusLine(const EmulatorStatus& s) {
  // %.17g: every double reads back exactly, 1e300 as 1e+300 (not 300 digits); 9 fields
  // of at most 24 characters each fit.
  char line[256];
  std::snprintf(line, sizeof(line), "%.17g %.17g %.17g %.17g %.17g %.17g %d %d %d", s.t, s.pose.x, s.pose.y, s.pose.theta,
                s.v, s.w, s.motors ? 1 : 0, s.open ? 1 : 0, s.watchdog ? 1 : 0);
  return line;
}

std::string parseStatusLine(const std::string& line, EmulatorStatus* status) {
  std::istringstream in(line);
  EmulatorStatus s;
  if (!(in >> s.t >> s.pose.x >> s.pose.y >> s.pose.theta >> s.v >> s.w)) {
    return "status line '" + line + "' is not 't x y theta v w motors open watchdog'";
  }
  if (!readFlag(in, &s.motors) || !readFlag(in, &s.open) || !readFlag(in, &s.watchdog)) {
    return "status line '" + line + "': motors, open and watchdog must each be 0 or 1";
  }
  std::string extra;
  if (in >> extra) return "status line '" + line + "' has extra fields";
  if (!std::isfinite(s.t) || !s.pose.isFinite() || !std::isfinite(s.v) || !std::isfinite(s.w)) {
    return "status line '" + line + "' has a non-finite number";
  }
  *status = s;
  return "";
}

StatusClient::StatusClient(std::string host, int port, double timeout, double reconnect_period)
    : host_(std::move(host)), port_(port), timeout_(timeout), reconnect_period_(reconnect_period) {}

StatusClient::~StatusClient() = default;

bool StatusClient::connected() const { return link_ != nullptr; }

std::string StatusClient::where() const { return "emulator status socket " + host_ + ":" + std::to_string(port_); }

std::string StatusClient::fail(const std::string& why) {
  link_.reset();
  buffer_.clear();
  next_attempt_ = link::steadySeconds() + reconnect_period_;
  last_error_ = why;
  return why;
}

std::string StatusClient::query(EmulatorStatus* status) {
  if (!link_) {
    if (link::steadySeconds() < next_attempt_) return last_error_;
    try {
      link_ = makeTransport(host_ + ":" + std::to_string(port_), 0);
      link_->open();
    } catch (const std::exception& e) {
      return fail("emulator status: " + std::string(e.what()));
    }
  }
  try {
    link_->write({'\n'});
    // The first complete line answers this request (one reply per request, in order).
    const double deadline = link::steadySeconds() + timeout_;
    std::string line;
    while (!link::takeLine(buffer_, &line)) {
      const double left = deadline - link::steadySeconds();
      if (left <= 0.0) return fail("no reply from the " + where() + " within " + std::to_string(timeout_) + " s");
      std::uint8_t chunk[512];
      const std::size_t n = link_->read(chunk, sizeof(chunk), static_cast<int>(std::ceil(left * 1e3)));
      buffer_.append(reinterpret_cast<const char*>(chunk), n);
      if (buffer_.size() > kMaxLine) return fail(where() + " sends no line breaks");
    }
    const std::string error = parseStatusLine(line, status);
    return error.empty() ? error : fail(where() + ": " + error);
  } catch (const std::exception& e) {
    return fail(where() + " lost: " + e.what());
  }
}

std::string parseControlLine(const std::string& line, core::Pose2* pose) {
  std::istringstream in(line);
  std::string command, extra;
  core::Pose2 p;
  if (!(in >> command) || command != "teleport") {
    return "control line '" + line + "': unknown command (known: teleport x y theta, deaf on|off)";
  }
  if (!(in >> p.x >> p.y >> p.theta)) return "control line '" + line + "' is not 'teleport x y theta'";
  if (in >> extra) return "control line '" + line + "' has extra fields";
  if (!p.isFinite() || std::abs(p.x) > kMaxTeleport || std::abs(p.y) > kMaxTeleport) {
    return "control line '" + line + "': x and y must be finite within 1e4 m, theta finite";
  }
  *pose = p;
  return "";
}

std::string parseDeafLine(const std::string& line, bool* deaf) {
  std::istringstream in(line);
  std::string command, state, extra;
  if (!(in >> command >> state) || command != "deaf" || (state != "on" && state != "off") || (in >> extra)) {
    return "control line '" + line + "' is not 'deaf on' or 'deaf off'";
  }
  *deaf = state == "on";
  return "";
}

std::string formatTeleportLine(const core::Pose2& pose) {
  char line[128];
  std::snprintf(line, sizeof(line), "teleport %.17g %.17g %.17g", pose.x, pose.y, pose.theta);
  return line;
}

void TeleportMailbox::post(const core::Pose2& pose) {
  std::lock_guard<std::mutex> lock(mutex_);
  pending_ = pose;
}

std::optional<core::Pose2> TeleportMailbox::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<core::Pose2> pose;
  pose.swap(pending_);
  return pose;
}

ControlServer::ControlServer(TeleportMailbox& mailbox, const std::string& bind_address, int port)
    : mailbox_(mailbox) {
  try {
    listener_.open(bind_address, port);
  } catch (const std::exception& e) {
    throw std::runtime_error("emulator control socket " + bind_address + ":" + std::to_string(port) + ": " + e.what());
  }
  thread_ = std::thread([this] { run(); });
}

ControlServer::~ControlServer() {
  stop_ = true;
  thread_.join();
}

bool ControlServer::answer(int fd, const std::string& line) {
  std::string error;
  if (line.rfind("deaf", 0) == 0) {
    bool deaf = false;
    error = parseDeafLine(line, &deaf);
    if (error.empty()) mailbox_.setDeaf(deaf);
  } else {
    core::Pose2 pose;
    error = parseControlLine(line, &pose);
    if (error.empty()) mailbox_.post(pose);
  }
  const std::string reply = error.empty() ? "ok\n" : "error: " + error + "\n";
  return ::send(fd, reply.data(), reply.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(reply.size());
}

void ControlServer::run() {
  while (!stop_) {
    std::vector<pollfd> fds{{listener_.fd(), POLLIN, 0}};
    for (std::size_t k = 0; k < clients_.size(); ++k) fds.push_back({clients_.fd(k), POLLIN, 0});
    if (::poll(fds.data(), fds.size(), 50) <= 0) continue;  // 50 ms: how soon the destructor returns
    for (std::size_t k = 0; k < clients_.size(); ++k) {
      if (!(fds[k + 1].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      // A client that sends no line breaks is dropped.
      clients_.read(k, [this](int fd, const std::string& line) { return answer(fd, line); }, kMaxControlLine);
    }
    clients_.sweep();
    if (fds[0].revents & POLLIN) {
      const int fd = listener_.accept();
      if (fd >= 0) clients_.add(fd);
    }
  }
}

std::string requestTeleport(const std::string& host, int port, const core::Pose2& pose, double timeout) {
  return requestControl(host, port, formatTeleportLine(pose), timeout);
}

std::string requestControl(const std::string& host, int port, const std::string& request, double timeout) {
  const std::string where = "emulator control socket " + host + ":" + std::to_string(port);
  try {
    std::unique_ptr<Transport> link = makeTransport(host + ":" + std::to_string(port), 0);
    link->open();
    const std::string line = request + "\n";
    link->write(std::vector<std::uint8_t>(line.begin(), line.end()));
    std::string pending, reply;
    const double deadline = link::steadySeconds() + timeout;
    while (!link::takeLine(pending, &reply)) {
      const double left = deadline - link::steadySeconds();
      if (left <= 0.0 || pending.size() > kMaxControlLine) return "no answer from the " + where;
      std::uint8_t chunk[256];
      const std::size_t n = link->read(chunk, sizeof(chunk), static_cast<int>(std::ceil(left * 1e3)));
      pending.append(reinterpret_cast<const char*>(chunk), n);
    }
    return reply == "ok" ? "" : where + ": " + reply;
  } catch (const std::exception& e) {
    return where + ": " + e.what();
  }
}

}  // namespace aria
}  // namespace amigobot_tracking

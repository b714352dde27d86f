#include "amigobot_tracking/ros/ground_truth.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <sstream>

#include <ros/console.h>

#include "amigobot_tracking/ros/param_reader.h"

namespace amigobot_tracking {
namespace ros_layer {

std::string parseEmulatorStatus(const std::string& line, EmulatorStatus* status) {
  std::istringstream in(line);
  EmulatorStatus s;
  int motors = 0, open = 0, watchdog = 0;
  if (!(in >> s.t >> s.pose.x >> s.pose.y >> s.pose.theta >> s.v >> s.w >> motors >> open >> watchdog)) {
    return "status line '" + line + "' is not 't x y theta v w motors open watchdog'";
  }
  std::string extra;
  if (in >> extra) return "status line '" + line + "' has extra fields";
  if (!std::isfinite(s.t) || !s.pose.isFinite() || !std::isfinite(s.v) || !std::isfinite(s.w)) {
    return "status line '" + line + "' has a non-finite number";
  }
  s.motors = motors != 0;
  s.open = open != 0;
  s.watchdog = watchdog != 0;
  *status = s;
  return "";
}

core::Pose2 mapToOdom(const core::Pose2& truth, const core::Pose2& odom_base) {
  const double theta = core::wrapAngle(truth.theta - odom_base.theta);
  const double c = std::cos(theta), s = std::sin(theta);
  core::Pose2 out;
  out.theta = theta;
  out.x = truth.x - (c * odom_base.x - s * odom_base.y);
  out.y = truth.y - (s * odom_base.x + c * odom_base.y);
  return out;
}

const core::FieldTable<GroundTruthConfig>& groundTruthFields() {
  using G = GroundTruthConfig;
  using core::field;
  static const core::FieldTable<G> table = {
      field("host", &G::host, "-", "the emulator's status socket address"),
      field("port", &G::port, "-", "its --status-port", core::interval(1, false, 65535, false)),
      field("global_frame", &G::global_frame, "-", "map frame"),
      field("odom_frame", &G::odom_frame, "-", "odometry frame"),
      field("base_frame", &G::base_frame, "-", "robot frame"),
      field("rate", &G::rate, "Hz", "map -> odom updates", core::positive()),
      field("transform_tolerance", &G::transform_tolerance, "s", "map -> odom is stamped this far ahead",
            core::nonNegative()),
      field("socket_timeout", &G::socket_timeout, "s", "a slower status reply counts as a lost link",
            core::positive()),
      field("reconnect_period", &G::reconnect_period, "s", "between reconnection attempts", core::positive()),
  };
  return table;
}

std::string GroundTruthConfig::validate() const {
  const std::string bad = core::checkFields(groundTruthFields(), *this);
  if (!bad.empty()) return bad;
  if (host.empty()) return "host: must not be empty";
  if (global_frame.empty() || odom_frame.empty() || base_frame.empty())
    return "global_frame/odom_frame/base_frame: must not be empty";
  return "";
}

std::string loadGroundTruthConfig(const ros::NodeHandle& pnh, GroundTruthConfig* config) {
  return readParams(pnh, groundTruthFields(), config);
}

StatusClient::StatusClient(std::string host, int port, double timeout)
    : host_(std::move(host)), port_(port), timeout_(timeout) {}

StatusClient::~StatusClient() { close(); }

void StatusClient::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  buffer_.clear();
}

std::string StatusClient::connectSocket() {
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(port_));
  if (inet_pton(AF_INET, host_.c_str(), &addr.sin_addr) != 1) return "'" + host_ + "' is not an IPv4 address";
  fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) return std::string("socket: ") + std::strerror(errno);
  if (::connect(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) != 0) {
    const std::string why = std::strerror(errno);
    close();
    return "cannot connect to the emulator status socket " + host_ + ":" + std::to_string(port_) + ": " + why;
  }
  return "";
}

std::string StatusClient::query(EmulatorStatus* status) {
  if (fd_ < 0) {
    const std::string error = connectSocket();
    if (!error.empty()) return error;
  }
  const char request = '\n';
  if (::send(fd_, &request, 1, MSG_NOSIGNAL) != 1) {
    close();
    return "status socket " + host_ + ":" + std::to_string(port_) + " closed (send failed)";
  }
  // Keep only the newest complete line: replies are answers to this or earlier requests.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_);
  while (true) {
    const std::size_t end = buffer_.find('\n');
    if (end != std::string::npos) {
      const std::string line = buffer_.substr(0, end);
      buffer_.erase(0, end + 1);
      const std::string error = parseEmulatorStatus(line, status);
      if (!error.empty()) close();
      return error;
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      close();
      return "no status reply from " + host_ + ":" + std::to_string(port_) + " within " + std::to_string(timeout_) + " s";
    }
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    char chunk[512];
    const ssize_t n = ::recv(fd_, chunk, sizeof(chunk), 0);
    if (n <= 0) {
      close();
      return "status socket " + host_ + ":" + std::to_string(port_) + " closed by the emulator";
    }
    buffer_.append(chunk, static_cast<std::size_t>(n));
    if (buffer_.size() > 65536) {
      close();
      return "status socket sends no line breaks";
    }
  }
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

// The end-to-end tests' judge: what the emulator says happened, never what the controller
// thinks. Ground truth from the emulator's status socket (aria::StatusClient), the
// motion commands it decoded from the wire (its --command-log journal), and a few ROS
// helpers (process id of a node, retried Trigger calls, geometry of the offset point).
#pragma once

#include <signal.h>
#include <sys/types.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <ros/network.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include "amigobot_tracking/aria/emulator_status.h"
#include "emulator_liveness.h"
#include "emulator_process.h"  // waitFor, now

namespace e2e {

using amigobot_test::now;
using amigobot_test::waitFor;
using amigobot_tracking::aria::EmulatorStatus;

// A private parameter of the test node (the .test file sets them); throws if missing.
template <typename T>
T requiredParam(const std::string& name) {
  T value;
  if (!ros::param::get("~" + name, value)) throw std::runtime_error("test node needs ~" + name);
  return value;
}

// The emulator's ground truth. The status socket may be down (emulator restarting): then
// truth() fails and tryTruth() returns false.
class GroundTruth {
 public:
  explicit GroundTruth(int status_port) : status_port_(status_port), client_("127.0.0.1", status_port, 1.0) {}
  bool tryTruth(EmulatorStatus* status) { return client_.query(status).empty(); }
  EmulatorStatus truth() {
    EmulatorStatus s;
    const std::string problem = client_.query(&s);
    if (!problem.empty()) throw std::runtime_error("emulator status: " + problem);
    return s;
  }
  // Waits until the emulator answers and the driver has it open with the motors on. Start-up
  // runs in stages (the emulator answers, the driver opens the robot, the motors come on) and
  // each stage gets `timeout` [s] from the end of the one before: a loaded machine lengthens
  // the wait while the stack makes progress. A failure names the stage, the process that was
  // late and, when the emulator is gone, its exit report.
  ::testing::AssertionResult waitForRobotReady(double timeout) {
    enum Stage { kNoAnswer, kClosed, kMotorsOff, kReady };
    Stage reached = kNoAnswer;
    double stage_start = now();
    std::string problem;
    EmulatorStatus s;
    while (true) {
      problem = client_.query(&s);
      const Stage stage = !problem.empty() ? kNoAnswer : !s.open ? kClosed : !s.motors ? kMotorsOff : kReady;
      if (stage == kReady) return ::testing::AssertionSuccess();
      if (stage > reached) {
        reached = stage;
        stage_start = now();
      }
      if (now() - stage_start > timeout) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    const std::string late = " within " + std::to_string(static_cast<int>(timeout)) + " s";
    switch (reached) {
      case kNoAnswer:
        return ::testing::AssertionFailure() << "the emulator never answered on its status port " << status_port_
                                             << late << " (" << problem << "): " << emulatorState(status_port_);
      case kClosed:
        return ::testing::AssertionFailure() << "the emulator answered but the driver never opened the robot" << late
                                             << " (no completed handshake; " << emulatorState(status_port_) << ")";
      default:
        return ::testing::AssertionFailure() << "the driver opened the robot but never enabled its motors" << late;
    }
  }
  // Waits until the robot's true v and w are exactly zero; *stopped = that status.
  bool waitForStandstill(double timeout, EmulatorStatus* stopped) {
    return waitFor([&] {
      return tryTruth(stopped) && stopped->v == 0.0 && stopped->w == 0.0;
    }, timeout);
  }

 private:
  int status_port_;
  amigobot_tracking::aria::StatusClient client_;
};

// One line of the emulator's command journal: the setpoint pair (v, w) the robot holds
// after the decoded command (VEL, RVEL, ROTATE, VEL2, STOP, ESTOP), at emulated time t.
struct WireCommand {
  double t = 0.0;  // [s] emulator time
  std::string command;
  double v = 0.0;  // [m/s]
  double w = 0.0;  // [rad/s]
};

inline std::vector<WireCommand> readCommandLog(const std::string& path) {
  std::ifstream in(path);
  std::vector<WireCommand> commands;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    WireCommand c;
    if (fields >> c.t >> c.command >> c.v >> c.w) commands.push_back(c);
  }
  return commands;
}

// The setpoint pairs the robot held: the driver sends VEL and RVEL back to back, which the
// journal records as two lines a few ms apart (the first a half-updated pair); lines closer
// than `merge` [s] (below the driver's 50 ms min_command_interval) are one pair, the last.
inline std::vector<WireCommand> setpointPairs(const std::vector<WireCommand>& commands, double merge = 0.02) {
  std::vector<WireCommand> pairs;
  for (const auto& c : commands) {
    if (!pairs.empty() && c.t - pairs.back().t < merge) {
      const double first_t = pairs.back().t;
      pairs.back() = c;
      pairs.back().t = first_t;
    } else {
      pairs.push_back(c);
    }
  }
  return pairs;
}

// Emulator time of the first zero setpoint pair (0, 0) held at or after `since`; -1 if none.
inline double firstZeroSetpoint(const std::vector<WireCommand>& commands, double since) {
  for (const auto& c : commands) {
    if (c.t >= since && c.v == 0.0 && c.w == 0.0) return c.t;
  }
  return -1.0;
}

// The true offset point p_r = (x, y) + r (cos theta, sin theta) of the robot's body.
inline Eigen::Vector2d offsetPoint(const EmulatorStatus& s, double offset) {
  return {s.pose.x + offset * std::cos(s.pose.theta), s.pose.y + offset * std::sin(s.pose.theta)};
}

// The process id of a ROS node, asked through its slave API (getPid); -1 if unknown.
inline int nodePid(const std::string& node) {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  request[1] = node;
  if (!ros::master::execute("lookupNode", request, response, payload, false)) return -1;
  std::string host, path;
  std::uint32_t port = 0;
  if (!ros::network::splitURI(static_cast<std::string>(payload), host, port)) return -1;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue args, result;
  args[0] = ros::this_node::getName();
  if (!client.execute("getPid", args, result) || result.getType() != XmlRpc::XmlRpcValue::TypeArray ||
      result.size() < 3 || static_cast<int>(result[0]) != 1) {
    return -1;
  }
  return static_cast<int>(result[2]);
}

// Calls a std_srvs/Trigger service until it succeeds (enable/disable are idempotent, so a
// retry after a lost reply is harmless); false after `timeout` [s].
inline bool callTrigger(const std::string& service, double timeout, std::string* message = nullptr) {
  return waitFor([&] {
    std_srvs::Trigger trigger;
    if (!ros::service::waitForService(service, ros::Duration(1.0)) || !ros::service::call(service, trigger)) {
      return false;
    }
    if (message) *message = trigger.response.message;
    return static_cast<bool>(trigger.response.success);
  }, timeout);
}

}  // namespace e2e

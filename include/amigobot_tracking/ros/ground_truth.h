// Ground-truth localisation for the emulated robot: the emulator's status socket reports
// the true pose of base_link in the world (= map); the map -> odom correction makes
// map -> odom -> base_link equal that pose (REP 105), as a perfect localiser would.
#pragma once

#include <string>

#include <ros/node_handle.h>

#include "amigobot_tracking/core/field_table.h"
#include "amigobot_tracking/core/types.h"

namespace amigobot_tracking {
namespace ros_layer {

// One line of the emulator's status socket: `t x y theta v w motors open watchdog` (SI).
struct EmulatorStatus {
  double t = 0.0;        // [s] emulated time
  core::Pose2 pose;      // [m, m, rad] true pose of base_link in the world
  double v = 0.0;        // [m/s]
  double w = 0.0;        // [rad/s]
  bool motors = false;
  bool open = false;
  bool watchdog = false;
};

// Parses one status line. Empty string when valid, else says what is wrong with it.
std::string parseEmulatorStatus(const std::string& line, EmulatorStatus* status);

// map -> odom such that (map -> odom) * (odom -> base) = truth: truth * inverse(odom_base).
core::Pose2 mapToOdom(const core::Pose2& truth, const core::Pose2& odom_base);

struct GroundTruthConfig {
  std::string host = "127.0.0.1";       // emulator's status socket address
  int port = 8102;                      // its --status-port
  std::string global_frame = "map";
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  double rate = 20.0;                   // [Hz] map -> odom updates
  double transform_tolerance = 0.1;     // [s] map -> odom is stamped this far ahead (as amcl does)
  double socket_timeout = 0.5;          // [s] a status reply slower than this counts as a lost link
  double reconnect_period = 1.0;        // [s] between reconnection attempts

  std::string validate() const;  // empty when valid, else "key: reason"
};

const core::FieldTable<GroundTruthConfig>& groundTruthFields();

std::string loadGroundTruthConfig(const ros::NodeHandle& pnh, GroundTruthConfig* config);

// Line-based TCP client of the status socket. Never blocks longer than its timeout.
class StatusClient {
 public:
  StatusClient(std::string host, int port, double timeout);
  ~StatusClient();
  StatusClient(const StatusClient&) = delete;
  StatusClient& operator=(const StatusClient&) = delete;

  // Connects if needed, asks for one status line. Empty on success, else why not (the
  // connection is then closed and the next call reconnects).
  std::string query(EmulatorStatus* status);
  bool connected() const { return fd_ >= 0; }

 private:
  std::string connectSocket();
  void close();

  std::string host_;
  int port_;
  double timeout_;
  int fd_ = -1;
  std::string buffer_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking

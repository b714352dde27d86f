// The emulator's ground-truth status protocol, one home for both ends: a client sends any
// line on the status socket, the emulator answers each with one line
// "t x y theta v w motors open watchdog" (SI units; motors, open, watchdog 0 or 1); a line
// starting with "quit" also stops the emulator. Ground-truth localisation and the tests
// read it through StatusClient.
#pragma once

#include <memory>
#include <string>

#include "amigobot_tracking/core/types.h"

namespace amigobot_tracking {
namespace aria {

class Transport;

struct EmulatorStatus {
  double t = 0.0;    // [s] emulated time
  core::Pose2 pose;  // [m, m, rad] true pose of base_link in the world
  double v = 0.0;    // [m/s]
  double w = 0.0;    // [rad/s]
  bool motors = false;
  bool open = false;
  bool watchdog = false;
};

// One status line, without the line break.
std::string formatStatusLine(const EmulatorStatus& status);
// Empty when `line` is a valid status line (then *status holds it), else what is wrong.
std::string parseStatusLine(const std::string& line, EmulatorStatus* status);

// Line-based client of the status socket over MRPT's TCP socket. Never blocks longer than
// its timeout (plus the connect timeout). After a failure it reconnects on a later query,
// at most once per reconnect_period; in between, query() repeats the last failure.
class StatusClient {
 public:
  StatusClient(std::string host, int port, double timeout, double reconnect_period = 0.0);
  ~StatusClient();
  StatusClient(const StatusClient&) = delete;
  StatusClient& operator=(const StatusClient&) = delete;

  // Connects if needed and asks for one status line. Empty on success, else why not (the
  // connection is then closed).
  std::string query(EmulatorStatus* status);
  bool connected() const;

 private:
  std::string fail(const std::string& why);
  std::string where() const;

  std::string host_;
  int port_;
  double timeout_, reconnect_period_;
  std::unique_ptr<Transport> link_;
  std::string buffer_, last_error_;
  double next_attempt_ = 0.0;  // [s] steady clock
};

}  // namespace aria
}  // namespace amigobot_tracking

// The emulator's ground-truth status protocol, one home for both ends: a client sends any
// line on the status socket, the emulator answers each with one line
// "t x y theta v w motors open watchdog" (SI units; motors, open, watchdog 0 or 1); a line
// starting with "quit" also stops the emulator. Ground-truth localisation and the tests
// read it through StatusClient.
// Its control socket (amigobot_emulator --control-port) injects faults into the world: a
// line "teleport x y theta" (SI units, world frame) moves the true pose there, answered "ok"
// or "error: <why>". Only the truth jumps: the firmware's odometry and the wheels carry on,
// as when a robot is lifted and put down elsewhere (a kidnap). A line "deaf on" cuts the
// driver -> robot direction (every client packet is lost, SIPs still flow), "deaf off" heals it.
// A port of its own because the
// status socket's readers (localisation, laser emulator, judges) must never be able to move
// the robot by a stray line.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "amigobot_tracking/core/support/types.h"
#include "amigobot_tracking/link/emulator_link.h"

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

// Line-based client of the status socket over the robot link's TCP transport (link::TcpClient). Never blocks longer than
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

// Empty when `line` is "teleport x y theta" with finite values within 1e4 m (then *pose holds
// it), else what is wrong.
std::string parseControlLine(const std::string& line, core::Pose2* pose);
// Empty when `line` is "deaf on" or "deaf off" (then *deaf holds it), else what is wrong.
std::string parseDeafLine(const std::string& line, bool* deaf);
// The line parseControlLine reads back exactly (%.17g), without the line break.
std::string formatTeleportLine(const core::Pose2& pose);

// Teleports (and the deaf switch) posted by the control socket's thread and taken by the
// emulator's own loop, which alone touches the RobotEmulator.
class TeleportMailbox {
 public:
  void post(const core::Pose2& pose);
  // The latest pose posted since the last take, once.
  std::optional<core::Pose2> take();
  void setDeaf(bool deaf) { deaf_ = deaf; }
  bool deaf() const { return deaf_; }

 private:
  std::mutex mutex_;
  std::optional<core::Pose2> pending_;
  std::atomic<bool> deaf_{false};
};

// Sends one control line (formatTeleportLine, "deaf on", ...) to the control socket at
// host:port; empty once it said "ok", else why not (naming the socket). Waits at most
// `timeout` [s] for the answer.
std::string requestControl(const std::string& host, int port, const std::string& line, double timeout);

// The control socket on a thread of its own (the emulator's poll loop is not ours to extend).
class ControlServer {
 public:
  // Listens on bind_address:port (0: any free port); throws std::runtime_error naming the address.
  ControlServer(TeleportMailbox& mailbox, const std::string& bind_address, int port);
  ~ControlServer();
  ControlServer(const ControlServer&) = delete;
  ControlServer& operator=(const ControlServer&) = delete;
  int port() const { return listener_.port(); }

 private:
  void run();
  bool answer(int fd, const std::string& line);  // false: close the client

  TeleportMailbox& mailbox_;
  link::TcpListener listener_;
  link::LineClients clients_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// Asks the control socket at host:port to teleport the robot to `pose`; empty once it said
// "ok", else why not (naming the socket). Waits at most `timeout` [s] for the answer.
std::string requestTeleport(const std::string& host, int port, const core::Pose2& pose, double timeout);

}  // namespace aria
}  // namespace amigobot_tracking

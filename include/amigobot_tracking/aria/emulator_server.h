// I/O around RobotEmulator: the robot port over TCP (one client at a time, like the one
// serial port of a robot: a new connection replaces the old one) and over a pseudo-terminal
// with a stable symlink (a modelled UART: aria/emulator_line.h), plus a line-based status socket that answers every line with the
// ground-truth status line. The sockets and the pty are link/emulator_link.h's, shared with
// the laser emulator; the poll() loop is the robot's own.
#pragma once

#include <atomic>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "amigobot_tracking/aria/emulator.h"
#include "amigobot_tracking/aria/emulator_line.h"
#include "amigobot_tracking/link/emulator_link.h"

namespace amigobot_tracking {
namespace aria {

struct EmulatorServerOptions {
  int tcp_port = 8101;          // robot port; 0 = any free port; -1 = none
  std::string bind_address = "127.0.0.1";
  std::string pty_link;         // symlink to the pty's slave; empty = no pty
  int status_port = -1;         // ground-truth status; 0 = any free port; -1 = none
  double time_scale = 1.0;      // emulated seconds per wall second
  double corrupt_probability = 0.0;  // per robot packet: flip a byte, cut it or prefix garbage
  std::uint32_t corrupt_seed = 1;
};

class EmulatorServer {
 public:
  EmulatorServer(RobotEmulator& robot, EmulatorServerOptions options);
  ~EmulatorServer();
  EmulatorServer(const EmulatorServer&) = delete;
  EmulatorServer& operator=(const EmulatorServer&) = delete;

  // Opens the listening sockets and the pty; throws std::runtime_error naming what failed.
  void open();
  int tcpPort() const { return tcp_listen_.port(); }
  int statusPort() const { return status_listen_.port(); }
  const std::string& ptyName() const { return pty_terminal_.name(); }
  // Serves until `stop` becomes true (checked at least every 10 ms).
  void run(const std::atomic<bool>& stop);

 private:
  struct Link {
    int fd = -1;
    PacketParser parser;
  };
  double now() const;
  void acceptRobotClient();
  void readLink(Link& link, bool is_tcp);
  void sendToActive(const std::vector<std::uint8_t>& bytes);
  void flushPtyLine();  // the robot's paced bytes that have left its UART by now
  void dropTcpClient();
  void serveStatus(std::size_t index, bool& quit);

  RobotEmulator& robot_;
  EmulatorServerOptions options_;
  link::TcpListener tcp_listen_, status_listen_;
  link::PseudoTerminal pty_terminal_;
  Link tcp_client_, pty_;  // pty_.fd is pty_terminal_'s master
  bool tcp_active_ = true;  // where the robot's replies go: the link that spoke last
  link::LineClients status_clients_;
  double start_wall_ = 0.0;
  std::mt19937 noise_;
  std::uint64_t corrupted_ = 0;
  SerialLineModel pty_line_;  // baud and pacing of the pty (TCP has neither)
};

}  // namespace aria
}  // namespace amigobot_tracking

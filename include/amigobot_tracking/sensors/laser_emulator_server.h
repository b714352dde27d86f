// I/O of the laser emulator: one client at a time over TCP (a new connection replaces the
// old one, as a device with one host) and, for SCIP and RPLIDAR, over a pseudo-terminal with
// a stable symlink (the URG's USB-ACM port, the RPLIDAR's USB-serial adapter). A scan is cast
// at the model's rate from the robot pose the status source gives, and streamed to the
// client that asked for it: at once when its last beam is measured, or for a RPLIDAR, whose
// nodes leave as they are measured, paced over the revolution. Faults on request
// damage every n-th streamed scan telegram. The socket and the pty are link/emulator_link.h's,
// shared with the robot emulator; the poll() loop and the pacing are the laser's own.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "amigobot_tracking/core/support/types.h"
#include "amigobot_tracking/link/emulator_link.h"
#include "amigobot_tracking/sensors/laser_model.h"
#include "amigobot_tracking/sensors/laser_session.h"
#include "amigobot_tracking/sensors/scan_source.h"

namespace amigobot_tracking {
namespace sensors {

enum class Fault { kNone, kMalformed, kTruncated, kChecksum, kStall, kDisconnect };
// none | malformed | truncated | checksum | stall | disconnect; throws naming the bad value.
Fault parseFault(const std::string& name);

struct LaserServerOptions {
  int tcp_port = 10940;  // 0 = any free port; -1 = none
  std::string bind_address = "127.0.0.1";
  std::string pty_link;  // SCIP and RPLIDAR only; empty = none
  Fault fault = Fault::kNone;
  int fault_every = 0;        // damage scan telegram n, 2n, ... (0 = never)
  double stall_time = 2.0;    // [s] silence of a stall
  std::string serial = "H0000001";

  void validate(const LaserModel& model) const;  // throws naming the bad option
};

// The model laser_emulator serves: the entry's, with the scan --scan-frequency and
// --resolution ask for (nullopt: not given, the entry's own). A model whose entry has no
// scan_setting refuses either option: std::invalid_argument naming the option, the model and
// the models that take one; a bad value is the setting's own error.
LaserModel emulatedLaserModel(const std::string& name, std::optional<double> frequency_hz,
                              std::optional<double> resolution_deg);
// "sick_lms1xx: 25 Hz at 0.5 | 0.25 deg, ...": the models with a scan to choose, for help texts.
std::string scanSettingChoices();

// The robot's pose at emulator time: false when it is not known (then no scan is sent).
using PoseSource = std::function<bool(core::Pose2* base, double* t)>;

class LaserEmulatorServer {
 public:
  LaserEmulatorServer(LaserModel model, ScanSource source, PoseSource pose, LaserServerOptions options);
  ~LaserEmulatorServer();
  LaserEmulatorServer(const LaserEmulatorServer&) = delete;
  LaserEmulatorServer& operator=(const LaserEmulatorServer&) = delete;

  void open();  // throws std::runtime_error naming what failed
  int tcpPort() const { return listener_.port(); }
  const std::string& ptyName() const { return pty_terminal_.name(); }
  void run(const std::atomic<bool>& stop);  // checks `stop` at least every 10 ms
  // Faults switched on and off while it runs (laser_emulator: SIGUSR1, SIGUSR2), read at each
  // scan; null: never. `blind`: every beam reports no return (each protocol's own "nothing
  // within range", as in an empty world): a laser that lost its echo. `halve`: every other
  // scan is not sent (a saturated link or an overloaded device): half the promised rate.
  void setLiveFaults(const std::atomic<bool>* blind, const std::atomic<bool>* halve) {
    blind_ = blind;
    halve_ = halve;
  }

 private:
  struct Link {
    int fd = -1;
    std::unique_ptr<LaserSession> session;
    std::string paced;             // RPLIDAR: the revolution being sent
    std::size_t paced_sent = 0;    // bytes of it already sent
    double paced_from = 0.0, paced_rate = 0.0;  // [s], [bytes/s]
  };
  void accept();
  void drop(Link& link);
  void serve(Link& link);
  void tick();
  void send(double now);  // streams latest_ to the clients that asked for scans
  void drain(Link& link, double now);  // sends the paced bytes that are due
  std::string damage(std::string telegram);

  LaserModel model_;
  ScanSource source_;
  PoseSource pose_;
  LaserServerOptions options_;
  link::TcpListener listener_;
  link::PseudoTerminal pty_terminal_;
  Link tcp_, pty_;  // pty_.fd is pty_terminal_'s master
  EmulatedScan latest_, pending_;  // last sent; cast but not yet sent
  bool has_pending_ = false;
  double next_scan_ = 0.0, stall_until_ = 0.0, pending_due_ = 0.0;
  std::uint64_t streamed_ = 0, cast_ = 0;
  const std::atomic<bool>* blind_ = nullptr;
  const std::atomic<bool>* halve_ = nullptr;
};

}  // namespace sensors
}  // namespace amigobot_tracking

// The robot driver without ROS (kobuki_driver style): owns the link, runs the handshake,
// keeps the robot's 2 s watchdog fed, turns the latest velocity request into VEL+RVEL or
// VEL2 commands that are never outside the diamond, integrates odometry from SIPs and
// reconnects with back-off when the link is lost. All I/O runs on one thread.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "amigobot_tracking/aria/acknowledgement_watch.h"
#include "amigobot_tracking/aria/odometry.h"
#include "amigobot_tracking/aria/packet.h"
#include "amigobot_tracking/aria/robot_params.h"
#include "amigobot_tracking/aria/sip.h"
#include "amigobot_tracking/aria/transport.h"
#include "amigobot_tracking/aria/wheel_command.h"
#include "amigobot_tracking/core/support/field_table.h"

namespace amigobot_tracking {
namespace aria {

struct ClientConfig {
  std::string port = "/dev/ttyUSB0";  // serial device, or host:port for TCP
  int baud = 9600;                    // [baud] serial only: the connect baud; after CONFIG
                                      // the link moves to robot.switch_to_baud if the robot allows
  RobotParams robot = RobotParams::amigo();
  CommandMode command_mode = CommandMode::kVelRvel;
  // The diamond every command is checked against is the robot description's (robot.v_max,
  // robot.w_max: the robot file); these may tighten it (0 = the robot's), never widen it.
  double v_max = 0.0;                 // [m/s] diamond half-width in v; 0 = robot.v_max
  double w_max = 0.0;                 // [rad/s] diamond half-width in w; 0 = robot.w_max
  double command_timeout = 0.6;       // [s] a request older than this becomes a stop; 0 = never
  double command_refresh = 0.5;       // [s] motion command re-sent at least this often (watchdog 2 s)
  double min_command_interval = 0.05; // [s] at most one motion command per this (serial bandwidth)
  double sync_timeout = 1.0;          // [s] wait for each SYNC reply (ARIA: 1000 ms)
  int max_sync_tries = 20;            // SYNC packets sent per connection attempt
  double config_timeout = 1.0;        // [s] wait for CONFIGpac; 0 = do not request it
  double command_ack_timeout = 0.3;   // [s] ENCODER probes unanswered this long while SIPs arrive:
                                      // the robot does not hear us (one-way link); 0 = no probes
  double link_timeout = 2.0;          // [s] without a SIP -> link lost (ARIA: 8 s). A false
                                      // alarm costs a re-handshake, which CLOSEs the robot
  double reconnect_delay_min = 0.5;   // [s] first back-off after a failure
  double reconnect_delay_max = 8.0;   // [s] back-off doubles up to this
  bool enable_motors = false;         // request ENABLE 1 after every (re)connection
  bool sonar = true;                  // SONAR 1 / SONAR 0 after OPEN
  bool open_with_argument = true;     // ARIA sends OPEN int 1; false sends a bare OPEN (p2os)
  int max_packet_count = kMaxSpecCount;  // parser limit on the count byte (ARIA: 255)
  double trans_accel = 0.0, trans_decel = 0.0;  // [m/s^2] SETA when > 0; 0 = firmware's
  double rot_accel = 0.0, rot_decel = 0.0;      // [rad/s^2] SETRA when > 0
  // Odometry calibration (RosAria's TicksMM, DriftFactor, RevCount), sent after CONFIG when
  // non-zero and read back from a second CONFIGpac. 0 = not sent: the FLASH value holds.
  int ticks_mm = 0;      // [ticks/mm]
  int drift_factor = 0;  // [1/8192]
  int rev_count = 0;     // [ticks per 180 deg turn]

  // Empty when valid, otherwise "key: reason" for the first bad field (the table's bounds,
  // then the robot's limits, its watchdog and the back-off order).
  std::string validate() const;
  // The diamond in force: v_max/w_max where set, else the robot's.
  core::DiamondSet diamond() const;
};

// The plain fields (robot and command_mode are chosen by name: see ros/driver.h). Keys are the
// driver's ROS parameters (cmd_vel_timeout: the command_timeout member). The live rows are
// the motion limits, which may change while the client runs (the driver's
// dynamic_reconfigure, cfg/Driver.cfg names them).
const core::FieldTable<ClientConfig>& clientFields();

enum class LinkState { kStopped, kConnecting, kConnected, kWaitingToReconnect };
std::string linkStateName(LinkState state);

// Everything one SIP tells, in SI units.
struct RobotState {
  double stamp = 0.0;          // [s] steady clock when the SIP was parsed
  OdometryState odometry;      // pose in the odom frame, twist measured by the robot
  double battery_voltage = 0.0;  // [V]
  bool motors_enabled = false;
  bool left_stall = false, right_stall = false;
  std::vector<double> sonar_ranges;   // [m] per transducer, latest reading (NaN: none yet)
  std::vector<bool> sonar_updated;    // which transducers this SIP refreshed
  Sip sip;                            // the raw packet
};

struct ClientStatus {
  LinkState link = LinkState::kStopped;
  std::optional<RobotIdentity> identity;
  std::optional<ConfigPac> config;
  ParserStats parser;
  std::uint64_t sips = 0;
  double sip_rate = 0.0;          // [Hz] over the last second
  std::uint64_t connections = 0;  // successful handshakes
  std::uint64_t still_open_recoveries = 0;  // SIPs answered a SYNC: robot left open
  std::uint64_t baud_recoveries = 0;        // CLOSE cycles through every baud after silent SYNCs
  int baud = 0;                             // [baud] active line speed; 0 on TCP
  std::uint64_t bytes_received = 0, bytes_sent = 0;  // on the link, every connection
  std::uint64_t commands_sent = 0;
  std::uint64_t non_finite_requests = 0;    // NaN/inf velocity requests refused
  std::string last_error;
  bool motors_requested = false;
  std::optional<QuantizedCommand> last_command;
  AcknowledgementState acknowledgement = AcknowledgementState::kOff;  // does the robot hear us?
  double unanswered_for = 0.0;  // [s] the oldest unanswered probe's age
  std::uint64_t probes_sent = 0, probes_answered = 0;
  std::optional<RobotState> robot;  // latest SIP
};

enum class LogLevel { kDebug, kInfo, kWarn, kError };
using LogFunction = std::function<void(LogLevel, const std::string&)>;
using SipCallback = std::function<void(const RobotState&)>;

class AriaClient {
 public:
  // ENCODER 1 every 0.1 s: 9 bytes out and a 14-byte answer (90 + 140 B/s) beside 10 SIPs of
  // up to 65 bytes (650 B/s) fits 9600 baud (960 B/s) and leaves 38400 nearly idle. With
  // probes and SIPs every 0.1 s, a lost direction is named within period +
  // command_ack_timeout + one SIP cycle (0.5 s with the default 0.3 s).
  static constexpr double kAckProbePeriod = 0.1;       // [s]
  static constexpr double kAckProbeSupportWait = 2.0;  // [s] no answer at all by then: no ENCODER in the firmware

  // Throws std::invalid_argument if config.validate() fails.
  explicit AriaClient(ClientConfig config, LogFunction log = {});
  ~AriaClient();
  AriaClient(const AriaClient&) = delete;
  AriaClient& operator=(const AriaClient&) = delete;

  // Called on the I/O thread after every SIP; keep it short. Set before start().
  void setSipCallback(SipCallback callback) { sip_callback_ = std::move(callback); }
  void start();
  // Stops the robot (zero velocity, ENABLE 0, CLOSE) and joins the I/O thread.
  void stop();

  // Latest velocity request; a non-finite one is refused and counted (the robot stops).
  void setVelocity(const core::Twist2& twist);
  void requestMotors(bool enabled);
  void resetOdometry(const core::Pose2& pose = {});
  // The live rows of clientFields() in `limits` (the rest is ignored), checked as
  // ClientConfig::validate does; valid ones take effect before the next command (SETA/SETRA
  // for the positive accelerations). Returns "" or "field: reason".
  std::string setMotionLimits(const ClientConfig& limits);
  // The config with the limits in force, or about to be (set but not yet applied).
  ClientConfig motionLimits() const;
  ClientStatus status() const;
  const ClientConfig& config() const { return config_; }

 private:
  using Clock = std::chrono::steady_clock;
  void run();
  bool connect();                 // one full handshake attempt; false if stopped
  // SYNC0/1/2 with the still-open recovery; nullopt if stopped, throws after max tries.
  std::optional<RobotIdentity> synchronise();
  // OPEN, SONAR, CONFIG (with retries), HOSTBAUD, SETA/SETRA; waits for the first SIP.
  std::optional<ConfigPac> openRobot();
  // Serial, robot allows it (CONFIGpac AutoBaud 2): HOSTBAUD to robot.switch_to_baud, kept
  // only if a SIP arrives at the new rate within 900 ms.
  void negotiateBaud(const std::optional<ConfigPac>& config);
  // CLOSE at every baud a crashed session may have left the robot at, back to the connect baud.
  void closeAtEveryBaud();
  void setLineBaud(int baud);
  // POLLING from the parameter set; TICKSMM/DRIFTFACTOR/REVCOUNT, then CONFIG to read them
  // back (logged). Returns the newer CONFIGpac, or `config` when none came.
  std::optional<ConfigPac> configureFirmware(std::optional<ConfigPac> config);
  // CONFIG, re-requested every 200 ms up to config_timeout; nullopt when none came.
  std::optional<ConfigPac> requestConfig(bool& have_sip);     // switches the port and forgets bytes parsed at the old rate
  // Pumps the link for up to `duration` [s], handing each packet to `on_packet` until it
  // returns true (then returns true).
  bool receiveFor(double duration, const std::function<bool(const Packet&)>& on_packet);
  void serve();                   // connected: until link loss or stop
  void shutdownRobot();
  bool sleepUnlessStopped(double seconds);
  void send(const std::vector<std::uint8_t>& bytes);
  // Reads whatever arrives within timeout and feeds the parser.
  void pump(int timeout_ms);
  bool nextPacket(Packet& packet);
  void handlePacket(const Packet& packet);
  void handleSip(const Sip& sip);
  void updateCommand(Clock::time_point now);
  // ENCODER 1 every kProbePeriod; the state and its changes (logged) into status_.
  void probeAcknowledgement(Clock::time_point now);
  void applyPendingLimits();      // I/O thread
  void sendAccelerations();       // SETA/SETRA for config_'s positive accelerations
  void setLink(LinkState state);
  void log(LogLevel level, const std::string& text);

  ClientConfig config_;
  LogFunction log_;
  SipCallback sip_callback_;
  core::DiamondSet diamond_;
  std::unique_ptr<Transport> transport_;
  PacketParser parser_;
  SipOdometry odometry_;
  std::thread thread_;
  std::atomic<bool> stop_requested_{false};
  std::mutex wake_mutex_;
  std::condition_variable wake_;

  // Shared with callers (mutex_).
  mutable std::mutex mutex_;
  ClientStatus status_;
  core::Twist2 requested_;
  Clock::time_point requested_at_{};
  bool have_request_ = false;
  bool motors_request_pending_ = false;
  std::optional<core::Pose2> odometry_reset_;
  std::optional<ClientConfig> pending_limits_;  // the config with the new limits

  // I/O thread only.
  Clock::time_point last_rx_{}, last_sip_{}, last_motion_sent_{}, last_enable_sent_{};
  std::optional<QuantizedCommand> sent_;
  std::vector<Clock::time_point> sip_times_;
  std::vector<double> sonar_ranges_;
  AcknowledgementWatch ack_watch_;
};

}  // namespace aria
}  // namespace amigobot_tracking

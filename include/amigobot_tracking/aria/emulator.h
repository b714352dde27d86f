// The robot side of the protocol as an AmigoBot's firmware does it, without I/O: a
// kinematic stub (a unicycle behind core::ActuatorModel: ramps, cycle, latency, wheel limit), the firmware's own
// odometry in its units and wrap, sonar from the world (disks, walls, polygons), the 2 s watchdog. With
// `simulator_mode` it reproduces a MobileSim-like ARIA simulator instead.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <ostream>
#include <string>
#include <vector>

#include "amigobot_tracking/aria/emulator_status.h"
#include "amigobot_tracking/aria/packet.h"
#include "amigobot_tracking/aria/robot_params.h"
#include "amigobot_tracking/aria/sip.h"
#include "amigobot_tracking/core/robot/actuator_model.h"
#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/core/support/types.h"
#include "amigobot_tracking/world/world.h"

namespace amigobot_tracking {
namespace aria {

struct EmulatorOptions {
  RobotParams robot = RobotParams::amigo();
  std::string name = "amigo-emulator";   // SYNC2 name
  bool simulator_mode = false;  // motors start enabled, SIPs always 0x32, watchdog only warns,
                                // SYNC0 while open = PULSE, a client disconnect closes the robot
  world::World world;   // the room (world/world.h) the sonar sees; its initial_pose is unused
                        // (initial_pose below)
  core::Pose2 initial_pose;              // [m, m, rad] ground truth at start
  double odometry_noise = 0.0;  // [-] relative std-dev of the wheel speeds the firmware integrates
  std::uint32_t seed = 1;
  double battery_voltage = 12.6;  // [V]
  double sonar_max_range = 5.0;   // [m] reported when nothing is in the cone
  double sonar_half_cone = 0.2;   // [rad] half opening angle of a transducer's cone
  double physics_step = 0.01;     // [s]
  // FLASH calibration: the encoders' true ticks per mm and per half turn. Arbitrary values:
  // only the ratio to what a client sets (TICKSMM, REVCOUNT) scales the odometry.
  int ticks_mm = 128;
  int rev_count = 16384;
  int left_open_at_baud = 0;      // [baud] > 0: starts open, talking at this baud, as a crashed
                                  // session leaves it; 0: closed at the FLASH default 9600
  std::string validate() const;   // "" or "key: reason"
};

// Its plain fields (the robot, world, pose and seed are set by the emulator tool).
const core::FieldTable<EmulatorOptions>& emulatorFields();

struct EmulatorCounters {
  std::uint64_t packets = 0;
  std::uint64_t sips_sent = 0;
  std::uint64_t watchdog_trips = 0;  // firmware: stops; simulator: warnings
  std::uint64_t opens = 0;
  std::uint64_t closes = 0;
  std::uint64_t unknown_commands = 0;
  std::uint64_t unheard_packets = 0;  // arrived while deaf (the driver -> robot direction cut)
  std::uint64_t commands_while_closed = 0;
};

class RobotEmulator {
 public:
  static constexpr int kFlashBaud = 9600;  // the HostBaud the firmware returns to on CLOSE

  explicit RobotEmulator(EmulatorOptions options);

  // A complete client packet at time `now` [s]; returns the bytes to send back (its reply;
  // SIPs come only from advance(), even when one is due at `now`).
  std::vector<std::uint8_t> handle(const Packet& packet, double now);
  // Advances the kinematics to `now`; returns a SIP when one is due (else empty).
  std::vector<std::uint8_t> advance(double now);
  // The client's link went away (TCP socket closed). Firmware keeps its state (a serial
  // cable pulled out); a simulator closes the robot.
  void clientDisconnected();

  bool isOpen() const { return open_; }
  // [baud] the robot's UART: 9600 after CLOSE, HOSTBAUD changes it while open (serial only:
  // the server applies it to the pseudo-terminal, TCP ignores it).
  int baud() const { return baud_; }
  bool motorsEnabled() const { return motors_; }
  const core::Pose2& truePose() const { return pose_; }
  core::Twist2 trueTwist() const { return {v_, w_}; }
  bool watchdogTripped() const { return watchdog_tripped_; }
  const EmulatorCounters& counters() const { return counters_; }
  const EmulatorOptions& options() const { return options_; }
  // Ground truth at `now` [s] for the status socket (aria/emulator_status.h).
  EmulatorStatus status(double now) const;
  // Sonar ranges [m] for the current true pose.
  std::vector<double> sonarRanges() const;
  // Journal of what reached the robot on the wire: after every motion command (VEL, RVEL,
  // ROTATE, VEL2, STOP, E-STOP) one line "t command v w" with the setpoints it now holds
  // (SI units, before the speed limits), flushed at once. Tests judge the stack by it.
  void setCommandLog(std::ostream* log) { command_log_ = log; }
  // A kidnap: the true pose jumps to `pose`; the firmware's odometry, the wheel speeds and
  // the setpoints carry on as they were (the robot was lifted and put down, its encoders saw
  // nothing). Throws std::invalid_argument for a non-finite pose.
  void teleport(const core::Pose2& pose);
  // Teleports and deafness posted from another thread (the control socket,
  // aria/emulator_status.h), taken at the start of every handle() and advance(); null: none.
  // While deaf, handle() drops every packet unheard (no answer, the watchdog not fed) while
  // SIPs still flow: a link whose driver -> robot direction is cut.
  void setTeleportMailbox(TeleportMailbox* mailbox) { teleports_ = mailbox; }

 private:
  void journal(double now, const char* command) const;
  void stepPhysics(double dt);
  // Physics and watchdog up to `now`, without sending anything.
  void stepTo(double now);
  void checkWatchdog(double now);
  void close();
  std::vector<std::uint8_t> makeSip();
  void setTarget(double v, double w);
  void syncLimits();  // the firmware's current accelerations into base_

  EmulatorOptions options_;
  std::mt19937 rng_;
  bool open_ = false;
  int baud_ = kFlashBaud;
  int sync_stage_ = 0;  // 0 waiting for SYNC0 ... 3 synchronised, waiting for OPEN
  bool motors_ = false;
  bool sonar_on_ = true;
  // Setpoints: either (v, w) or wheel speeds from VEL2, all SI.
  double target_v_ = 0.0, target_w_ = 0.0;
  double requested_v_ = 0.0, requested_w_ = 0.0;  // as decoded, before the speed limits
  std::ostream* command_log_ = nullptr;
  TeleportMailbox* teleports_ = nullptr;
  double max_v_, max_w_;  // SETV / SETRV
  double accel_, decel_, rot_accel_, rot_decel_;  // SETA / SETRA, reported in the CONFIGpac
  std::optional<core::ActuatorModel> base_;  // the wheels: ramps, cycle, latency, wheel limit
  double v_ = 0.0, w_ = 0.0;  // actual (base_'s velocity)
  core::Pose2 pose_;          // ground truth
  double odo_x_mm_ = 0.0, odo_y_mm_ = 0.0, odo_th_ = 0.0;  // firmware odometry
  double left_ticks_ = 0.0, right_ticks_ = 0.0;  // encoder counts (ENCODER answers them)
  bool deaf_ = false;  // the control socket's "deaf on": every client packet is lost on the way
  double last_time_ = -1.0, last_command_ = 0.0, next_sip_ = 0.0;
  bool watchdog_tripped_ = false;
  std::size_t next_sonar_ = 0;       // position in the firing order
  std::vector<std::size_t> polling_;  // firing order (POLLING); empty: 0, 1, 2, ...
  int ticks_mm_, rev_count_, drift_factor_ = 0;  // working calibration (TICKSMM, ...)
  EmulatorCounters counters_;
};

}  // namespace aria
}  // namespace amigobot_tracking

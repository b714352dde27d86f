// ClientConfig's field table and its validation.
#include <string>

#include "amigobot_tracking/aria/client.h"

namespace amigobot_tracking {
namespace aria {

const core::FieldTable<ClientConfig>& clientFields() {
  using C = ClientConfig;
  using core::field;
  using core::live;
  using core::nonNegative;
  using core::positive;
  static const core::FieldTable<C> table = {
      field("port", &C::port, "-",
            "serial device, or host:port for TCP (amigobot_emulator, an ARIA simulator or a serial-to-TCP bridge)"),
      field("baud", &C::baud, "baud",
            "serial only: the connect baud. After CONFIG the link moves to the robot file's switch_to_baud "
            "(HOSTBAUD) when higher and CONFIGpac's AutoBaud allows it, kept only if a SIP arrives within 900 ms. "
            "Unanswered SYNCs: CLOSE at 9600, 38400, 115200, 19200, 57600 (a robot a crashed session left open at "
            "another baud), then OPEN to dislodge; every reconnect repeats it",
            core::atLeast(1)),
      live(field("v_max", &C::v_max, "m/s",
                 "tightens the robot file's v_max, the diamond's half-width in v that every command is checked "
                 "against (set there); 0 = the robot's. Above the robot's is refused, at start and on reconfigure; "
                 "set (> 0), it is named in a WARN at start",
                 nonNegative()),
           0.0, 2.0),
      live(field("w_max", &C::w_max, "rad/s",
                 "tightens the robot file's w_max, the diamond's half-width in omega; 0 = the robot's. Above the "
                 "robot's is refused, at start and on reconfigure; set (> 0), it is named in a WARN at start",
                 nonNegative()),
           0.0, 10.0),
      live(field("cmd_vel_timeout", &C::command_timeout, "s",
                 "a cmd_vel older than this becomes a stop (zero velocity); 0 = never", core::boundedTimeoutOrOff()),
           0.0, 10.0),
      field("command_refresh", &C::command_refresh, "s",
            "a motion command is re-sent at least this often, feeding the firmware watchdog; must stay below the "
            "robot file's watchdog",
            core::duration()),
      field("min_command_interval", &C::min_command_interval, "s",
            "at most one changed motion command per this (serial bandwidth)", nonNegative()),
      field("sync_timeout", &C::sync_timeout, "s", "wait for each SYNC reply (ARIA: 1000 ms)", core::boundedTimeout()),
      field("max_sync_tries", &C::max_sync_tries, "-",
            "SYNC packets sent per connection attempt, at least 3 (the recoveries: see baud)", core::atLeast(3)),
      field("config_timeout", &C::config_timeout, "s",
            "wait for CONFIGpac, CONFIG re-sent every 200 ms; 0 = do not request it (then no baud switch and no "
            "calibration read-back)",
            core::boundedTimeoutOrOff()),
      field("command_ack_timeout", &C::command_ack_timeout, "s",
            "the driver probes with ENCODER 1 every 0.1 s; unanswered this long while SIPs still arrive -> one-way "
            "link (the robot does not hear the driver): throttled ERROR and diagnostics ERROR one-way link. A "
            "firmware that never answers in the first 2 s gets one WARN and no more probes. 0 = no probes",
            core::boundedTimeoutOrOff()),
      field("link_timeout", &C::link_timeout, "s",
            "no SIP for this long -> link lost, reconnect with back-off (ARIA: 8 s; a false alarm costs a "
            "re-handshake, which CLOSEs the robot); also the wait for the first SIP after OPEN",
            core::boundedTimeout()),
      field("reconnect_delay_min", &C::reconnect_delay_min, "s",
            "first back-off after a failure (again after every successful connection)", core::duration()),
      field("reconnect_delay_max", &C::reconnect_delay_max, "s",
            "back-off ceiling: the back-off doubles after each failed attempt up to this (not below "
            "reconnect_delay_min)",
            core::duration()),
      field("enable_motors", &C::enable_motors, "-",
            "ENABLE 1 after every (re)connection; false: the motors stay disabled until the enable_motors service"),
      field("sonar", &C::sonar, "-", "SONAR 1 after OPEN (false: SONAR 0, the transducers stay silent)"),
      field("open_with_argument", &C::open_with_argument, "-",
            "OPEN with int 1 as ARIA does; false: a bare OPEN (p2os)"),
      field("max_packet_count", &C::max_packet_count, "-",
            "parser limit on a packet's count byte, 3..255 (the protocol spec says 200, ARIA accepts 255)",
            core::interval(3, false, 255, false)),
      live(field("trans_accel", &C::trans_accel, "m/s^2",
                 "sent as SETA after every OPEN and on reconfigure when > 0; 0 = keep the firmware's value",
                 nonNegative()),
           0.0, 5.0),
      live(field("trans_decel", &C::trans_decel, "m/s^2",
                 "sent as SETA with a negative argument (the deceleration) after every OPEN and on reconfigure when "
                 "> 0; 0 = keep the firmware's value",
                 nonNegative()),
           0.0, 5.0),
      live(field("rot_accel", &C::rot_accel, "rad/s^2",
                 "sent as SETRA after every OPEN and on reconfigure when > 0; 0 = keep the firmware's value",
                 nonNegative()),
           0.0, 20.0),
      live(field("rot_decel", &C::rot_decel, "rad/s^2",
                 "sent as SETRA with a negative argument (the deceleration) after every OPEN and on reconfigure "
                 "when > 0; 0 = keep the firmware's value",
                 nonNegative()),
           0.0, 20.0),
      field("ticks_mm", &C::ticks_mm, "ticks/mm",
            "TICKSMM after CONFIG when not 0, read back from a new CONFIGpac and logged (WARN if the firmware "
            "ignored it); 0 = not sent, the FLASH value holds. RosAria's TicksMM is read as an alias",
            core::interval(0, false, 65535, false)),
      field("drift_factor", &C::drift_factor, "1/8192",
            "DRIFTFACTOR after CONFIG when not 0, -32768..32767, read back from a new CONFIGpac and logged; 0 = not "
            "sent, the FLASH value holds. RosAria's DriftFactor is read as an alias",
            core::interval(-32768, false, 32767, false)),
      field("rev_count", &C::rev_count, "ticks/180deg",
            "REVCOUNT after CONFIG when not 0, read back from a new CONFIGpac and logged; 0 = not sent, the FLASH "
            "value holds. RosAria's RevCount is read as an alias",
            core::interval(0, false, 65535, false)),
  };
  return table;
}

core::DiamondSet ClientConfig::diamond() const {
  return core::DiamondSet(v_max > 0.0 ? v_max : robot.v_max, w_max > 0.0 ? w_max : robot.w_max);
}

std::string ClientConfig::validate() const {
  const std::string bad = core::checkFields(clientFields(), *this);
  if (!bad.empty()) return bad;
  if (port.empty()) return "port: empty (expected /dev/ttyUSB0 or host:port)";
  const std::string robot_error = robot.validate();
  if (!robot_error.empty()) return "robot." + robot_error;
  const std::string wider = core::diamondInsideError(robot, v_max, w_max, "v_max", "w_max", robot.origin());
  if (!wider.empty()) return wider + ": the robot's diamond is set in its robot file, a driver limit only tightens it";
  if (command_refresh >= robot.watchdog) {
    return "command_refresh: must be well below the robot's " + std::to_string(robot.watchdog) + " s watchdog";
  }
  if (reconnect_delay_max < reconnect_delay_min) return "reconnect_delay_max: smaller than reconnect_delay_min";
  return {};
}

}  // namespace aria
}  // namespace amigobot_tracking

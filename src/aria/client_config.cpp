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
      field("port", &C::port, "-", "serial device, or host:port for TCP"),
      field("baud", &C::baud, "baud", "serial only", core::atLeast(1)),
      live(field("v_max", &C::v_max, "m/s", "tightens the robot file's v_max, the diamond every command is checked against; 0 = the robot's",
                 nonNegative())),
      live(field("w_max", &C::w_max, "rad/s", "tightens the robot file's w_max; 0 = the robot's", nonNegative())),
      live(field("cmd_vel_timeout", &C::command_timeout, "s", "a request older than this becomes a stop; 0 = never",
                 core::boundedTimeoutOrOff())),
      field("command_refresh", &C::command_refresh, "s", "motion command re-sent at least this often", core::duration()),
      field("min_command_interval", &C::min_command_interval, "s", "at most one motion command per this",
            nonNegative()),
      field("sync_timeout", &C::sync_timeout, "s", "wait for each SYNC reply", core::boundedTimeout()),
      field("max_sync_tries", &C::max_sync_tries, "-", "SYNC packets sent per connection attempt", core::atLeast(3)),
      field("config_timeout", &C::config_timeout, "s", "wait for CONFIGpac; 0 = do not request it",
            core::boundedTimeoutOrOff()),
      field("command_ack_timeout", &C::command_ack_timeout, "s",
            "probes (ENCODER) unanswered this long while SIPs arrive: one-way link, named; 0 = no probes",
            core::boundedTimeoutOrOff()),
      field("link_timeout", &C::link_timeout, "s", "no SIP for this long -> link lost, reconnect",
            core::boundedTimeout()),
      field("reconnect_delay_min", &C::reconnect_delay_min, "s", "first back-off after a failure", core::duration()),
      field("reconnect_delay_max", &C::reconnect_delay_max, "s", "back-off ceiling (doubles up to it)", core::duration()),
      field("enable_motors", &C::enable_motors, "-", "ENABLE 1 after every (re)connection"),
      field("sonar", &C::sonar, "-", "SONAR 1 after OPEN (false: SONAR 0)"),
      field("open_with_argument", &C::open_with_argument, "-", "OPEN int 1 as ARIA; false: a bare OPEN (p2os)"),
      field("max_packet_count", &C::max_packet_count, "-", "parser limit on the count byte",
            core::interval(3, false, 255, false)),
      live(field("trans_accel", &C::trans_accel, "m/s^2", "SETA when > 0; 0 = the firmware's", nonNegative())),
      live(field("trans_decel", &C::trans_decel, "m/s^2", "SETA (decel) when > 0; 0 = the firmware's", nonNegative())),
      live(field("rot_accel", &C::rot_accel, "rad/s^2", "SETRA when > 0; 0 = the firmware's", nonNegative())),
      live(field("rot_decel", &C::rot_decel, "rad/s^2", "SETRA (decel) when > 0; 0 = the firmware's", nonNegative())),
      field("ticks_mm", &C::ticks_mm, "ticks/mm", "TICKSMM after CONFIG, read back; 0 = not sent (FLASH)",
            core::interval(0, false, 65535, false)),
      field("drift_factor", &C::drift_factor, "1/8192", "DRIFTFACTOR after CONFIG, read back; 0 = not sent",
            core::interval(-32768, false, 32767, false)),
      field("rev_count", &C::rev_count, "ticks/180deg", "REVCOUNT after CONFIG, read back; 0 = not sent (FLASH)",
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

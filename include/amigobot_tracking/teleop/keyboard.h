// Keyboard tele-operation, ROS-free: the key layout ROS users know from teleop_twist_keyboard
// (u i o / j k l / m , . move; q/z, w/x, e/c change the speeds by 10 %), for a
// differential-drive robot (no holonomic shift layer: the AmigoBot cannot move sideways).
// A motion key sets a direction; the command is direction x speed while keys keep coming,
// and zero once no key has arrived for key_timeout (a real robot stops when the operator
// lets go: a held key repeats, a released one does not).
#pragma once

#include <string>
#include <vector>

#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/core/robot/robot_description.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace teleop {

struct KeyboardConfig {
  double speed = 0.15;        // [m/s] linear speed at start
  double turn = 0.4;          // [rad/s] angular speed at start
  // q/w, q/e never raise the speeds above these; keyboard_teleop sets them to the robot
  // file's diamond before reading its parameters (may be smaller, never larger).
  double speed_max = core::RobotDescription().v_max;  // [m/s]
  double turn_max = core::RobotDescription().w_max;   // [rad/s]
  double rate = 20.0;         // [Hz] cmd_vel publication rate (>= 10)
  double key_timeout = 0.7;   // [s] no key for this long -> zero; 0 = never (not for a real robot)
  bool enable_motors = false; // call the driver's enable_motors service at start

  std::string validate() const;  // "" or "key: reason"
};

const core::FieldTable<KeyboardConfig>& keyboardFields();

// What a key does.
enum class KeyAction { kMove, kStop, kScale, kQuit, kIgnored };

struct KeyBinding {
  char key;
  KeyAction action;
  int linear;            // kMove: -1, 0, +1 (direction of v)
  int angular;           // kMove: -1, 0, +1 (direction of omega, REP 103: + = left)
  double speed_factor;   // kScale: factor on the linear speed
  double turn_factor;    // kScale: factor on the angular speed
  const char* meaning;   // for the help text
};

// Every bound key (the table the help text and docs/teleop.md show).
const std::vector<KeyBinding>& keyBindings();
// The binding of `key`: a bound key; Ctrl-C (0x03) and Ctrl-D (0x04) quit; any other
// printable key stops (as teleop_twist_keyboard); other control bytes are ignored.
KeyBinding bindingOf(char key);
// The key layout as printed at start ("u i o ... " grid with what each row does).
std::string keyHelp();

// The state machine: keys in, (v, omega) out. Times in seconds on any monotonic clock.
class KeyboardTeleop {
 public:
  explicit KeyboardTeleop(const KeyboardConfig& config);

  // Applies one key read at time `now`; returns what it did.
  KeyAction onKey(char key, double now);
  // The command to publish at `now`: direction x speeds, or zero after key_timeout.
  core::Twist2 command(double now);

  double speed() const { return speed_; }
  double turn() const { return turn_; }
  // "speed 0.150 m/s  turn 0.400 rad/s  cmd v 0.150 w 0.000" for the status line.
  std::string status(const core::Twist2& command) const;

 private:
  KeyboardConfig config_;
  double speed_, turn_;
  int linear_ = 0, angular_ = 0;
  double last_key_ = -1.0;  // no key yet
};

}  // namespace teleop
}  // namespace amigobot_tracking

#include "amigobot_tracking/teleop/keyboard.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace amigobot_tracking {
namespace teleop {

const core::FieldTable<KeyboardConfig>& keyboardFields() {
  using K = KeyboardConfig;
  using core::field;
  static const core::FieldTable<K> table = {
      field("speed", &K::speed, "m/s", "linear speed at start, <= speed_max (q/z, w/x: +/-10 %)", core::positive()),
      field("turn", &K::turn, "rad/s", "angular speed at start, <= turn_max (q/z, e/c: +/-10 %)", core::positive()),
      core::defaultText(field("speed_max", &K::speed_max, "m/s",
                              "q/w never raise the linear speed above this; above the robot file's v_max is refused "
                              "(the robot file: robot_params or robot_model, as the driver's; teleop.launch model:=)",
                              core::positive()),
                        "the robot file's v_max (0.3)"),
      core::defaultText(field("turn_max", &K::turn_max, "rad/s",
                              "q/e never raise the angular speed above this; above the robot file's w_max is refused "
                              "(the robot file: robot_params or robot_model, as the driver's; teleop.launch model:=)",
                              core::positive()),
                        "the robot file's w_max (0.8)"),
      field("rate", &K::rate, "Hz", "cmd_vel rate, zeros included (>= 10)", core::interval(10.0, false, 1000.0, false)),
      field("key_timeout", &K::key_timeout, "s",
            "no key for this long -> zero, the motion forgotten (hold a key to keep moving; the default is above the "
            "usual 0.5-0.66 s autorepeat delay, so a held key keeps going); 0 = never (not for a real robot)",
            core::boundedTimeoutOrOff()),
      field("enable_motors", &K::enable_motors, "-",
            "call the driver's enable_motors service (std_srvs/Empty, in this namespace) at start"),
  };
  return table;
}

std::string KeyboardConfig::validate() const {
  const std::string bad = core::checkFields(keyboardFields(), *this);
  if (!bad.empty()) return bad;
  if (speed > speed_max) return "speed: must be <= speed_max (" + core::formatValue(speed_max) + "), got " + core::formatValue(speed);
  if (turn > turn_max) return "turn: must be <= turn_max (" + core::formatValue(turn_max) + "), got " + core::formatValue(turn);
  return "";
}

const std::vector<KeyBinding>& keyBindings() {
  using A = KeyAction;
  static const std::vector<KeyBinding> table = {
      {'u', A::kMove, 1, 1, 1, 1, "forward, turning left"},
      {'i', A::kMove, 1, 0, 1, 1, "forward"},
      {'o', A::kMove, 1, -1, 1, 1, "forward, turning right"},
      {'j', A::kMove, 0, 1, 1, 1, "turn left on the spot"},
      {'l', A::kMove, 0, -1, 1, 1, "turn right on the spot"},
      // As teleop_twist_keyboard: m and . reverse towards their own side (reversing with
      // omega < 0 carries the robot to the left, with omega > 0 to the right).
      {'m', A::kMove, -1, -1, 1, 1, "backward, towards the left"},
      {',', A::kMove, -1, 0, 1, 1, "backward"},
      {'.', A::kMove, -1, 1, 1, 1, "backward, towards the right"},
      {'k', A::kStop, 0, 0, 1, 1, "stop"},
      {' ', A::kStop, 0, 0, 1, 1, "stop"},
      {'q', A::kScale, 0, 0, 1.1, 1.1, "both speeds +10 %"},
      {'z', A::kScale, 0, 0, 0.9, 0.9, "both speeds -10 %"},
      {'w', A::kScale, 0, 0, 1.1, 1, "linear speed +10 %"},
      {'x', A::kScale, 0, 0, 0.9, 1, "linear speed -10 %"},
      {'e', A::kScale, 0, 0, 1, 1.1, "angular speed +10 %"},
      {'c', A::kScale, 0, 0, 1, 0.9, "angular speed -10 %"},
  };
  return table;
}

KeyBinding bindingOf(char key) {
  if (key == 0x03 || key == 0x04) return {key, KeyAction::kQuit, 0, 0, 1, 1, "quit"};
  const unsigned char byte = static_cast<unsigned char>(key);
  // Letters either case: Shift (teleop_twist_keyboard's holonomic layer) means nothing here.
  const char lower = static_cast<char>(std::tolower(byte));
  for (const KeyBinding& b : keyBindings())
    if (b.key == lower) return b;
  if (std::isprint(byte)) return {key, KeyAction::kStop, 0, 0, 1, 1, "stop"};
  return {key, KeyAction::kIgnored, 0, 0, 1, 1, "ignored"};
}

std::string keyHelp() {
  return "Moving around (differential drive: no holonomic Shift layer, Shift = the same key):\n"
         "   u    i    o\n"
         "   j    k    l\n"
         "   m    ,    .\n"
         "k or space (or any other key): stop.  The robot stops by itself when no key arrives\n"
         "for key_timeout: hold a key to keep moving.\n"
         "q/z: both speeds +/-10 %   w/x: linear only   e/c: angular only   Ctrl-C: quit\n";
}

KeyboardTeleop::KeyboardTeleop(const KeyboardConfig& config)
    : config_(config), speed_(config.speed), turn_(config.turn) {}

KeyAction KeyboardTeleop::onKey(char key, double now) {
  const KeyBinding b = bindingOf(key);
  switch (b.action) {
    case KeyAction::kMove:
      linear_ = b.linear;
      angular_ = b.angular;
      last_key_ = now;
      break;
    case KeyAction::kStop:
    case KeyAction::kQuit:
      linear_ = angular_ = 0;
      last_key_ = now;
      break;
    case KeyAction::kScale:
      speed_ = std::min(speed_ * b.speed_factor, config_.speed_max);
      turn_ = std::min(turn_ * b.turn_factor, config_.turn_max);
      last_key_ = now;  // the operator is there: a held motion goes on at the new speed
      break;
    case KeyAction::kIgnored:
      break;
  }
  return b.action;
}

core::Twist2 KeyboardTeleop::command(double now) {
  const bool fresh = last_key_ >= 0.0 && (config_.key_timeout <= 0.0 || now - last_key_ < config_.key_timeout);
  if (!fresh) linear_ = angular_ = 0;  // a timed-out motion does not come back with a speed key
  core::Twist2 out;
  out.v = linear_ * speed_;
  out.omega = angular_ * turn_;
  return out;
}

std::string KeyboardTeleop::status(const core::Twist2& command) const {
  char text[120];
  std::snprintf(text, sizeof(text), "speed %.3f m/s  turn %.3f rad/s  cmd v %+.3f m/s  w %+.3f rad/s", speed_,
                turn_, command.v, command.omega);
  return text;
}

}  // namespace teleop
}  // namespace amigobot_tracking

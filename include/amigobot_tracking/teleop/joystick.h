// Joystick tele-operation, ROS-free: decoding of the Linux joystick API's events (struct
// js_event of linux/joystick.h: 8 bytes, host byte order) and the deadman/axes mapping onto
// (v, omega), as teleop_twist_joy maps sensor_msgs/Joy: a command only while the deadman
// button is held, one zero when it is released, when the device is lost or (optionally)
// when it has been silent too long.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace teleop {

struct JoystickConfig {
  std::string device = "/dev/input/js0";  // Linux joystick device
  int axis_linear = 1;                    // axis for v (left stick up/down on most pads)
  int axis_angular = 0;                   // axis for omega (left stick left/right)
  double scale_linear = 0.2;              // [m/s] v at full deflection (negative inverts)
  double scale_angular = 0.6;             // [rad/s] omega at full deflection (negative inverts)
  int deadman_button = 0;                 // held = motion allowed (teleop_twist_joy's enable_button)
  int turbo_button = -1;                  // held with the deadman = the turbo scales; -1 = none
  double scale_linear_turbo = 0.3;        // [m/s]
  double scale_angular_turbo = 0.8;       // [rad/s]
  double deadzone = 0.05;                 // [-] |axis| below this reads 0 (as joy_node)
  double rate = 20.0;                     // [Hz] cmd_vel rate while the deadman is held (>= 10)
  double stale_timeout = 0.0;             // [s] no event for this long -> zero until the next; 0 = off
  double reconnect_period = 1.0;          // [s] between attempts to (re)open the device
  bool enable_motors = false;             // call the driver's enable_motors service at start

  std::string validate() const;  // "" or "key: reason"
};

const core::FieldTable<JoystickConfig>& joystickFields();

// One event of the joystick API.
struct JoystickEvent {
  static constexpr std::uint8_t kButton = 0x01;  // JS_EVENT_BUTTON
  static constexpr std::uint8_t kAxis = 0x02;    // JS_EVENT_AXIS
  static constexpr std::uint8_t kInit = 0x80;    // JS_EVENT_INIT: the state at open, not a change
  static constexpr std::size_t kSize = 8;        // sizeof(struct js_event)

  std::uint32_t time_ms = 0;  // the driver's timestamp
  std::int16_t value = 0;     // axis -32767..32767, button 0/1
  std::uint8_t type = 0;
  std::uint8_t number = 0;

  bool isButton() const { return (type & ~kInit) == kButton; }
  bool isAxis() const { return (type & ~kInit) == kAxis; }
};

// Appends the complete events at the front of `buffer` to *out and erases their bytes (a
// read may end inside an event; the rest waits for the next read).
void decodeEvents(std::string* buffer, std::vector<JoystickEvent>* out);
// The 8 bytes of an event as the kernel writes them (tests and device stand-ins).
std::string encodeEvent(const JoystickEvent& event);

// The joystick's state from its events: axes in [-1, 1] in joy_node's convention (stick up
// and left positive, so REP 103 needs no sign change), buttons pressed or not.
struct JoystickState {
  std::vector<double> axes;
  std::vector<bool> buttons;
};

// An axis value -32767..32767 (js: up/left negative) as joy_node reports it: negated,
// in [-1, 1], zero inside the deadzone and rescaled outside it so the output is continuous.
double normalizeAxis(std::int16_t value, double deadzone);
// Applies one event to the state (grows the vectors as needed); unknown types are ignored.
void applyEvent(const JoystickEvent& event, double deadzone, JoystickState* state);
bool buttonHeld(const JoystickState& state, int button);
// The command the sticks ask for (scales of the turbo when it is held), ignoring the deadman.
core::Twist2 mapAxes(const JoystickState& state, const JoystickConfig& config);

// What to publish when: ticks at `rate` ask for a command.
class JoystickTeleop {
 public:
  explicit JoystickTeleop(const JoystickConfig& config);

  void onEvent(const JoystickEvent& event, double now);
  // The device went away: the state is forgotten, the next tick sends one zero.
  void onDeviceLost();
  // The command to publish at `now`, or nothing: the mapped axes while the deadman is held
  // (and events are not stale), then one zero, then silence (other sources may drive).
  std::optional<core::Twist2> tick(double now);

  bool deadmanHeld() const { return buttonHeld(state_, config_.deadman_button); }
  // The deadman is held but no event came for stale_timeout.
  bool stale(double now) const;
  const JoystickState& state() const { return state_; }

 private:
  JoystickConfig config_;
  JoystickState state_;
  double last_event_ = -1.0;
  bool moving_ = false;        // the last tick published a motion command
  bool zero_pending_ = false;  // a zero is owed (device lost)
};

}  // namespace teleop
}  // namespace amigobot_tracking

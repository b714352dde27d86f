#include "amigobot_tracking/teleop/joystick.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace amigobot_tracking {
namespace teleop {

const core::FieldTable<JoystickConfig>& joystickFields() {
  using J = JoystickConfig;
  using core::field;
  const core::Bounds number = core::atLeast(0.0);  // an axis or button number
  static const core::FieldTable<J> table = {
      field("device", &J::device, "-",
            "Linux joystick device (struct js_event API of linux/joystick.h, read directly: no joy node); find a "
            "pad's axis and button numbers with jstest"),
      field("axis_linear", &J::axis_linear, "-", "axis for v (left stick up/down on most pads)", number),
      field("axis_angular", &J::axis_angular, "-",
            "axis for omega (left stick left/right on most pads); not axis_linear", number),
      field("scale_linear", &J::scale_linear, "m/s", "v at full deflection, stick up = forward (negative inverts)"),
      field("scale_angular", &J::scale_angular, "rad/s",
            "omega at full deflection, stick left = turn left, REP 103 (negative inverts)"),
      field("deadman_button", &J::deadman_button, "-",
            "motion only while this button is held (teleop_twist_joy's enable_button); on release one zero, then "
            "nothing (other sources may drive)",
            number),
      field("turbo_button", &J::turbo_button, "-",
            "held with the deadman -> the turbo scales; -1 = no turbo; not deadman_button", core::atLeast(-1.0)),
      field("scale_linear_turbo", &J::scale_linear_turbo, "m/s", "v at full deflection with turbo"),
      field("scale_angular_turbo", &J::scale_angular_turbo, "rad/s", "omega at full deflection with turbo"),
      field("deadzone", &J::deadzone, "-",
            "an axis within this fraction of full deflection reads 0 (as joy_node); beyond it, rescaled to reach 1 "
            "at full deflection",
            core::interval(0.0, false, 1.0, true)),
      field("rate", &J::rate, "Hz", "cmd_vel rate while the deadman is held (>= 10)",
            core::interval(10.0, false, 1000.0, false)),
      field("stale_timeout", &J::stale_timeout, "s",
            "no event for this long with the deadman held -> zero until the next event (a pad whose link dies "
            "silently); 0 = off, the default because a stick held still sends no events",
            core::boundedTimeoutOrOff()),
      field("reconnect_period", &J::reconnect_period, "s",
            "between attempts to (re)open a missing or failed device; after a loss one zero is sent and the deadman "
            "must be pressed again",
            core::duration()),
      field("enable_motors", &J::enable_motors, "-",
            "call the driver's enable_motors service (std_srvs/Empty, in this namespace) at start"),
  };
  return table;
}

std::string JoystickConfig::validate() const {
  const std::string bad = core::checkFields(joystickFields(), *this);
  if (!bad.empty()) return bad;
  if (device.empty()) return "device: must not be empty";
  if (axis_linear == axis_angular) return "axis_angular: must differ from axis_linear (" + std::to_string(axis_linear) + ")";
  if (turbo_button == deadman_button) return "turbo_button: must differ from deadman_button (" + std::to_string(deadman_button) + ")";
  return "";
}

namespace {
// struct js_event's layout: __u32 time; __s16 value; __u8 type; __u8 number.
constexpr std::size_t kTime = 0, kValue = 4, kType = 6, kNumber = 7;
}  // namespace

void decodeEvents(std::string* buffer, std::vector<JoystickEvent>* out) {
  const std::size_t whole = buffer->size() / JoystickEvent::kSize * JoystickEvent::kSize;
  for (std::size_t at = 0; at < whole; at += JoystickEvent::kSize) {
    const char* bytes = buffer->data() + at;
    JoystickEvent e;
    std::memcpy(&e.time_ms, bytes + kTime, sizeof(e.time_ms));
    std::memcpy(&e.value, bytes + kValue, sizeof(e.value));
    std::memcpy(&e.type, bytes + kType, 1);
    std::memcpy(&e.number, bytes + kNumber, 1);
    out->push_back(e);
  }
  buffer->erase(0, whole);
}

std::string encodeEvent(const JoystickEvent& event) {
  std::string bytes(JoystickEvent::kSize, '\0');
  std::memcpy(&bytes[kTime], &event.time_ms, sizeof(event.time_ms));
  std::memcpy(&bytes[kValue], &event.value, sizeof(event.value));
  std::memcpy(&bytes[kType], &event.type, 1);
  std::memcpy(&bytes[kNumber], &event.number, 1);
  return bytes;
}

double normalizeAxis(std::int16_t value, double deadzone) {
  const double x = std::clamp(-static_cast<double>(value) / 32767.0, -1.0, 1.0);
  if (std::abs(x) <= deadzone) return 0.0;
  return std::copysign((std::abs(x) - deadzone) / (1.0 - deadzone), x);
}

void applyEvent(const JoystickEvent& event, double deadzone, JoystickState* state) {
  const std::size_t n = event.number;
  if (event.isAxis()) {
    if (state->axes.size() <= n) state->axes.resize(n + 1, 0.0);
    state->axes[n] = normalizeAxis(event.value, deadzone);
  } else if (event.isButton()) {
    if (state->buttons.size() <= n) state->buttons.resize(n + 1, false);
    state->buttons[n] = event.value != 0;
  }
}

bool buttonHeld(const JoystickState& state, int button) {
  return button >= 0 && static_cast<std::size_t>(button) < state.buttons.size() && state.buttons[button];
}

namespace {
double axis(const JoystickState& state, int index) {
  return static_cast<std::size_t>(index) < state.axes.size() ? state.axes[index] : 0.0;
}
}  // namespace

core::Twist2 mapAxes(const JoystickState& state, const JoystickConfig& config) {
  const bool turbo = buttonHeld(state, config.turbo_button);
  core::Twist2 out;
  out.v = axis(state, config.axis_linear) * (turbo ? config.scale_linear_turbo : config.scale_linear);
  out.omega = axis(state, config.axis_angular) * (turbo ? config.scale_angular_turbo : config.scale_angular);
  return out;
}

JoystickTeleop::JoystickTeleop(const JoystickConfig& config) : config_(config) {}

void JoystickTeleop::onEvent(const JoystickEvent& event, double now) {
  applyEvent(event, config_.deadzone, &state_);
  last_event_ = now;
}

void JoystickTeleop::onDeviceLost() {
  state_ = JoystickState();
  last_event_ = -1.0;
  zero_pending_ = true;
}

bool JoystickTeleop::stale(double now) const {
  return config_.stale_timeout > 0.0 && deadmanHeld() && now - last_event_ >= config_.stale_timeout;
}

std::optional<core::Twist2> JoystickTeleop::tick(double now) {
  if (deadmanHeld() && !stale(now)) {
    moving_ = true;
    zero_pending_ = false;
    return mapAxes(state_, config_);
  }
  if (moving_ || zero_pending_) {
    moving_ = zero_pending_ = false;
    return core::Twist2();
  }
  return std::nullopt;
}

}  // namespace teleop
}  // namespace amigobot_tracking

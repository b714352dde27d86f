// teleop joystick: js_event decoding (against the kernel's own struct), axis normalisation,
// the deadman/axes/turbo mapping, and what is published when: motion while the deadman is
// held, one zero on release, on device loss and when events go stale.
#include <gtest/gtest.h>

#include <linux/joystick.h>

#include <cstring>

#include "amigobot_tracking/teleop/joystick.h"

using namespace amigobot_tracking;
using teleop::JoystickEvent;

namespace {

JoystickEvent event(std::uint8_t type, std::uint8_t number, std::int16_t value) {
  JoystickEvent e;
  e.type = type;
  e.number = number;
  e.value = value;
  return e;
}
JoystickEvent button(std::uint8_t number, bool pressed) { return event(JoystickEvent::kButton, number, pressed ? 1 : 0); }
JoystickEvent axis(std::uint8_t number, std::int16_t value) { return event(JoystickEvent::kAxis, number, value); }

teleop::JoystickConfig joystickConfig() {
  teleop::JoystickConfig c;
  c.axis_linear = 1;
  c.axis_angular = 3;
  c.scale_linear = 0.2;
  c.scale_angular = 0.6;
  c.deadman_button = 4;
  c.turbo_button = 5;
  c.scale_linear_turbo = 0.3;
  c.scale_angular_turbo = 0.8;
  c.deadzone = 0.0;
  return c;
}

}  // namespace

TEST(JoystickDecode, ReadsTheKernelsStructAndKeepsAPartialEvent) {
  js_event raw[2];
  raw[0] = {123456u, -32767, JS_EVENT_AXIS | JS_EVENT_INIT, 3};
  raw[1] = {123470u, 1, JS_EVENT_BUTTON, 7};
  std::string bytes(reinterpret_cast<const char*>(raw), sizeof(raw));
  const std::string tail = bytes.substr(13);  // a read that ends inside the second event
  bytes.resize(13);
  std::vector<JoystickEvent> events;
  teleop::decodeEvents(&bytes, &events);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(bytes.size(), 5u);
  EXPECT_EQ(events[0].time_ms, 123456u);
  EXPECT_EQ(events[0].value, -32767);
  EXPECT_TRUE(events[0].isAxis());  // the INIT flag does not hide the type
  EXPECT_FALSE(events[0].isButton());
  EXPECT_EQ(events[0].number, 3);
  bytes += tail;
  teleop::decodeEvents(&bytes, &events);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_TRUE(bytes.empty());
  EXPECT_TRUE(events[1].isButton());
  EXPECT_EQ(events[1].number, 7);
  EXPECT_EQ(events[1].value, 1);
  EXPECT_EQ(teleop::encodeEvent(events[1]), std::string(reinterpret_cast<const char*>(&raw[1]), sizeof(js_event)));
}

TEST(JoystickMapping, AxesAreNegatedNormalisedAndDeadzoned) {
  EXPECT_DOUBLE_EQ(teleop::normalizeAxis(-32767, 0.0), 1.0);  // stick up / left: positive, as joy_node
  EXPECT_DOUBLE_EQ(teleop::normalizeAxis(32767, 0.0), -1.0);
  EXPECT_DOUBLE_EQ(teleop::normalizeAxis(-32768, 0.0), 1.0);  // clamped
  EXPECT_DOUBLE_EQ(teleop::normalizeAxis(0, 0.1), 0.0);
  EXPECT_DOUBLE_EQ(teleop::normalizeAxis(-3000, 0.1), 0.0);  // 0.0916 inside the deadzone
  EXPECT_NEAR(teleop::normalizeAxis(-16384, 0.1), (16384.0 / 32767.0 - 0.1) / 0.9, 1e-12);  // continuous at the edge
  EXPECT_DOUBLE_EQ(teleop::normalizeAxis(32767, 0.1), -1.0);
}

TEST(JoystickMapping, ScalesAxesAndTurbo) {
  teleop::JoystickState s;
  const teleop::JoystickConfig c = joystickConfig();
  EXPECT_DOUBLE_EQ(teleop::mapAxes(s, c).v, 0.0);  // no axis seen yet
  teleop::applyEvent(axis(1, -32767), 0.0, &s);      // full forward
  teleop::applyEvent(axis(3, 16384), 0.0, &s);       // half right
  core::Twist2 u = teleop::mapAxes(s, c);
  EXPECT_DOUBLE_EQ(u.v, 0.2);
  EXPECT_NEAR(u.omega, -0.6 * 16384.0 / 32767.0, 1e-12);
  teleop::applyEvent(button(5, true), 0.0, &s);
  u = teleop::mapAxes(s, c);
  EXPECT_DOUBLE_EQ(u.v, 0.3);
  EXPECT_NEAR(u.omega, -0.8 * 16384.0 / 32767.0, 1e-12);
  teleop::JoystickConfig inverted = c;
  inverted.scale_linear = -0.2;
  teleop::applyEvent(button(5, false), 0.0, &s);
  EXPECT_DOUBLE_EQ(teleop::mapAxes(s, inverted).v, -0.2);
  teleop::applyEvent(event(0x40, 9, 1), 0.0, &s);  // unknown type: ignored
  EXPECT_EQ(s.buttons.size(), 6u);
  EXPECT_EQ(s.axes.size(), 4u);
}

TEST(JoystickTeleop, MotionOnlyWhileTheDeadmanIsHeldThenOneZero) {
  teleop::JoystickTeleop t(joystickConfig());
  EXPECT_FALSE(t.tick(0.0));  // nothing before the deadman
  t.onEvent(axis(1, -32767), 0.0);
  EXPECT_FALSE(t.tick(0.05));  // sticks alone never move the robot
  t.onEvent(button(4, true), 0.1);
  for (double time : {0.15, 0.2, 0.25}) {
    const auto u = t.tick(time);
    ASSERT_TRUE(u);
    EXPECT_DOUBLE_EQ(u->v, 0.2);
  }
  t.onEvent(button(4, false), 0.3);
  const auto zero = t.tick(0.35);
  ASSERT_TRUE(zero);
  EXPECT_DOUBLE_EQ(zero->v, 0.0);
  EXPECT_DOUBLE_EQ(zero->omega, 0.0);
  EXPECT_FALSE(t.tick(0.4));  // silent afterwards: other sources may drive
  EXPECT_FALSE(t.tick(0.45));
}

TEST(JoystickTeleop, DeviceLostGivesOneZeroAndForgetsTheState) {
  teleop::JoystickTeleop t(joystickConfig());
  t.onEvent(button(4, true), 0.0);
  t.onEvent(axis(1, -32767), 0.0);
  ASSERT_TRUE(t.tick(0.05));
  t.onDeviceLost();
  EXPECT_FALSE(t.deadmanHeld());
  const auto zero = t.tick(0.1);
  ASSERT_TRUE(zero);
  EXPECT_DOUBLE_EQ(zero->v, 0.0);
  EXPECT_FALSE(t.tick(0.15));
  t.onDeviceLost();  // lost while idle: still one zero (the robot may have been driven before)
  EXPECT_TRUE(t.tick(0.2));
  EXPECT_FALSE(t.tick(0.25));
}

TEST(JoystickTeleop, StaleEventsStopUntilTheNextEvent) {
  teleop::JoystickConfig c = joystickConfig();
  c.stale_timeout = 1.0;
  teleop::JoystickTeleop t(c);
  t.onEvent(button(4, true), 0.0);
  t.onEvent(axis(1, -32767), 0.0);
  EXPECT_FALSE(t.stale(0.99));
  ASSERT_TRUE(t.tick(0.99));
  EXPECT_TRUE(t.stale(1.0));
  const auto zero = t.tick(1.0);
  ASSERT_TRUE(zero);
  EXPECT_DOUBLE_EQ(zero->v, 0.0);
  EXPECT_FALSE(t.tick(1.5));
  t.onEvent(axis(1, -32767), 2.0);  // the pad speaks again
  const auto u = t.tick(2.05);
  ASSERT_TRUE(u);
  EXPECT_DOUBLE_EQ(u->v, 0.2);
}

TEST(JoystickConfig, DefaultsAreValidAndBadValuesAreNamed) {
  EXPECT_EQ(teleop::JoystickConfig().validate(), "");
  teleop::JoystickConfig c;
  c.axis_angular = c.axis_linear;
  EXPECT_EQ(c.validate().rfind("axis_angular: must differ", 0), 0u) << c.validate();
  c = teleop::JoystickConfig();
  c.turbo_button = c.deadman_button;
  EXPECT_EQ(c.validate().rfind("turbo_button: must differ", 0), 0u) << c.validate();
  c = teleop::JoystickConfig();
  c.deadman_button = -1;
  EXPECT_EQ(c.validate().rfind("deadman_button: ", 0), 0u) << c.validate();
  c = teleop::JoystickConfig();
  c.deadzone = 1.0;
  EXPECT_EQ(c.validate().rfind("deadzone: ", 0), 0u) << c.validate();
  c = teleop::JoystickConfig();
  c.device = "";
  EXPECT_EQ(c.validate(), "device: must not be empty");
  c = teleop::JoystickConfig();
  c.rate = 9.0;
  EXPECT_EQ(c.validate().rfind("rate: ", 0), 0u) << c.validate();
}

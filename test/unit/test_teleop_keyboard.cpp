// teleop::KeyboardTeleop: every key of the layout, the speed steps and their clamps, the key
// timeout, and the configuration's checks.
#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "amigobot_tracking/teleop/keyboard.h"

using namespace amigobot_tracking;
using teleop::KeyAction;

namespace {

teleop::KeyboardConfig config() {
  teleop::KeyboardConfig c;
  c.speed = 0.2;
  c.turn = 0.5;
  c.speed_max = 0.3;
  c.turn_max = 0.8;
  c.key_timeout = 0.5;
  return c;
}

}  // namespace

TEST(KeyboardTeleop, EveryMotionKeyGivesTeleopTwistKeyboardsDirection) {
  // key -> (sign of v, sign of omega), teleop_twist_keyboard's moveBindings (x, th).
  const std::map<char, std::pair<int, int>> expected = {
      {'u', {1, 1}},  {'i', {1, 0}},  {'o', {1, -1}}, {'j', {0, 1}},  {'l', {0, -1}},
      {'m', {-1, -1}}, {',', {-1, 0}}, {'.', {-1, 1}}, {'k', {0, 0}}, {' ', {0, 0}}};
  for (const auto& [key, direction] : expected) {
    teleop::KeyboardTeleop t(config());
    t.onKey('i', 0.0);  // moving first, so that the stop keys show
    t.onKey(key, 0.1);
    const core::Twist2 u = t.command(0.2);
    EXPECT_DOUBLE_EQ(u.v, 0.2 * direction.first) << "key '" << key << "'";
    EXPECT_DOUBLE_EQ(u.omega, 0.5 * direction.second) << "key '" << key << "'";
  }
}

TEST(KeyboardTeleop, UpperCaseIsTheSameKeyAndOtherKeysStop) {
  teleop::KeyboardTeleop t(config());
  EXPECT_EQ(t.onKey('U', 0.0), KeyAction::kMove);  // no holonomic layer on a differential drive
  EXPECT_DOUBLE_EQ(t.command(0.1).v, 0.2);
  EXPECT_DOUBLE_EQ(t.command(0.1).omega, 0.5);
  EXPECT_EQ(t.onKey('p', 0.2), KeyAction::kStop);  // as teleop_twist_keyboard: anything else stops
  EXPECT_DOUBLE_EQ(t.command(0.3).v, 0.0);
  t.onKey('i', 0.4);
  EXPECT_EQ(t.onKey('\033', 0.5), KeyAction::kIgnored);  // a control byte changes nothing
  EXPECT_DOUBLE_EQ(t.command(0.6).v, 0.2);
  EXPECT_EQ(t.onKey('\x03', 0.6), KeyAction::kQuit);  // Ctrl-C
  EXPECT_DOUBLE_EQ(t.command(0.6).v, 0.0);
  EXPECT_EQ(teleop::bindingOf('\x04').action, KeyAction::kQuit);  // Ctrl-D
}

TEST(KeyboardTeleop, SpeedKeysScaleByTenPercentEachAxisAsBound) {
  // key -> (speed factor, turn factor)
  const std::map<char, std::pair<double, double>> expected = {
      {'q', {1.1, 1.1}}, {'z', {0.9, 0.9}}, {'w', {1.1, 1.0}}, {'x', {0.9, 1.0}}, {'e', {1.0, 1.1}}, {'c', {1.0, 0.9}}};
  for (const auto& [key, factors] : expected) {
    teleop::KeyboardTeleop t(config());
    t.onKey('u', 0.0);
    EXPECT_EQ(t.onKey(key, 0.1), KeyAction::kScale);
    EXPECT_NEAR(t.speed(), 0.2 * factors.first, 1e-12) << key;
    EXPECT_NEAR(t.turn(), 0.5 * factors.second, 1e-12) << key;
    const core::Twist2 u = t.command(0.2);  // the motion goes on at the new speeds
    EXPECT_NEAR(u.v, t.speed(), 1e-12) << key;
    EXPECT_NEAR(u.omega, t.turn(), 1e-12) << key;
  }
}

TEST(KeyboardTeleop, SpeedsAreClampedToTheirMaxima) {
  teleop::KeyboardTeleop t(config());
  for (int i = 0; i < 30; ++i) t.onKey('q', 0.0);
  EXPECT_DOUBLE_EQ(t.speed(), 0.3);
  EXPECT_DOUBLE_EQ(t.turn(), 0.8);
  t.onKey('i', 0.0);
  EXPECT_DOUBLE_EQ(t.command(0.0).v, 0.3);
  for (int i = 0; i < 5; ++i) t.onKey('x', 0.0);  // down again from the clamp, in 10 % steps
  EXPECT_NEAR(t.speed(), 0.3 * 0.9 * 0.9 * 0.9 * 0.9 * 0.9, 1e-12);
  EXPECT_DOUBLE_EQ(t.turn(), 0.8);
  for (int i = 0; i < 200; ++i) t.onKey('z', 0.0);
  EXPECT_GT(t.speed(), 0.0);  // never reverses the keys' meaning
  EXPECT_GT(t.turn(), 0.0);
}

TEST(KeyboardTeleop, ZeroAfterKeyTimeoutAndNoMotionBeforeTheFirstKey) {
  teleop::KeyboardTeleop t(config());
  EXPECT_DOUBLE_EQ(t.command(0.0).v, 0.0);
  t.onKey('i', 10.0);
  EXPECT_DOUBLE_EQ(t.command(10.49).v, 0.2);
  t.onKey('i', 10.4);  // a held key repeats: the motion goes on
  EXPECT_DOUBLE_EQ(t.command(10.89).v, 0.2);
  EXPECT_DOUBLE_EQ(t.command(10.91).v, 0.0);  // key_timeout after the last key
  t.onKey('q', 11.0);  // a speed key does not bring a timed-out motion back
  EXPECT_DOUBLE_EQ(t.command(11.1).v, 0.0);
  t.onKey('q', 11.2);
  t.onKey('j', 11.3);
  EXPECT_NEAR(t.command(11.4).omega, 0.5 * 1.1 * 1.1, 1e-12);
}

TEST(KeyboardTeleop, ZeroKeyTimeoutNeverStops) {
  teleop::KeyboardConfig c = config();
  c.key_timeout = 0.0;
  teleop::KeyboardTeleop t(c);
  t.onKey('o', 0.0);
  EXPECT_DOUBLE_EQ(t.command(1e6).v, 0.2);
  EXPECT_DOUBLE_EQ(t.command(1e6).omega, -0.5);
}

TEST(KeyboardTeleop, StatusShowsSpeedsAndCommand) {
  teleop::KeyboardTeleop t(config());
  t.onKey('.', 0.0);
  EXPECT_EQ(t.status(t.command(0.1)), "speed 0.200 m/s  turn 0.500 rad/s  cmd v -0.200 m/s  w +0.500 rad/s");
}

TEST(KeyboardTeleop, EveryBindingIsInTheHelp) {
  const std::string help = teleop::keyHelp();
  for (const teleop::KeyBinding& b : teleop::keyBindings())
    if (b.key != ' ') {
      EXPECT_NE(help.find(b.key), std::string::npos) << b.key;
    }
  EXPECT_NE(help.find("holonomic"), std::string::npos);
}

TEST(KeyboardConfig, DefaultsAreValidAndBadValuesAreNamed) {
  EXPECT_EQ(teleop::KeyboardConfig().validate(), "");
  teleop::KeyboardConfig c;
  c.speed = 0.5;  // above speed_max 0.3
  EXPECT_EQ(c.validate().rfind("speed: must be <= speed_max", 0), 0u) << c.validate();
  c = teleop::KeyboardConfig();
  c.turn = 1.0;
  EXPECT_EQ(c.validate().rfind("turn: must be <= turn_max", 0), 0u) << c.validate();
  c = teleop::KeyboardConfig();
  c.rate = 5.0;  // below the promised 10 Hz
  EXPECT_EQ(c.validate().rfind("rate: ", 0), 0u) << c.validate();
  c = teleop::KeyboardConfig();
  c.key_timeout = -1.0;
  EXPECT_EQ(c.validate().rfind("key_timeout: ", 0), 0u) << c.validate();
  c = teleop::KeyboardConfig();
  c.speed_max = 0.0;
  EXPECT_EQ(c.validate().rfind("speed_max: ", 0), 0u) << c.validate();
}

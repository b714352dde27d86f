// rostest: joystick_teleop reading a FIFO that stands in for /dev/input/jsN, into which the
// test writes real struct js_event records (linux/joystick.h). One behaviour per .test
// (joystick_teleop_*.test picks a case with --gtest_filter): the deadman (held: motion at
// the rate; released: one zero, then silence), and the device going away (a zero, an error
// naming the device, and driving again once it is back).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <linux/joystick.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>

#include <ros/ros.h>

#include "cmd_vel_log.h"
#include "node_process.h"

namespace joystick_teleop_test {

using amigobot_test::CmdVelLog;
using amigobot_test::NodeProcess;

namespace {

using Received = CmdVelLog::Received;

double now() { return CmdVelLog::now(); }

class JoystickTeleopNode : public testing::Test {
 protected:
  void SetUp() override {
    char dir[] = "/tmp/joystick_teleop_testXXXXXX";
    ASSERT_NE(::mkdtemp(dir), nullptr);
    dir_ = dir;
    fifo_ = dir_ + "/js0";
    ASSERT_EQ(::mkfifo(fifo_.c_str(), 0600), 0);
    openDevice();
    node_.start({JOYSTICK_TELEOP, "__name:=joystick_teleop", "_device:=" + fifo_, "_deadman_button:=4",
                 "_axis_linear:=1", "_axis_angular:=3", "_scale_linear:=0.2", "_scale_angular:=0.6",
                 "_deadzone:=0.0", "_rate:=20.0", "_reconnect_period:=0.5"},
                NodeProcess::Terminal::kPipe);
    ASSERT_TRUE(log_.waitForPublisher(30.0)) << node_.output();
    // The state at open, as the driver reports it (JS_EVENT_INIT): everything at rest.
    for (std::uint8_t b = 0; b < 6; ++b) send(JS_EVENT_BUTTON | JS_EVENT_INIT, b, 0);
    for (std::uint8_t a = 0; a < 4; ++a) send(JS_EVENT_AXIS | JS_EVENT_INIT, a, 0);
    ASSERT_TRUE(node_.waitForOutput("connected", 10.0)) << node_.output();
    // A FIFO reader sees the hang-up (POLLHUP, then end of file) only of a writer that came
    // after its open: write through a new one from now on, as a device the node opened.
    const int writer = ::open(fifo_.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    ASSERT_GE(writer, 0);
    ::close(writer_);
    writer_ = writer;
  }
  void TearDown() override {
    node_.stop(SIGINT, 10.0);
    if (writer_ >= 0) ::close(writer_);
    ::unlink(fifo_.c_str());
    ::rmdir(dir_.c_str());
  }

  // O_RDWR: never blocks, and keeps the FIFO open for the node's reads; O_CLOEXEC: the node
  // must not inherit a writer, or the FIFO never hangs up.
  void openDevice() { writer_ = ::open(fifo_.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC); ASSERT_GE(writer_, 0); }
  void closeDevice() {
    ::close(writer_);
    writer_ = -1;
  }
  void send(std::uint8_t type, std::uint8_t number, std::int16_t value) {
    js_event e{static_cast<std::uint32_t>(std::fmod(now() * 1000.0, 4294967296.0)), value, type, number};
    ASSERT_EQ(::write(writer_, &e, sizeof(e)), static_cast<ssize_t>(sizeof(e)));
  }
  std::vector<Received> since(double t) const { return log_.since(t); }
  double waitFor(double v, double w, double t, double timeout = 3.0) const { return log_.waitFor(v, w, t, timeout); }

  std::string dir_, fifo_;
  int writer_ = -1;
  CmdVelLog log_;
  NodeProcess node_;
};

}  // namespace

TEST_F(JoystickTeleopNode, DeadmanHeldDrivesAtRateReleasedSendsOneZero) {
  double t = now();
  send(JS_EVENT_AXIS, 1, -32767);  // full forward, deadman not held
  send(JS_EVENT_AXIS, 3, 16384);   // half right
  ros::WallDuration(0.7).sleep();
  EXPECT_TRUE(since(t).empty()) << "the sticks alone never move the robot";

  t = now();
  send(JS_EVENT_BUTTON, 4, 1);
  const double v = 0.2, w = -0.6 * 16384.0 / 32767.0;
  const double first = waitFor(v, w, t);
  ASSERT_FALSE(std::isnan(first)) << node_.output();
  ros::WallDuration(2.0).sleep();
  const auto moving = since(first);
  const double rate = (moving.size() - 1) / (moving.back().t - first);
  RecordProperty("cmd_vel_rate_hz", std::to_string(rate));
  EXPECT_GE(rate, 10.0);
  for (const Received& m : moving) {
    EXPECT_DOUBLE_EQ(m.v, v);
    EXPECT_DOUBLE_EQ(m.w, w);
  }

  send(JS_EVENT_AXIS, 1, -16384);  // half forward: the command follows the stick
  ASSERT_FALSE(std::isnan(waitFor(0.2 * 16384.0 / 32767.0, w, now())));

  t = now();
  send(JS_EVENT_BUTTON, 4, 0);
  ASSERT_FALSE(std::isnan(waitFor(0.0, 0.0, t))) << "a zero on release";
  ros::WallDuration(1.0).sleep();
  const auto after = since(t);
  ASSERT_FALSE(after.empty());
  size_t zeros = 0;
  for (const Received& m : after) zeros += m.v == 0.0 && m.w == 0.0;
  EXPECT_EQ(zeros, 1u) << "one zero, then silence";
  EXPECT_EQ(after.back().v, 0.0);
}

TEST_F(JoystickTeleopNode, DeviceClosedSendsZeroLogsItAndReconnects) {
  send(JS_EVENT_AXIS, 1, -32767);
  send(JS_EVENT_BUTTON, 4, 1);
  ASSERT_FALSE(std::isnan(waitFor(0.2, 0.0, now() - 1.0))) << node_.output();

  const double t = now();
  closeDevice();  // the pad unplugged: the node's read ends
  ASSERT_FALSE(std::isnan(waitFor(0.0, 0.0, t))) << "a zero when the device goes away\n" << node_.output();
  EXPECT_TRUE(node_.waitForOutput("device " + fifo_ + ": closed", 5.0)) << node_.output();
  ros::WallDuration(1.0).sleep();
  for (const Received& m : since(t)) EXPECT_EQ(m.v, 0.0) << "nothing but zeros while it is gone";

  openDevice();  // plugged in again: reopened within reconnect_period, a new state
  const double back = now();
  for (int i = 0; i < 40 && std::isnan(waitFor(0.2, 0.0, back, 0.05)); ++i) {
    send(JS_EVENT_AXIS, 1, -32767);
    send(JS_EVENT_BUTTON, 4, 1);
  }
  EXPECT_FALSE(std::isnan(waitFor(0.2, 0.0, back, 1.0))) << "drives again after the reconnection\n" << node_.output();
}

}  // namespace joystick_teleop_test

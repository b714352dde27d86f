// rostest: keyboard_teleop on a real pseudo-terminal (test/support/node_process.h): keys typed
// into the master drive cmd_vel; one behaviour per .test (keyboard_teleop_*.test picks a case
// with --gtest_filter): keys and rate, the key timeout, a zero and the terminal restored on
// SIGINT, and the refusals (no terminal, a bad parameter) that publish nothing.
#include <gtest/gtest.h>
#include <unistd.h>
#include <cstdio>
#include <fstream>

#include <cmath>

#include <ros/ros.h>

#include "cmd_vel_log.h"
#include "node_process.h"

namespace keyboard_teleop_test {

using amigobot_test::CmdVelLog;
using amigobot_test::NodeProcess;

namespace {

using Received = CmdVelLog::Received;

double now() { return ros::WallTime::now().toSec(); }

// keyboard_teleop on a pty, started and connected to the log's subscriber.
void startOnPty(NodeProcess* node, const CmdVelLog& log, std::vector<std::string> params = {}) {
  std::vector<std::string> args = {KEYBOARD_TELEOP, "__name:=keyboard_teleop"};
  args.insert(args.end(), params.begin(), params.end());
  node->start(args, NodeProcess::Terminal::kPty);
  ASSERT_TRUE(node->waitForOutput("Publishing", 30.0)) << node->output();
  ASSERT_TRUE(log.waitForPublisher(15.0)) << node->output();
}

}  // namespace

TEST(KeyboardTeleopNode, KeysDriveCmdVelAtRate) {
  CmdVelLog log;
  NodeProcess node;
  startOnPty(&node, log, {"_key_timeout:=0"});  // no timeout: only the keys count here
  const termios raw = node.terminalSettings();
  EXPECT_EQ(raw.c_lflag & (ICANON | ECHO), 0u) << "the node's terminal is raw";

  double t = now();
  ros::WallDuration(0.5).sleep();
  for (const Received& r : log.since(t)) EXPECT_EQ(r.v, 0.0) << "nothing moves before the first key";
  struct Step {
    char key;
    double v, w;
  };
  const double s = 0.15, r = 0.4;  // defaults
  const Step steps[] = {{'i', s, 0},          {'j', 0, r},           {'l', 0, -r},          {'u', s, r},
                        {'o', s, -r},         {',', -s, 0},          {'m', -s, -r},         {'.', -s, r},
                        {'k', 0, 0},          {'i', s, 0},           {' ', 0, 0},           {'q', 0, 0},
                        {'i', s * 1.1, 0},    {'w', s * 1.21, 0},    {'x', s * 1.089, 0},   {'j', 0, r * 1.1},
                        {'e', 0, r * 1.21},   {'c', 0, r * 1.089},   {'z', 0, r * 0.9801}};
  for (const Step& step : steps) {
    t = now();
    node.type(std::string(1, step.key));
    const double arrived = log.waitFor(step.v, step.w, t);
    ASSERT_FALSE(std::isnan(arrived)) << "key '" << step.key << "': no cmd_vel (" << step.v << ", " << step.w << ")";
    ros::WallDuration(0.15).sleep();
  }
  // Clamps: 20 x q reaches speed_max 0.3 and turn_max 0.8, never more.
  node.type("qqqqqqqqqqqqqqqqqqqqu");
  ASSERT_FALSE(std::isnan(log.waitFor(0.3, 0.8, now()))) << "clamped to speed_max, turn_max";
  EXPECT_TRUE(node.waitForOutput("speed 0.300 m/s  turn 0.800 rad/s", 2.0)) << "the status line shows the speeds";

  // Rate: >= 10 Hz (default 20) over 3 s, zeros included.
  node.type("k");
  t = now();
  ros::WallDuration(3.0).sleep();
  const size_t count = log.since(t).size();
  RecordProperty("cmd_vel_rate_hz", std::to_string(count / 3.0));
  EXPECT_GE(count / 3.0, 10.0);
  for (const Received& m : log.since(t + 0.3)) EXPECT_EQ(m.v, 0.0);
}

TEST(KeyboardTeleopNode, StopsAfterKeyTimeout) {
  CmdVelLog log;
  NodeProcess node;
  startOnPty(&node, log, {"_key_timeout:=0.7"});
  const double typed = now();
  node.type("i");
  const double moving = log.waitFor(0.15, 0.0, typed);
  ASSERT_FALSE(std::isnan(moving));
  const double stopped = log.waitFor(0.0, 0.0, moving, 5.0);
  ASSERT_FALSE(std::isnan(stopped)) << "no zero after the key timeout";
  const double lasted = stopped - typed;
  RecordProperty("motion_after_one_key_s", std::to_string(lasted));
  EXPECT_GE(lasted, 0.65) << "stopped before key_timeout";
  EXPECT_LE(lasted, 0.7 + 0.4) << "key_timeout plus a few periods (loaded machine)";
  ros::WallDuration(1.0).sleep();
  const auto after = log.since(stopped);
  EXPECT_GE(after.size(), 10u) << "zeros go on at the rate";
  for (const Received& m : after) EXPECT_EQ(m.v, 0.0);

  // Held key: repeats closer than key_timeout keep the robot moving.
  const double held = now();
  for (int i = 0; i < 8; ++i) {
    node.type("i");
    ros::WallDuration(0.25).sleep();
  }
  const double first = log.waitFor(0.15, 0.0, held);
  ASSERT_FALSE(std::isnan(first));
  for (const Received& m : log.since(first)) {
    if (m.t > held + 8 * 0.25) break;
    EXPECT_EQ(m.v, 0.15) << "a held key stopped at " << m.t - held << " s";
  }
}

TEST(KeyboardTeleopNode, SigintSendsZeroAndRestoresTheTerminal) {
  CmdVelLog log;
  NodeProcess node;
  startOnPty(&node, log);
  const termios before = node.initialTerminalSettings();  // the fresh pty's, before the node ran
  node.type("i");
  ASSERT_FALSE(std::isnan(log.waitFor(0.15, 0.0, now() - 1.0)));
  node.type("i");
  node.signal(SIGINT);
  EXPECT_EQ(node.waitExit(10.0), 0) << node.output();
  ros::WallDuration(0.3).sleep();
  const std::vector<Received> all = log.all();
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all.back().v, 0.0) << "the last command is a zero";
  EXPECT_EQ(all.back().w, 0.0);
  const termios after = node.terminalSettings();
  EXPECT_EQ(after.c_lflag, before.c_lflag) << "ICANON, ECHO, ISIG as before";
  EXPECT_EQ(after.c_iflag, before.c_iflag);
  EXPECT_NE(after.c_lflag & ICANON, 0u);
  EXPECT_NE(after.c_lflag & ECHO, 0u);
  EXPECT_NE(node.output().find("zero command sent"), std::string::npos) << node.output();
}

TEST(KeyboardTeleopNode, RefusesWithoutTerminalOrWithBadParameterAndPublishesNothing) {
  CmdVelLog log;
  const double t = now();
  {
    NodeProcess node;  // stdin /dev/null: no terminal
    node.start({KEYBOARD_TELEOP, "__name:=keyboard_teleop_no_tty"}, NodeProcess::Terminal::kPipe);
    EXPECT_EQ(node.waitExit(30.0), 1);
    EXPECT_NE(node.output().find("not a terminal"), std::string::npos) << node.output();
    EXPECT_NE(node.output().find("rosrun amigobot_tracking keyboard_teleop"), std::string::npos);
  }
  {
    NodeProcess node;  // on a terminal, but speed above speed_max
    node.start({KEYBOARD_TELEOP, "__name:=keyboard_teleop_bad", "_speed:=0.5"}, NodeProcess::Terminal::kPty);
    EXPECT_EQ(node.waitExit(30.0), 1);
    EXPECT_NE(node.output().find("~speed: must be <= speed_max"), std::string::npos) << node.output();
  }
  // A robot file with a smaller diamond: the keys' ceilings default to it, and may not exceed it.
  const std::string slow = "/tmp/amigobot_teleop_slow_" + std::to_string(::getpid()) + ".yaml";
  std::ofstream(slow) << "v_max: 0.2\nw_max: 0.5\n";
  {
    NodeProcess node;  // the old default speed_max 0.3, above this robot's 0.2
    node.start({KEYBOARD_TELEOP, "__name:=keyboard_teleop_wide", "_robot_params:=" + slow, "_speed_max:=0.3"},
               NodeProcess::Terminal::kPty);
    EXPECT_EQ(node.waitExit(30.0), 1);
    EXPECT_NE(node.output().find("~speed_max: must be <= the robot's v_max 0.2 m/s (" + slow + "), got 0.3"),
              std::string::npos)
        << node.output();
  }
  {
    NodeProcess node;  // no speed_max: the robot's 0.2 is the ceiling the start speed must keep
    node.start({KEYBOARD_TELEOP, "__name:=keyboard_teleop_slow", "_robot_params:=" + slow, "_speed:=0.25"},
               NodeProcess::Terminal::kPty);
    EXPECT_EQ(node.waitExit(30.0), 1);
    EXPECT_NE(node.output().find("~speed: must be <= speed_max (0.2)"), std::string::npos) << node.output();
  }
  std::remove(slow.c_str());
  ros::WallDuration(0.5).sleep();
  EXPECT_TRUE(log.since(t).empty());
}

}  // namespace keyboard_teleop_test

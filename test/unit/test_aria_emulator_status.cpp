// The emulator's status protocol (aria/emulator_status.h): the writer and the parser agree,
// malformed lines are refused saying why, and the client waits out its reconnect period.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "amigobot_tracking/aria/emulator_status.h"
#include "emulator_process.h"

using namespace amigobot_tracking::aria;

TEST(EmulatorStatus, ParsesAStatusLine) {
  EmulatorStatus s;
  ASSERT_EQ(parseStatusLine("12.5 1.25 -0.5 0.75 0.2 -0.1 1 1 0", &s), "");
  EXPECT_DOUBLE_EQ(s.t, 12.5);
  EXPECT_DOUBLE_EQ(s.pose.x, 1.25);
  EXPECT_DOUBLE_EQ(s.pose.y, -0.5);
  EXPECT_DOUBLE_EQ(s.pose.theta, 0.75);
  EXPECT_DOUBLE_EQ(s.v, 0.2);
  EXPECT_DOUBLE_EQ(s.w, -0.1);
  EXPECT_TRUE(s.motors);
  EXPECT_TRUE(s.open);
  EXPECT_FALSE(s.watchdog);
}

TEST(EmulatorStatus, WriterAndParserRoundTrip) {
  for (int k = 0; k < 8; ++k) {
    EmulatorStatus in;
    in.t = 0.1234 * k;
    in.pose = {1.5 - k, -0.25 * k, std::remainder(0.9 * k, 2.0 * M_PI)};
    in.v = 0.05 * k;
    in.w = -0.125 * k;
    in.motors = k & 1;
    in.open = k & 2;
    in.watchdog = k & 4;
    EmulatorStatus out;
    const std::string line = formatStatusLine(in);
    ASSERT_EQ(parseStatusLine(line, &out), "") << line;
    EXPECT_EQ(out.t, in.t);  // %.17g: every double reads back exactly
    EXPECT_EQ(out.pose.x, in.pose.x);
    EXPECT_EQ(out.pose.y, in.pose.y);
    EXPECT_EQ(out.pose.theta, in.pose.theta);
    EXPECT_EQ(out.v, in.v);
    EXPECT_EQ(out.w, in.w);
    EXPECT_EQ(out.motors, in.motors);
    EXPECT_EQ(out.open, in.open);
    EXPECT_EQ(out.watchdog, in.watchdog);
  }
}

TEST(EmulatorStatus, HugeAndTinyValuesReadBackExactly) {
  // Written with %.6f, 1e300 was 300 digits and the line did not parse back.
  for (const double value : {1e300, -1e300, std::numeric_limits<double>::max(), 1e-300,
                             std::numeric_limits<double>::min(), -0.1}) {
    EmulatorStatus in;
    in.t = value;
    in.pose = {value, -value, value};
    in.v = value;
    in.w = value;
    EmulatorStatus out;
    const std::string line = formatStatusLine(in);
    ASSERT_EQ(parseStatusLine(line, &out), "") << line;
    EXPECT_LT(line.size(), 200u) << line;
    EXPECT_EQ(out.t, value) << line;
    EXPECT_EQ(out.pose.y, -value) << line;
    EXPECT_EQ(out.w, value) << line;
  }
}

TEST(EmulatorStatus, RejectsBadLinesSayingWhy) {
  EmulatorStatus s;
  s.t = 42.0;
  EXPECT_NE(parseStatusLine("1 2 3", &s).find("t x y theta"), std::string::npos);
  EXPECT_NE(parseStatusLine("1 2 3 4 5 6 1 1 0 9", &s).find("extra"), std::string::npos);
  EXPECT_NE(parseStatusLine("1 nan 3 4 5 6 1 1 0", &s), "");
  EXPECT_NE(parseStatusLine("1 2 3 4 5 6 1 2 0", &s).find("0 or 1"), std::string::npos);
  EXPECT_NE(parseStatusLine("1 2 3 4 5 6 1 1", &s).find("0 or 1"), std::string::npos);
  EXPECT_NE(parseStatusLine("", &s), "");
  EXPECT_NE(parseStatusLine("t x y theta v w 1 1 0", &s), "");
  EXPECT_DOUBLE_EQ(s.t, 42.0) << "a refused line must leave the status alone";
}

TEST(EmulatorStatus, ClientRepeatsTheFailureUntilTheReconnectPeriodHasPassed) {
  const int port = amigobot_test::freePort();  // nobody listens there
  StatusClient client("127.0.0.1", port, 1.0, 0.5);
  EmulatorStatus s;
  const std::string first = client.query(&s);
  EXPECT_NE(first.find("cannot connect"), std::string::npos) << first;
  EXPECT_FALSE(client.connected());
  // The emulator appears at once, but the client waits out the period before it looks again.
  amigobot_test::EmulatorProcess emu({"--status-port", std::to_string(port)});
  EXPECT_EQ(client.query(&s), first);
  EXPECT_TRUE(amigobot_test::waitFor([&] { return client.query(&s).empty(); }, 5.0));
  EXPECT_TRUE(client.connected());
}

TEST(EmulatorControl, TeleportLinesRoundTripAndBadOnesAreRefusedSayingWhy) {
  amigobot_tracking::core::Pose2 p{0.1234567890123, -1e3, -3.0};
  amigobot_tracking::core::Pose2 q;
  ASSERT_EQ(parseControlLine(formatTeleportLine(p), &q), "") << formatTeleportLine(p);
  EXPECT_EQ(q.x, p.x);
  EXPECT_EQ(q.y, p.y);
  EXPECT_EQ(q.theta, p.theta);
  q = {7.0, 7.0, 7.0};
  EXPECT_NE(parseControlLine("jump 1 2 3", &q).find("unknown command"), std::string::npos);
  EXPECT_NE(parseControlLine("", &q).find("unknown command"), std::string::npos);
  EXPECT_NE(parseControlLine("teleport 1 2", &q).find("teleport x y theta"), std::string::npos);
  EXPECT_NE(parseControlLine("teleport 1 2 3 4", &q).find("extra"), std::string::npos);
  EXPECT_NE(parseControlLine("teleport nan 2 3", &q), "");  // libstdc++ does not read nan or inf
  EXPECT_NE(parseControlLine("teleport 1 2 1e400", &q), "");
  EXPECT_NE(parseControlLine("teleport 1e5 2 3", &q).find("1e4 m"), std::string::npos);
  EXPECT_NE(parseControlLine("teleport 1 -2e4 3", &q).find("1e4 m"), std::string::npos);
  EXPECT_EQ(q.x, 7.0) << "a refused line must leave the pose alone";
}

// The tool end to end: --control-port moves the truth its status socket reports; a bad line
// is answered with the reason and changes nothing; a socket nobody serves is named.
TEST(EmulatorControl, TheEmulatorsControlSocketTeleportsItsRobot) {
  const int control = amigobot_test::freePort();
  amigobot_test::EmulatorProcess emu({"--control-port", std::to_string(control)});
  StatusClient status("127.0.0.1", emu.statusPort(), 1.0);
  EmulatorStatus s;
  ASSERT_EQ(requestTeleport("127.0.0.1", control, {1.5, -0.5, 1.0}, 2.0), "");
  ASSERT_TRUE(amigobot_test::waitFor([&] { return status.query(&s).empty() && s.pose.x == 1.5; }, 2.0))
      << "status still says x = " << s.pose.x;
  EXPECT_EQ(s.pose.y, -0.5);
  EXPECT_EQ(s.pose.theta, 1.0);

  const int fd = amigobot_test::connectTcp(control);
  ASSERT_GE(fd, 0);
  const std::string bad = "teleport 1 2e4 0\n";
  ASSERT_EQ(::write(fd, bad.data(), bad.size()), static_cast<ssize_t>(bad.size()));
  std::string reply;
  char c;
  while (reply.find('\n') == std::string::npos && ::read(fd, &c, 1) == 1) reply += c;
  ::close(fd);
  EXPECT_EQ(reply.rfind("error: ", 0), 0u) << reply;
  EXPECT_NE(reply.find("within 1e4 m"), std::string::npos) << reply;
  ASSERT_EQ(status.query(&s), "");
  EXPECT_EQ(s.pose.x, 1.5) << "a refused line moved the robot";

  const std::string none = requestTeleport("127.0.0.1", amigobot_test::freePort(), {0.0, 0.0, 0.0}, 1.0);
  EXPECT_NE(none.find("control socket"), std::string::npos) << none;
}

// The baud over a real pseudo-terminal against amigobot_emulator, whose pty models the
// robot's UART (aria/emulator_line.h): the switch to the parameter set's 38400 after CONFIG,
// recovery of a robot a crashed session left open at another baud, a clear refusal of a
// robot that answers at none, and what the faster line buys (figures printed).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "amigobot_tracking/aria/client.h"
#include "emulator_process.h"

using namespace amigobot_test;
using namespace amigobot_tracking::aria;

namespace {

std::string ptyLink(const std::string& tag) { return "/tmp/amigobot_baud_" + tag + "_" + std::to_string(::getpid()); }

std::unique_ptr<AriaClient> startClient(const ClientConfig& config) {
  auto client = std::make_unique<AriaClient>(config, [](LogLevel, const std::string&) {});
  client->start();
  return client;
}

bool connected(const AriaClient& client) {
  const ClientStatus s = client.status();
  return s.link == LinkState::kConnected && s.robot.has_value();
}

// SIPs keep arriving (and parse) for `seconds`: the two ends agree on the baud.
bool sipsFlow(const AriaClient& client, double seconds) {
  const std::uint64_t before = client.status().sips;
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  return client.status().sips >= before + static_cast<std::uint64_t>(5 * seconds);
}

}  // namespace

TEST(AriaBaud, ConnectsAt9600AndSwitchesTo38400) {
  const std::string link = ptyLink("switch");
  EmulatorProcess emu({}, 0, link);
  auto client = startClient(emulatorClientConfig(link));
  ASSERT_TRUE(waitFor([&] { return connected(*client); }, 20.0)) << client->status().last_error;
  ASSERT_TRUE(client->status().config);
  EXPECT_EQ(client->status().config->auto_baud.value_or(0), 2);
  EXPECT_EQ(client->status().baud, 38400);
  EXPECT_TRUE(sipsFlow(*client, 1.5));
  EXPECT_EQ(client->status().connections, 1u);
  EXPECT_EQ(client->status().baud_recoveries, 0u);
}

TEST(AriaBaud, StaysAtTheConnectBaudWhenTheParameterSetSaysSo) {
  const std::string link = ptyLink("stay");
  EmulatorProcess emu({}, 0, link);
  ClientConfig config = emulatorClientConfig(link);
  config.robot.switch_to_baud = 9600;
  auto client = startClient(config);
  ASSERT_TRUE(waitFor([&] { return connected(*client); }, 20.0)) << client->status().last_error;
  EXPECT_EQ(client->status().baud, 9600);
  EXPECT_TRUE(sipsFlow(*client, 1.0));
}

TEST(AriaBaud, TcpHasNoBaudAndSendsNoHostBaud) {
  EmulatorProcess emu;
  auto client = startClient(emulatorClientConfig(emu.address()));
  ASSERT_TRUE(waitFor([&] { return connected(*client); }, 20.0)) << client->status().last_error;
  EXPECT_EQ(client->status().baud, 0);
  EXPECT_TRUE(sipsFlow(*client, 1.0));
}

// A frozen robot keeps its 38400 while the driver gives the link up and comes back at the
// connect baud: the CLOSE cycle frees the robot and the switch is made again.
TEST(AriaBaud, AReconnectAfterLinkLossRepeatsTheWholeSequence) {
  const std::string link = ptyLink("loss");
  EmulatorProcess emu({}, 0, link);
  auto client = startClient(emulatorClientConfig(link));
  ASSERT_TRUE(waitFor([&] { return connected(*client); }, 20.0)) << client->status().last_error;
  ASSERT_EQ(client->status().baud, 38400);
  emu.signal(SIGSTOP);
  EXPECT_TRUE(waitFor([&] { return client->status().link != LinkState::kConnected; }, 10.0));
  emu.signal(SIGCONT);
  ASSERT_TRUE(waitFor([&] { return connected(*client) && client->status().connections == 2; }, 30.0))
      << client->status().last_error;
  EXPECT_GE(client->status().baud_recoveries, 1u);
  EXPECT_EQ(client->status().baud, 38400);
  EXPECT_TRUE(sipsFlow(*client, 1.0));
}

class AriaBaudLeftOpen : public ::testing::TestWithParam<int> {};

TEST_P(AriaBaudLeftOpen, ClosesTheRobotAtItsBaudThenConnects) {
  const std::string link = ptyLink("open" + std::to_string(GetParam()));
  EmulatorProcess emu({"--left-open-at", std::to_string(GetParam())}, 0, link);
  ASSERT_TRUE(emu.truth().open);
  auto client = startClient(emulatorClientConfig(link));
  ASSERT_TRUE(waitFor([&] { return connected(*client); }, 30.0)) << client->status().last_error;
  EXPECT_GE(client->status().baud_recoveries, 1u);
  EXPECT_EQ(client->status().baud, 38400);
  EXPECT_TRUE(sipsFlow(*client, 1.0));
}

INSTANTIATE_TEST_SUITE_P(Bauds, AriaBaudLeftOpen, ::testing::Values(38400, 115200));

TEST(AriaBaud, RefusesARobotThatAnswersAtNoBaudAndSaysWhy) {
  const std::string link = ptyLink("deaf");
  EmulatorProcess emu({"--left-open-at", "4800"}, 0, link);
  ClientConfig config = emulatorClientConfig(link);
  config.max_sync_tries = 6;
  config.sync_timeout = 0.5;
  auto client = startClient(config);
  ASSERT_TRUE(waitFor([&] { return !client->status().last_error.empty(); }, 20.0));
  const std::string error = client->status().last_error;
  EXPECT_NE(error.find("no SYNC0/1/2 handshake"), std::string::npos) << error;
  EXPECT_NE(error.find("CLOSE at 9600, 38400, 115200, 19200, 57600 baud"), std::string::npos) << error;
  EXPECT_NE(error.find("formed no packet"), std::string::npos) << error;
  EXPECT_EQ(client->status().connections, 0u);
  EXPECT_TRUE(emu.truth().open);  // never reached
}

namespace {

struct LinkFigures {
  double sip_rate = 0.0;        // [Hz]
  double rx_rate = 0.0;         // [bytes/s] robot to host
  double tx_rate = 0.0;         // [bytes/s] host to robot
  double latency = 0.0;         // [s] mean, velocity request to the first SIP showing motion
};

LinkFigures measure(int switch_to_baud) {
  const std::string link = ptyLink("figures" + std::to_string(switch_to_baud));
  EmulatorProcess emu({}, 0, link);
  ClientConfig config = emulatorClientConfig(link);
  config.robot.switch_to_baud = switch_to_baud;
  config.enable_motors = true;
  config.trans_accel = config.trans_decel = 2.0;
  auto client = startClient(config);
  LinkFigures f;
  if (!waitFor([&] { return connected(*client) && emu.truth().motors; }, 20.0)) return f;
  const auto speed = [&] { return std::abs(client->status().robot->odometry.twist.v); };
  // Utilisation while driving: the driver refreshes its command and the robot sends SIPs.
  client->setVelocity({0.05, 0.0});
  const ClientStatus a = client->status();
  const auto t0 = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(std::chrono::seconds(3));
  const ClientStatus b = client->status();
  const double span = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  f.sip_rate = static_cast<double>(b.sips - a.sips) / span;
  f.rx_rate = static_cast<double>(b.bytes_received - a.bytes_received) / span;
  f.tx_rate = static_cast<double>(b.bytes_sent - a.bytes_sent) / span;
  const int trials = 10;
  for (int k = 0; k < trials; ++k) {
    client->setVelocity({0.0, 0.0});
    waitFor([&] { return speed() < 1e-4; }, 5.0);
    std::this_thread::sleep_for(std::chrono::milliseconds(37 * k % 100));  // spread over the SIP phase
    const auto start = std::chrono::steady_clock::now();
    client->setVelocity({0.1, 0.0});
    waitFor([&] { return speed() > 1e-3; }, 5.0);
    f.latency += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / trials;
  }
  client->setVelocity({0.0, 0.0});
  return f;
}

}  // namespace

TEST(AriaBaud, TheFasterLineCutsTheLatencyAndTheLoad) {
  const LinkFigures slow = measure(9600), fast = measure(38400);
  for (const auto& [baud, f] : {std::pair<int, LinkFigures>{9600, slow}, {38400, fast}}) {
    const double capacity = baud / 10.0;
    std::printf("[figures] %5d baud: SIP %.1f Hz, robot->host %.0f B/s (%.0f%% of %.0f), host->robot %.0f B/s "
                "(%.0f%%), request-to-SIP latency %.0f ms\n",
                baud, f.sip_rate, f.rx_rate, 100.0 * f.rx_rate / capacity, capacity, f.tx_rate,
                100.0 * f.tx_rate / capacity, 1e3 * f.latency);
  }
  EXPECT_GT(slow.sip_rate, 8.0);
  EXPECT_GE(fast.sip_rate, slow.sip_rate - 1.0);
  EXPECT_GT(slow.rx_rate, 0.0);
  EXPECT_LT(fast.latency, slow.latency);  // a SIP takes ~55 ms at 9600, ~14 ms at 38400
}

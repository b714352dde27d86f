// Driver configuration: port parsing (serial vs host:port) and validation messages that
// name the bad field.
#include <gtest/gtest.h>

#include <cmath>

#include "amigobot_tracking/aria/client.h"
#include "amigobot_tracking/aria/transport.h"

using namespace amigobot_tracking::aria;

TEST(AriaTransport, HostPortIsTcpAndDevicesAreSerial) {
  EXPECT_TRUE(isTcpAddress("localhost:8101"));
  EXPECT_TRUE(isTcpAddress("10.0.126.11:8102"));
  EXPECT_FALSE(isTcpAddress("/dev/ttyUSB0"));
  EXPECT_FALSE(isTcpAddress("/tmp/odd:123"));  // a path with a colon is still a device
  EXPECT_FALSE(isTcpAddress("localhost:"));
  EXPECT_FALSE(isTcpAddress("localhost:81a"));
  EXPECT_TRUE(makeTransport("localhost:8101", 9600)->describe().find("tcp localhost:8101") != std::string::npos);
  EXPECT_TRUE(makeTransport("/dev/ttyUSB0", 9600)->isSerial());
  EXPECT_THROW(makeTransport("localhost:99999", 9600), std::invalid_argument);
  EXPECT_THROW(makeTransport("", 9600), std::invalid_argument);
  EXPECT_THROW(makeTransport("/dev/ttyUSB0", 0), std::invalid_argument);
}

TEST(AriaTransport, OpeningAMissingDeviceSaysWhichOne) {
  auto t = makeTransport("/nonexistent/ttyAMIGO", 9600);
  try {
    t->open();
    FAIL() << "opened a missing device";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/ttyAMIGO"), std::string::npos) << e.what();
  }
}

TEST(AriaClientConfig, DefaultsAreValid) { EXPECT_EQ(ClientConfig().validate(), ""); }

TEST(AriaClientConfig, BadFieldsAreNamed) {
  auto error = [](auto mutate) {
    ClientConfig c;
    mutate(c);
    return c.validate();
  };
  EXPECT_NE(error([](ClientConfig& c) { c.v_max = std::nan(""); }).find("v_max"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.w_max = 10.0; }).find("w_max"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.command_timeout = -1; }).find("cmd_vel_timeout"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.command_refresh = 2.5; }).find("watchdog"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.port = ""; }).find("port"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.robot.vel2_divisor = 0; }).find("robot.vel2_divisor"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.max_packet_count = 300; }).find("max_packet_count"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.reconnect_delay_max = 0.1; }).find("reconnect_delay_max"), std::string::npos);
  ClientConfig bad;
  bad.v_max = -1;
  EXPECT_THROW(AriaClient client(bad), std::invalid_argument);
}

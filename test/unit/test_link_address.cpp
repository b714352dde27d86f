// The one host:port rule (link/address.h): what is TCP, what is a device, and errors that
// quote the text and say what is wrong with it.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "amigobot_tracking/link/address.h"

using amigobot_tracking::link::formatTcpAddress;
using amigobot_tracking::link::parseTcpAddress;
using amigobot_tracking::link::TcpAddress;

namespace {

// The message parseTcpAddress throws for `text` ("" when it does not throw).
std::string errorOf(const std::string& text) {
  try {
    parseTcpAddress(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(LinkAddress, HostPortIsTcp) {
  const auto a = parseTcpAddress("localhost:8101");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->host, "localhost");
  EXPECT_EQ(a->port, 8101);
  const auto b = parseTcpAddress("10.0.126.11:2111");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->host, "10.0.126.11");
  EXPECT_EQ(b->port, 2111);
  EXPECT_EQ(parseTcpAddress("h:1")->port, 1);
  EXPECT_EQ(parseTcpAddress("h:65535")->port, 65535);
  EXPECT_EQ(parseTcpAddress("h:08101")->port, 8101);  // five digits, a leading zero
}

TEST(LinkAddress, Ipv6InBrackets) {
  const auto a = parseTcpAddress("[::1]:10940");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->host, "::1");
  EXPECT_EQ(a->port, 10940);
  EXPECT_EQ(parseTcpAddress("[fe80::1%eth0]:2111")->host, "fe80::1%eth0");
  EXPECT_EQ(formatTcpAddress(*a), "[::1]:10940");
  EXPECT_EQ(formatTcpAddress(TcpAddress{"robot", 8101}), "robot:8101");
}

TEST(LinkAddress, DevicePathsAreNotTcp) {
  EXPECT_FALSE(parseTcpAddress("/dev/ttyUSB0"));
  EXPECT_FALSE(parseTcpAddress("/tmp/odd:123"));  // a path with a colon is still a device
  EXPECT_FALSE(parseTcpAddress("./pty:1"));
  EXPECT_FALSE(parseTcpAddress("ttyACM0"));
}

TEST(LinkAddress, MalformedAddressesAreErrorsQuotingTheText) {
  const struct {
    const char* text;
    const char* says;
  } cases[] = {
      {"", "empty"},
      {"localhost:", "no port"},
      {"localhost:81a", "'81a' is not a number"},
      {"localhost:99999", "99999 is outside 1..65535"},
      {"localhost:0", "0 is outside"},
      {"localhost:123456", "'123456' is not a number"},  // the old sensors rule took six digits
      {"localhost:-1", "'-1' is not a number"},
      {":8101", "no host"},
      {"my host:8101", "holds a blank"},
      {"::1:8101", "more than one ':'"},
      {"[::1]8101", "no ':port' after ']'"},
      {"[::1:8101", "'[' without ']'"},
      {"[]:8101", "empty IPv6 host"},
      {"[robot]:8101", "'robot' is not an IPv6 address"},
      {"[::1]:", "no port"},
  };
  for (const auto& c : cases) {
    const std::string error = errorOf(c.text);
    EXPECT_NE(error.find(std::string("'") + c.text + "'"), std::string::npos) << c.text << " -> " << error;
    EXPECT_NE(error.find(c.says), std::string::npos) << c.text << " -> " << error;
    EXPECT_NE(error.find("expected host:port"), std::string::npos) << c.text << " -> " << error;
  }
}

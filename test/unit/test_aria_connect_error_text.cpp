// Error texts carry the library's message, never a backtrace frame or a stray byte
// (core/support/error_text.h): on real MRPT exceptions (a TCP connect to a port nobody serves); and
// the robot link's transport (link::TcpClient) and the emulator's status client, which printed
// "cannot connect: [6 ]     0x556f10c727a1" when they were on MRPT's socket, name the reason once.
#include <gtest/gtest.h>

#include <regex>
#include <stdexcept>
#include <string>

#include <mrpt/comms/CClientTCPSocket.h>

#include "amigobot_tracking/aria/emulator_status.h"
#include "amigobot_tracking/aria/transport.h"
#include "amigobot_tracking/core/support/error_text.h"
#include "child_process.h"

using amigobot_tracking::core::libraryMessage;

namespace {

// What MRPT's client socket throws when the port is closed.
std::string mrptConnectError(int port) {
  try {
    mrpt::comms::CClientTCPSocket socket;
    socket.connect("127.0.0.1", static_cast<unsigned short>(port), 1000);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// No address, no control byte, no line break: one line a user can read.
void expectReadable(const std::string& text) {
  EXPECT_FALSE(std::regex_search(text, std::regex("0x[0-9a-fA-F]{6,}"))) << text;
  for (const char c : text) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "byte " << int(c) << " in '" << text << "'";
}

}  // namespace

TEST(ErrorText, TakesTheMessageLineOfARealMrptException) {
  const int port = amigobot_test::freePort();
  const std::string what = mrptConnectError(port);
  ASSERT_NE(what.find("Message:"), std::string::npos) << "MRPT's text changed its form:\n" << what;
  ASSERT_NE(what.find("0x"), std::string::npos) << "expected a backtrace in:\n" << what;
  const std::string message = libraryMessage(what);
  EXPECT_EQ(message, "Error connecting to 127.0.0.1:" + std::to_string(port) + ". Error: Connection refused.") << what;
  expectReadable(message);
}

TEST(ErrorText, KeepsAPlainMessageAndCleansStrayBytes) {
  EXPECT_EQ(libraryMessage("serial /dev/ttyUSB8: cannot open: No such file or directory"),
            "serial /dev/ttyUSB8: cannot open: No such file or directory");
  EXPECT_EQ(libraryMessage("first line\nsecond line\n"), "first line");
  EXPECT_EQ(libraryMessage(std::string("reply '\x02sRA\x03\xff'")), "reply '?sRA?" "?'");
  EXPECT_EQ(libraryMessage("==== MRPT exception ====\nMessage:  \nLocation: a.cpp:3\n[0 ]     0x7f53aa\n"),
            "unknown error");  // an empty message and frames only: nothing worth showing
  EXPECT_EQ(libraryMessage(""), "unknown error");
  EXPECT_EQ(libraryMessage(std::string(500, 'x'), 20), std::string(17, 'x') + "...");
}

TEST(ErrorText, TheRobotLinkNamesWhyItCannotConnect) {
  const int port = amigobot_test::freePort();
  const auto link = amigobot_tracking::aria::makeTransport("127.0.0.1:" + std::to_string(port), 0);
  try {
    link->open();
    FAIL() << "connected to a port nobody serves";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "tcp 127.0.0.1:" + std::to_string(port) + ": cannot connect: Connection refused");
    expectReadable(e.what());
  }
}

// The path of the line quoted from a user's log: "emulator status: tcp ...: cannot connect: ...".
TEST(ErrorText, TheEmulatorStatusClientNamesWhyItCannotConnect) {
  amigobot_tracking::aria::StatusClient status("127.0.0.1", amigobot_test::freePort(), 0.5);
  amigobot_tracking::aria::EmulatorStatus s;
  const std::string error = status.query(&s);
  EXPECT_NE(error.find("emulator status: tcp 127.0.0.1:"), std::string::npos) << error;
  EXPECT_NE(error.find("Connection refused"), std::string::npos) << error;
  expectReadable(error);
}

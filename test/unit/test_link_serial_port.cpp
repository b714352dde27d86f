// The serial opener and the emulator's pty (link/serial_port.h, link/emulator_link.h) on a
// real pseudo-terminal: raw bytes both ways, the speed the client sets seen on the
// emulator's side, a non-standard rate, and errors naming the device.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdint>
#include <stdexcept>
#include <string>

#include "amigobot_tracking/link/emulator_link.h"
#include "amigobot_tracking/link/serial_port.h"

using namespace amigobot_tracking::link;

namespace {

std::string tempLink() { return "/tmp/amigobot_test_link_" + std::to_string(::getpid()); }

}  // namespace

TEST(LinkSerialPort, RawBytesBothWaysOverTheEmulatorsPty) {
  PseudoTerminal pty;
  pty.open(tempLink(), 9600);
  EXPECT_EQ(lineBaud(pty.slave()), 9600);
  SerialPort port;
  port.open(tempLink(), 115200);
  EXPECT_EQ(lineBaud(pty.slave()), 115200);  // both ends of a pty share the termios
  // Raw: no echo, CR/LF and 0x03 (Ctrl-C) pass untouched.
  const std::string sent("\x03\r\n\xfa\xfb", 5);
  port.write(sent.data(), sent.size());
  char buffer[16] = {};
  std::size_t got = 0;
  for (int i = 0; i < 50 && got < sent.size(); ++i) {
    const ssize_t n = ::read(pty.master(), buffer + got, sizeof(buffer) - got);
    if (n > 0) got += static_cast<std::size_t>(n);
    else ::usleep(2000);
  }
  EXPECT_EQ(std::string(buffer, got), sent);
  sendAvailable(pty.master(), "ok", 2);
  char reply[4] = {};
  EXPECT_EQ(port.read(reply, sizeof(reply), 500), 2u);
  EXPECT_EQ(std::string(reply, 2), "ok");
  EXPECT_EQ(port.read(reply, sizeof(reply), 10), 0u);  // nothing more: a timeout, not an error
}

TEST(LinkSerialPort, SwitchesToAnyRateIncludingNonStandardOnes) {
  PseudoTerminal pty;
  pty.open(tempLink());
  SerialPort port;
  port.open(tempLink(), 256000);  // the RPLIDAR A3's: no Bxxx constant
  EXPECT_EQ(port.baud(), 256000);
  port.setBaud(38400);
  EXPECT_EQ(lineBaud(pty.slave()), 38400);
}

TEST(LinkSerialPort, ErrorsNameTheDevice) {
  SerialPort port;
  try {
    port.open("/nonexistent/ttyLASER", 115200);
    FAIL() << "opened a missing device";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/ttyLASER"), std::string::npos) << e.what();
  }
  try {
    port.open("/dev/null", 115200);
    FAIL() << "opened /dev/null as a serial port";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/null"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not a serial port"), std::string::npos) << e.what();
  }
}

TEST(LinkTcpListener, AnyFreePortAndABadBindAddressNamed) {
  TcpListener listener;
  listener.open("127.0.0.1", 0);
  EXPECT_GT(listener.port(), 0);
  EXPECT_EQ(listener.accept(), -1);  // nobody waiting
  TcpListener bad;
  try {
    bad.open("localhost", 0);
    FAIL() << "bound a name";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'localhost'"), std::string::npos) << e.what();
  }
}

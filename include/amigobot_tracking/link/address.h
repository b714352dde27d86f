// The one rule for a device address, shared by the robot's and the lasers' drivers: a text
// that names a TCP endpoint ("host:port", "[IPv6]:port") or a device path (anything else:
// "/dev/ttyUSB0", "/tmp/odd:123", "ttyACM0").
//
// Rule: a text with a colon that does not start with '/' or '.' means TCP and must then be
// well formed: a host without blanks or '/', a port of 1..5 digits within 1..65535, an IPv6
// host in brackets. A malformed one is an error naming the text, never a serial device of
// that name (which would fail later with a puzzling "cannot open").
#pragma once

#include <optional>
#include <string>

namespace amigobot_tracking {
namespace link {

struct TcpAddress {
  std::string host;  // a name, an IPv4 address, or an IPv6 address without its brackets
  int port = 0;      // 1..65535
};

// The TCP endpoint `text` names, or nullopt for a device path. Throws std::invalid_argument
// naming `text` and what is wrong with it for an empty text or a malformed host:port.
std::optional<TcpAddress> parseTcpAddress(const std::string& text);

// "host:port", with brackets around an IPv6 host: the text parseTcpAddress reads back.
std::string formatTcpAddress(const TcpAddress& address);

}  // namespace link
}  // namespace amigobot_tracking

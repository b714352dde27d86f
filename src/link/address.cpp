#include "amigobot_tracking/link/address.h"

#include <stdexcept>

namespace amigobot_tracking {
namespace link {
namespace {

constexpr const char* kExpected = "(expected host:port, [IPv6]:port or a device path such as /dev/ttyUSB0)";

std::invalid_argument malformed(const std::string& text, const std::string& why) {
  return std::invalid_argument("address '" + text + "': " + why + " " + kExpected);
}

int parsePort(const std::string& text, const std::string& digits) {
  if (digits.empty()) throw malformed(text, "no port after the colon");
  if (digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos) {
    throw malformed(text, "port '" + digits + "' is not a number within 1..65535");
  }
  const int port = std::stoi(digits);
  if (port < 1 || port > 65535) throw malformed(text, "port " + digits + " is outside 1..65535");
  return port;
}

}  // namespace

std::optional<TcpAddress> parseTcpAddress(const std::string& text) {
  if (text.empty()) throw malformed(text, "empty");
  // A path may hold a colon (a pty link in /tmp): only a relative or absolute path is a device.
  if (text.front() == '/' || text.front() == '.' || text.find(':') == std::string::npos) return std::nullopt;
  TcpAddress address;
  std::string port;
  if (text.front() == '[') {
    const auto close = text.find(']');
    if (close == std::string::npos) throw malformed(text, "'[' without ']'");
    address.host = text.substr(1, close - 1);
    if (address.host.empty()) throw malformed(text, "empty IPv6 host in brackets");
    const std::string bare = address.host.substr(0, address.host.find('%'));  // fe80::1%eth0: a zone after '%'
    if (bare.empty() || bare.find(':') == std::string::npos ||
        bare.find_first_not_of("0123456789abcdefABCDEF:.") != std::string::npos) {
      throw malformed(text, "'" + address.host + "' is not an IPv6 address");
    }
    if (close + 1 >= text.size() || text[close + 1] != ':') throw malformed(text, "no ':port' after ']'");
    port = text.substr(close + 2);
  } else {
    const auto colon = text.find(':');
    if (text.find(':', colon + 1) != std::string::npos) throw malformed(text, "more than one ':' (an IPv6 host goes in brackets)");
    address.host = text.substr(0, colon);
    port = text.substr(colon + 1);
    if (address.host.empty()) throw malformed(text, "no host before the colon");
    if (address.host.find_first_of(" \t\r\n/[]") != std::string::npos) {
      throw malformed(text, "host '" + address.host + "' holds a blank, '/' or a bracket");
    }
  }
  address.port = parsePort(text, port);
  return address;
}

std::string formatTcpAddress(const TcpAddress& address) {
  const bool ipv6 = address.host.find(':') != std::string::npos;
  return (ipv6 ? "[" + address.host + "]" : address.host) + ":" + std::to_string(address.port);
}

}  // namespace link
}  // namespace amigobot_tracking

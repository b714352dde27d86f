#include "amigobot_tracking/sensors/transport_address.h"

#include <regex>
#include <stdexcept>

namespace amigobot_tracking {
namespace sensors {

bool splitTcpAddress(const std::string& address, std::string* host, int* port) {
  static const std::regex tcp(R"(([^/:][^:]*):([0-9]{1,6}))");
  std::smatch match;
  if (!std::regex_match(address, match, tcp)) return false;
  const int number = std::stoi(match[2].str());
  if (number < 1 || number > 65535) throw std::invalid_argument("port: TCP port out of range in '" + address + "'");
  *host = match[1].str();
  *port = number;
  return true;
}

}  // namespace sensors
}  // namespace amigobot_tracking

// "host:port" (port all digits, 1..65535) names a TCP device, anything else a serial one.
#pragma once

#include <string>

namespace amigobot_tracking {
namespace sensors {

// True for a TCP address (then *host and *port are set); throws std::invalid_argument for
// "host:port" with a port out of range.
bool splitTcpAddress(const std::string& address, std::string* host, int* port);

}  // namespace sensors
}  // namespace amigobot_tracking

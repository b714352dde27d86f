// CoLa-A (SICK TiM5xx, LMS1xx): its LaserProtocol, and the driver's device and the emulator's
// session it hands out. Only CoLa-A's own files and the registry include this: the rest
// reaches it through LaserProtocol.
#pragma once

#include <memory>
#include <string>

#include "amigobot_tracking/sensors/laser_protocol.h"

namespace amigobot_tracking {
namespace sensors {

const LaserProtocol& colaProtocol();  // cola_protocol.cpp

// The driver's CoLa-A client (cola_device.cpp). model: sick_tim5xx | sick_lms1xx; port: "host:port".
std::unique_ptr<LaserDevice> openCola(const std::string& model, const std::string& port);
// The emulator's session (cola_session.cpp).
std::unique_ptr<LaserSession> makeColaSession(const LaserModel& model, const std::string& serial);

}  // namespace sensors
}  // namespace amigobot_tracking

// Slamtec's RPLIDAR protocol (A1, A2, A3): its LaserProtocol, and the driver's device and
// the emulator's session it hands out. Only the RPLIDAR's own files and the registry include
// this: the rest reaches it through LaserProtocol.
#pragma once

#include <memory>
#include <string>

#include "amigobot_tracking/sensors/laser_protocol.h"

namespace amigobot_tracking {
namespace sensors {

const LaserProtocol& rplidarProtocol();  // rplidar_protocol.cpp

// The driver's client (rplidar_device.cpp): port a serial device, baud 115200 | 256000.
std::unique_ptr<LaserDevice> openRplidar(const std::string& port, int baud = 115200);
// The emulator's session (rplidar_session.cpp).
std::unique_ptr<LaserSession> makeRplidarSession(const LaserModel& model, const std::string& serial);

}  // namespace sensors
}  // namespace amigobot_tracking

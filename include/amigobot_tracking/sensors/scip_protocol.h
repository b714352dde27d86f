// SCIP 2.0 (Hokuyo URG-04LX): its LaserProtocol, and the driver's device and the emulator's
// session it hands out. Only SCIP's own files and the registry include this: the rest of the
// package reaches SCIP through LaserProtocol.
#pragma once

#include <memory>
#include <string>

#include "amigobot_tracking/sensors/laser_protocol.h"

namespace amigobot_tracking {
namespace sensors {

const LaserProtocol& scipProtocol();  // scip_protocol.cpp

// The driver's device: MRPT's CHokuyoURG (hokuyo_device.cpp). model: a registry entry
// speaking SCIP; port: a serial device or "host:port".
std::unique_ptr<LaserDevice> openHokuyo(const std::string& model, const std::string& port);
// The emulator's session (scip_session.cpp).
std::unique_ptr<LaserSession> makeScipSession(const LaserModel& model, const std::string& serial);

}  // namespace sensors
}  // namespace amigobot_tracking

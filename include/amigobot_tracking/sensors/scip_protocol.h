// SCIP 2.0 (Hokuyo URG-04LX): the protocol's numbers, its LaserProtocol, and the driver's
// device and the emulator's session it hands out. Only SCIP's own files and the registry
// include this: the rest of the package reaches SCIP through LaserProtocol.
#pragma once

#include <memory>
#include <string>

#include "amigobot_tracking/sensors/laser_protocol.h"

namespace amigobot_tracking {
namespace sensors {

// What a URG-04LX answers to PP (and VV, II): the defaults are its own.
struct ScipGeometry final : ProtocolGeometry {
  static constexpr const char* kName = "SCIP 2.0";
  int ares = 1024;  // steps per revolution
  int amin = 44, amax = 725, afrt = 384;  // first, last and front step
  int dmin_mm = 20, dmax_mm = 4000;
  int scan_rpm = 600;
  std::string product = "URG-04LX";  // the name in MODL (PP, II) and PROD (VV): each SCIP model's own

  // Steps AMIN..AMAX, step s at (s - AFRT) 2 pi / ARES.
  int beams() const override;
  double angleMin() const override;
  double angleIncrement() const override;
};

const LaserProtocol& scipProtocol();  // scip_protocol.cpp

// The driver's device: MRPT's CHokuyoURG (hokuyo_device.cpp). model: a registry entry
// speaking SCIP; port: a serial device or "host:port".
std::unique_ptr<LaserDevice> openHokuyo(const std::string& model, const std::string& port);
// The emulator's session (scip_session.cpp).
std::unique_ptr<LaserSession> makeScipSession(const LaserModel& model, const std::string& serial);

}  // namespace sensors
}  // namespace amigobot_tracking

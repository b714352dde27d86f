// Slamtec's RPLIDAR protocol (A1, A2, A3): the protocol's numbers, its LaserProtocol, and the
// driver's device and the emulator's session it hands out. Only the RPLIDAR's own files and
// the registry include this: the rest reaches it through LaserProtocol.
#pragma once

#include <memory>
#include <string>

#include "amigobot_tracking/sensors/laser_protocol.h"

namespace amigobot_tracking {
namespace sensors {

// A RPLIDAR turns clockwise seen from above and samples at its own clock, so the angles of
// one revolution are uneven and differ from the next one's. The driver publishes them on a
// fixed grid of `bins` over 360 deg (REP 117: +inf where no sample fell).
struct RplidarGeometry final : ProtocolGeometry {
  static constexpr const char* kName = "RPLIDAR";
  double sample_rate = 2000.0;  // [1/s] standard SCAN mode (GET_SAMPLERATE: 500 us)
  double speed_jitter = 0.02;   // emulator: revolution speed varies by up to this fraction
  int bins = 360;               // published grid: 1 deg, bin 0 at -180 deg

  // The published grid: bin i at -pi + i 2 pi / bins.
  int beams() const override { return bins; }
  double angleMin() const override;
  double angleIncrement() const override;
};

const LaserProtocol& rplidarProtocol();  // rplidar_protocol.cpp

// The driver's client (rplidar_device.cpp): port a serial device, baud 115200 | 256000.
std::unique_ptr<LaserDevice> openRplidar(const std::string& port, int baud = 115200);
// The emulator's session (rplidar_session.cpp).
std::unique_ptr<LaserSession> makeRplidarSession(const LaserModel& model, const std::string& serial);

}  // namespace sensors
}  // namespace amigobot_tracking

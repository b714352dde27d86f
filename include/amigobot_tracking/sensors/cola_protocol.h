// CoLa-A (SICK TiM5xx, LMS1xx): the protocol's numbers, its LaserProtocol, the LMS1xx's scan
// configurations, and the driver's device and the emulator's session it hands out. Only
// CoLa-A's own files and the registry include this: the rest reaches it through LaserProtocol.
#pragma once

#include <memory>
#include <string>

#include "amigobot_tracking/sensors/laser_protocol.h"

namespace amigobot_tracking {
namespace sensors {

// What a TiM5xx or an LMS1xx puts in its scan telegram (and the LMS1xx in its LMPscancfg
// reply); the defaults are the TiM5xx's.
struct ColaGeometry final : ProtocolGeometry {
  static constexpr const char* kName = "CoLa-A";
  int start_angle = -450000;  // [1/10000 deg] first beam, SICK frame (0 deg = +y of the device)
  int angular_step = 3333;    // [1/10000 deg]
  int beam_count = 811;
  int scan_frequency = 1500;  // [1/100 Hz]
  // The LMS1xx family: a client logs in, may set the scan (mLMPsetscancfg) and starts the
  // measurement (LMCstartmeas); a TiM5xx measures from power-up and has none of that.
  bool measures_on_command = false;

  // Beam i at start + i step, turned by -90 deg from SICK's frame (0 deg = +y) to REP 103.
  int beams() const override { return beam_count; }
  double angleMin() const override;
  double angleIncrement() const override;
};

const LaserProtocol& colaProtocol();  // cola_protocol.cpp

// The LMS1xx's scan configurations (mLMPsetscancfg): 25 Hz at 0.25 or 0.5 deg, 50 Hz at
// 0.5 deg. Throws std::invalid_argument naming the bad value for another combination, and
// std::logic_error for a model whose numbers are not CoLa-A's.
void setLms1xxScanConfig(LaserModel* model, double frequency_hz, double resolution_deg);

// The driver's CoLa-A client (cola_device.cpp). model: sick_tim5xx | sick_lms1xx; port: "host:port".
std::unique_ptr<LaserDevice> openCola(const std::string& model, const std::string& port);
// The emulator's session (cola_session.cpp).
std::unique_ptr<LaserSession> makeColaSession(const LaserModel& model, const std::string& serial);

}  // namespace sensors
}  // namespace amigobot_tracking

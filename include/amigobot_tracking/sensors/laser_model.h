// The lasers the emulator imitates and the driver knows: their geometry in the sensor frame
// (REP 103: x forward, angles counter-clockwise), rate and range, and the protocol numbers
// behind that geometry. The SCIP numbers are what a URG-04LX answers to PP; the CoLa-A
// numbers what a TiM5xx or an LMS1xx puts in its scan telegram (and the LMS1xx in its
// LMPscancfg reply); the RPLIDAR numbers its sample rate and motor speed.
#pragma once

#include <string>

#include "amigobot_tracking/core/perception/scan_obstacles.h"

namespace amigobot_tracking {
namespace sensors {

class LaserProtocol;  // laser_protocol.h

struct ScipGeometry {
  int ares = 1024;  // steps per revolution
  int amin = 44, amax = 725, afrt = 384;  // first, last and front step
  int dmin_mm = 20, dmax_mm = 4000;
  int scan_rpm = 600;
  std::string product = "URG-04LX";  // the name in MODL (PP, II) and PROD (VV): each SCIP model's own
};

struct ColaGeometry {
  int start_angle = -450000;  // [1/10000 deg] first beam, SICK frame (0 deg = +y of the device)
  int angular_step = 3333;    // [1/10000 deg]
  int beams = 811;
  int scan_frequency = 1500;  // [1/100 Hz]
  // The LMS1xx family: a client logs in, may set the scan (mLMPsetscancfg) and starts the
  // measurement (LMCstartmeas); a TiM5xx measures from power-up and has none of that.
  bool measures_on_command = false;
};

// A RPLIDAR turns clockwise seen from above and samples at its own clock, so the angles of
// one revolution are uneven and differ from the next one's. The driver publishes them on a
// fixed grid of `bins` over 360 deg (REP 117: +inf where no sample fell).
struct RplidarGeometry {
  double sample_rate = 2000.0;  // [1/s] standard SCAN mode (GET_SAMPLERATE: 500 us)
  double speed_jitter = 0.02;   // emulator: revolution speed varies by up to this fraction
  int bins = 360;               // published grid: 1 deg, bin 0 at -180 deg
};

struct LaserModel {
  std::string name;  // its entry in laser_registry.h
  const LaserProtocol* protocol = nullptr;  // set by its registry entry; never owned
  ScipGeometry scip;
  ColaGeometry cola;
  RplidarGeometry rplidar;
  double range_min = 0.02, range_max = 4.0;  // [m]
  double rate = 10.0;                        // [Hz] scans per second

  // From the protocol's numbers (LaserProtocol); throws std::logic_error without a protocol.
  int beams() const;
  double angleMin() const;
  double angleIncrement() const;
  double angleMax() const { return angleMin() + angleIncrement() * (beams() - 1); }
  double scanTime() const { return 1.0 / rate; }
  // Time between beams: one revolution (a full turn of the mirror) takes scanTime().
  double timeIncrement() const;
  core::ScanGeometry geometry() const;
};

// The model's protocol; throws std::logic_error for a model built without its registry entry.
const LaserProtocol& protocolOf(const LaserModel& model);
// The model of a laser_registry.h entry (laser_registry.cpp); throws std::invalid_argument
// naming `name` and the known models when there is no such entry.
LaserModel laserModel(const std::string& name);
// The LMS1xx's scan configurations (mLMPsetscancfg): 25 Hz at 0.25 or 0.5 deg, 50 Hz at
// 0.5 deg. Throws std::invalid_argument naming the bad value for another combination.
void setLms1xxScanConfig(LaserModel* model, double frequency_hz, double resolution_deg);

}  // namespace sensors
}  // namespace amigobot_tracking

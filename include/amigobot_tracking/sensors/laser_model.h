// The lasers the emulator imitates and the driver knows: their geometry in the sensor frame
// (REP 103: x forward, angles counter-clockwise), rate and range, and the protocol numbers
// behind that geometry. The SCIP numbers are what a URG-04LX answers to PP; the CoLa-A
// numbers what a TiM5xx puts in its scan telegram.
#pragma once

#include <string>

#include "amigobot_tracking/core/scan_obstacles.h"

namespace amigobot_tracking {
namespace sensors {

enum class Protocol { kScip, kColaA };

struct ScipGeometry {
  int ares = 1024;  // steps per revolution
  int amin = 44, amax = 725, afrt = 384;  // first, last and front step
  int dmin_mm = 20, dmax_mm = 4000;
  int scan_rpm = 600;
};

struct ColaGeometry {
  int start_angle = -450000;  // [1/10000 deg] first beam, SICK frame (0 deg = +y of the device)
  int angular_step = 3333;    // [1/10000 deg]
  int beams = 811;
  int scan_frequency = 1500;  // [1/100 Hz]
};

struct LaserModel {
  std::string name;  // hokuyo_urg | sick_tim5xx
  Protocol protocol = Protocol::kScip;
  ScipGeometry scip;
  ColaGeometry cola;
  double range_min = 0.02, range_max = 4.0;  // [m]
  double rate = 10.0;                        // [Hz] scans per second

  int beams() const;
  // The device's own angles: SCIP (step - AFRT) 2 pi / ARES; CoLa-A start + i step, turned
  // by -90 deg from SICK's frame to REP 103.
  double angleMin() const;
  double angleIncrement() const;
  double angleMax() const { return angleMin() + angleIncrement() * (beams() - 1); }
  double scanTime() const { return 1.0 / rate; }
  // Time between beams: one revolution (a full turn of the mirror) takes scanTime().
  double timeIncrement() const;
  core::ScanGeometry geometry() const;
};

// hokuyo_urg (URG-04LX: 240 deg, 0.352 deg, 10 Hz, 4 m) or sick_tim5xx (TiM5xx: 270 deg,
// 0.333 deg, 15 Hz, 10 m). Throws std::invalid_argument naming the model otherwise.
LaserModel laserModel(const std::string& name);

}  // namespace sensors
}  // namespace amigobot_tracking

#include "amigobot_tracking/sensors/laser_model.h"

#include <cmath>
#include <stdexcept>

namespace amigobot_tracking {
namespace sensors {
namespace {

constexpr double kTenThousandthDegree = M_PI / 180.0 / 10000.0;

}  // namespace

int LaserModel::beams() const {
  switch (protocol) {
    case Protocol::kScip: return scip.amax - scip.amin + 1;
    case Protocol::kColaA: return cola.beams;
    default: return rplidar.bins;
  }
}

double LaserModel::angleMin() const {
  switch (protocol) {
    case Protocol::kScip: return (scip.amin - scip.afrt) * 2.0 * M_PI / scip.ares;
    case Protocol::kColaA: return cola.start_angle * kTenThousandthDegree - M_PI / 2.0;
    default: return -M_PI;
  }
}

double LaserModel::angleIncrement() const {
  switch (protocol) {
    case Protocol::kScip: return 2.0 * M_PI / scip.ares;
    case Protocol::kColaA: return cola.angular_step * kTenThousandthDegree;
    default: return 2.0 * M_PI / rplidar.bins;
  }
}

double LaserModel::timeIncrement() const {
  return scanTime() * angleIncrement() / (2.0 * M_PI);
}

core::ScanGeometry LaserModel::geometry() const {
  core::ScanGeometry g;
  g.angle_min = angleMin();
  g.angle_increment = angleIncrement();
  g.range_min = range_min;
  g.range_max = range_max;
  return g;
}

LaserModel laserModel(const std::string& name) {
  LaserModel m;
  m.name = name;
  if (name == "hokuyo_urg") {
    m.protocol = Protocol::kScip;
    m.range_min = m.scip.dmin_mm / 1000.0;
    m.range_max = m.scip.dmax_mm / 1000.0;
    m.rate = m.scip.scan_rpm / 60.0;
  } else if (name == "sick_tim5xx") {
    m.protocol = Protocol::kColaA;
    m.range_min = 0.05;
    m.range_max = 10.0;
    m.rate = m.cola.scan_frequency / 100.0;
  } else if (name == "sick_lms1xx") {
    m.protocol = Protocol::kColaA;
    // The LMS111 data sheet's operating range starts at 0.5 m, but the device reports echoes
    // from 0.01 m on (real captures carry 0.126 m) and clearpath's LMS1xx driver publishes
    // range_min 0.01: dropping them would lose what the device measured.
    m.range_min = 0.01;
    m.range_max = 20.0;
    setLms1xxScanConfig(&m, 25.0, 0.5);
  } else if (name == "rplidar") {
    m.protocol = Protocol::kRplidar;
    m.range_min = 0.15;  // A1M8 data sheet: 0.15 .. 12 m
    m.range_max = 12.0;
    m.rate = 5.5;
  } else {
    throw std::invalid_argument("model: '" + name +
                                "' is not an emulated laser (hokuyo_urg | sick_tim5xx | sick_lms1xx | rplidar)");
  }
  return m;
}

void setLms1xxScanConfig(LaserModel* model, double frequency_hz, double resolution_deg) {
  if (frequency_hz != 25.0 && frequency_hz != 50.0) {
    throw std::invalid_argument("scan frequency: " + std::to_string(frequency_hz) + " Hz (LMS1xx: 25 or 50)");
  }
  if (resolution_deg != 0.25 && resolution_deg != 0.5) {
    throw std::invalid_argument("angular resolution: " + std::to_string(resolution_deg) + " deg (LMS1xx: 0.25 or 0.5)");
  }
  if (frequency_hz == 50.0 && resolution_deg == 0.25) {
    throw std::invalid_argument("angular resolution: 0.25 deg needs 25 Hz on an LMS1xx");
  }
  ColaGeometry& c = model->cola;
  c.scan_frequency = static_cast<int>(frequency_hz * 100.0);
  c.angular_step = static_cast<int>(resolution_deg * 10000.0);
  c.start_angle = -450000;  // -45 deg .. 225 deg in SICK's frame
  c.beams = 2700000 / c.angular_step + 1;
  model->rate = frequency_hz;
}

}  // namespace sensors
}  // namespace amigobot_tracking

#include "amigobot_tracking/sensors/laser_model.h"

#include <cmath>
#include <stdexcept>

namespace amigobot_tracking {
namespace sensors {
namespace {

constexpr double kTenThousandthDegree = M_PI / 180.0 / 10000.0;

}  // namespace

int LaserModel::beams() const {
  return protocol == Protocol::kScip ? scip.amax - scip.amin + 1 : cola.beams;
}

double LaserModel::angleMin() const {
  if (protocol == Protocol::kScip) return (scip.amin - scip.afrt) * 2.0 * M_PI / scip.ares;
  return cola.start_angle * kTenThousandthDegree - M_PI / 2.0;
}

double LaserModel::angleIncrement() const {
  return protocol == Protocol::kScip ? 2.0 * M_PI / scip.ares : cola.angular_step * kTenThousandthDegree;
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
  } else {
    throw std::invalid_argument("model: '" + name + "' is not an emulated laser (hokuyo_urg | sick_tim5xx)");
  }
  return m;
}

}  // namespace sensors
}  // namespace amigobot_tracking

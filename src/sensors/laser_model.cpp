#include "amigobot_tracking/sensors/laser_model.h"

#include <cmath>
#include <stdexcept>

#include "amigobot_tracking/sensors/laser_protocol.h"

namespace amigobot_tracking {
namespace sensors {

const LaserProtocol& protocolOf(const LaserModel& model) {
  if (!model.protocol) throw std::logic_error("laser model '" + model.name + "': no protocol (not from laser_registry.h)");
  return *model.protocol;
}

int LaserModel::beams() const { return protocolOf(*this).beams(*this); }
double LaserModel::angleMin() const { return protocolOf(*this).angleMin(*this); }
double LaserModel::angleIncrement() const { return protocolOf(*this).angleIncrement(*this); }

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

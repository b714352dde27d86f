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

const ProtocolGeometry& protocolGeometryOf(const LaserModel& model) {
  protocolOf(model);  // a bare model says it has no protocol first: the cause of both
  if (!model.protocol_geometry) {
    throw std::logic_error("laser model '" + model.name + "': no protocol geometry (not from laser_registry.h)");
  }
  return *model.protocol_geometry;
}

int LaserModel::beams() const { return protocolGeometryOf(*this).beams(); }
double LaserModel::angleMin() const { return protocolGeometryOf(*this).angleMin(); }
double LaserModel::angleIncrement() const { return protocolGeometryOf(*this).angleIncrement(); }

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

}  // namespace sensors
}  // namespace amigobot_tracking

#include "amigobot_tracking/sensors/laser_session.h"

#include <cmath>

#include "amigobot_tracking/sensors/laser_protocol.h"
#include "amigobot_tracking/sensors/laser_registry.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

std::uint32_t millimetres(float range) { return static_cast<std::uint32_t>(std::lround(range * 1000.0)); }

}  // namespace

std::vector<std::uint32_t> deviceRanges(const LaserModel& model, const std::vector<float>& ranges) {
  std::vector<std::uint32_t> out;
  out.reserve(ranges.size());
  for (float r : ranges) out.push_back(std::isfinite(r) ? millimetres(r) : protocolOf(model).noMeasurementCode(r));
  return out;
}

std::unique_ptr<LaserSession> makeSession(const LaserModel& model, const std::string& serial) {
  laserModelEntry(model.name);  // throws naming a model that is not in the registry
  return protocolOf(model).session(model, serial);
}

}  // namespace sensors
}  // namespace amigobot_tracking

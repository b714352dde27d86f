#include "amigobot_tracking/core/reference/reference_spec.h"

#include <stdexcept>

#include "amigobot_tracking/core/reference/waypoint_reference.h"

namespace amigobot_tracking {
namespace core {

const std::vector<std::string>& referenceTypes() {
  static const std::vector<std::string> types = {"rose", "circle", "spline", "waypoints"};
  return types;
}

const FieldTable<ReferenceSpec>& referenceFields() {
  using R = ReferenceSpec;
  static const FieldTable<R> table = {
      field("type", &R::type, "-", "the curve", oneOf(referenceTypes())),
      field("amplitude", &R::amplitude, "m", "rose: amplitude", positive()),
      field("k", &R::k, "-", "rose: petal factor", positive()),
      field("period_scale", &R::period_scale, "s/rad", "rose: its own time scale", positive()),
      field("radius", &R::radius, "m", "circle: radius", boundedRadius()),
      field("period", &R::period, "s", "circle: period", positive()),
      field("duration", &R::duration, "s", "spline: duration", positive()),
      field("speed", &R::speed, "m/s", "waypoints: speed", positive()),
      field("loop", &R::loop, "-", "waypoints: start again after the last"),
  };
  return table;
}

std::unique_ptr<Reference> makeReference(const ReferenceSpec& spec) {
  const std::string problem = checkFields(referenceFields(), spec);
  if (!problem.empty()) throw std::invalid_argument(problem);
  if (spec.type == "rose") return std::make_unique<RoseReference>(spec.amplitude, spec.k, spec.period_scale);
  if (spec.type == "circle") return std::make_unique<CircleReference>(spec.center, spec.radius, spec.period);
  if (spec.type == "spline") return std::make_unique<SplineReference>(spec.waypoints, spec.duration);
  return std::make_unique<WaypointReference>(spec.waypoints, spec.speed, spec.loop);
}

}  // namespace core
}  // namespace amigobot_tracking

#include "amigobot_tracking/core/reference/reference_spec.h"

#include <algorithm>
#include <stdexcept>

#include "amigobot_tracking/core/reference/waypoint_reference.h"

namespace amigobot_tracking {
namespace core {

bool ReferenceCurve::takes(const std::string& key) const {
  return std::find(required.begin(), required.end(), key) != required.end() ||
         std::find(optional.begin(), optional.end(), key) != optional.end();
}

const std::vector<ReferenceCurve>& referenceCurves() {
  using R = ReferenceSpec;
  static const std::vector<ReferenceCurve> curves = {
      {"rose", {"amplitude", "k"}, {"period_scale"}, false, false,
       [](const R& s) { return std::make_unique<RoseReference>(s.amplitude, s.k, s.period_scale); }},
      {"circle", {"radius", "period"}, {}, true, false,
       [](const R& s) { return std::make_unique<CircleReference>(s.center, s.radius, s.period); }},
      {"spline", {"duration"}, {}, false, true,
       [](const R& s) { return std::make_unique<SplineReference>(s.waypoints, s.duration); }},
      {"waypoints", {}, {"speed", "loop"}, false, true,
       [](const R& s) { return std::make_unique<WaypointReference>(s.waypoints, s.speed, s.loop); }},
  };
  return curves;
}

const ReferenceCurve& referenceCurve(const std::string& type) {
  for (const ReferenceCurve& c : referenceCurves())
    if (c.type == type) return c;
  std::string known;
  for (const std::string& t : referenceTypes()) known += (known.empty() ? "" : ", ") + t;
  throw std::invalid_argument("unknown reference type '" + type + "' (" + known + ")");
}

const std::vector<std::string>& referenceTypes() {
  static const std::vector<std::string> types = [] {
    std::vector<std::string> names;
    for (const ReferenceCurve& c : referenceCurves()) names.push_back(c.type);
    return names;
  }();
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
  return referenceCurve(spec.type).make(spec);
}

}  // namespace core
}  // namespace amigobot_tracking

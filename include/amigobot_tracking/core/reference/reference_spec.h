// One description of a reference trajectory (which curve, its numbers), and the one factory
// that builds it: the simulator's scenario files and reference_publisher's parameters both
// fill a ReferenceSpec, so a curve and its keys have one name everywhere (`period_scale` is
// the rose's own time scale in both; the publisher's top-level `time_scale` is its slow-down).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/reference/reference.h"
#include "amigobot_tracking/core/support/field_table.h"

namespace amigobot_tracking {
namespace core {

struct ReferenceSpec {
  std::string type = "circle";                               // rose | circle | spline | waypoints
  double amplitude = 1.0, k = 3.0, period_scale = 1.0;       // rose [m], [-], [s/rad]
  Eigen::Vector2d center = Eigen::Vector2d::Zero();          // circle [m]
  double radius = 1.0, period = 30.0;                        // circle [m], [s]
  std::vector<Eigen::Vector2d> waypoints;                    // spline, waypoints [m]
  double duration = 60.0;                                    // spline [s]
  double speed = 0.2;                                        // waypoints [m/s]
  bool loop = false;                                         // waypoints
};

// One curve: its name (`type`), the keys it takes and how it is built. referenceCurves() is
// the one list of them: the factory, the simulator's scenario reader and reference_publisher
// ask it which keys a curve takes instead of comparing names.
struct ReferenceCurve {
  std::string type;
  std::vector<std::string> required, optional;  // its scalar keys (rows of referenceFields())
  bool center = false;                          // takes `center` [x, y] (required)
  bool waypoints = false;                       // takes `waypoints`, >= 2 points [x, y] (required)
  std::function<std::unique_ptr<Reference>(const ReferenceSpec&)> make;

  bool takes(const std::string& key) const;  // one of its scalar keys
};
const std::vector<ReferenceCurve>& referenceCurves();
// The curve named `type`; std::invalid_argument "unknown reference type 'X' (rose, circle, ...)".
const ReferenceCurve& referenceCurve(const std::string& type);
// The curves' names, as `type` takes them.
const std::vector<std::string>& referenceTypes();
// The scalar keys (type and the numbers; center and waypoints are lists, read by each reader).
const FieldTable<ReferenceSpec>& referenceFields();
// The curve `spec` describes; std::invalid_argument naming the key when it cannot be built
// (a key out of its bounds, fewer than 2 waypoints, ...).
std::unique_ptr<Reference> makeReference(const ReferenceSpec& spec);

}  // namespace core
}  // namespace amigobot_tracking

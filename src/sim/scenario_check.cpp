// checkScenario: the rules across a scenario's sections (the controller's cross-field rules,
// the setup, the reference, a feasible start), after the parser has checked each field.
#include <memory>
#include <sstream>
#include <stdexcept>

#include "amigobot_tracking/core/law/law_registry.h"
#include "amigobot_tracking/core/robot/offset_point.h"
#include "amigobot_tracking/sim/scenario.h"
#include "amigobot_tracking/sim/scenario_fields.h"

namespace amigobot_tracking {
namespace sim {
void checkScenario(const Scenario& scenario) {
  const sim::ClosedLoopSetup& setup = scenario.setup;
  // The controller's rules across fields name a table key ("key: reason"); the parser has
  // checked every other field, so validateSetup's own messages are a last guard.
  const std::string controller = setup.controller.validate();
  if (!controller.empty()) {
    const std::string key = controller.substr(0, controller.find(':'));
    throw ScenarioError(scenario.file + ": " + scenarioPath(key) + controller.substr(key.size()));
  }
  const std::string err = sim::validateSetup(setup);
  if (!err.empty()) throw ScenarioError(scenario.file + ": " + err);
  std::unique_ptr<core::Reference> reference;
  try {
    reference = scenario.makeReference();
  } catch (const std::invalid_argument& e) {
    throw ScenarioError(scenario.file + ": reference: " + e.what());
  }
  const Eigen::Vector2d p_d = reference->at(0.0).position;
  const Eigen::Vector2d p_r = core::offsetPoint(setup.initial_pose, setup.controller.offset);
  // A start inside a disk's zone (R + r with body_safe) is infeasible, not a result: (10) is
  // evaluated at its contact floor and rho blows up (ring.yaml's 5.9 cm: rho 1 -> 74 m).
  const double zone = setup.controller.effectiveRadius();
  for (size_t i = 0; i < setup.obstacles.size(); ++i) {
    const core::Disk& o = setup.obstacles[i];
    const double inside = zone + o.radius - (p_r - o.center).norm();
    if (inside < 0.0) continue;
    std::ostringstream msg;
    msg << scenario.file << ": robot.initial_pose: the offset point p_r(0) = (" << p_r.x() << ", " << p_r.y()
        << ") starts " << inside << " m inside the zone (R + r + radius = " << zone + o.radius
        << " m) of obstacles[" << i << "] at (" << o.center.x() << ", " << o.center.y()
        << "): an infeasible start (move robot.initial_pose)";
    throw ScenarioError(msg.str());
  }
  const double e0 = (p_d - p_r).norm();
  const core::LawEntry* law = core::findLaw(setup.law);
  const bool has_rho = law && law->has_rho_bound;
  if (has_rho && !(e0 < setup.controller.rho_0)) {
    std::ostringstream msg;
    msg << scenario.file << ": controller.rho_0: " << setup.controller.rho_0
        << " m is too small: the initial error |e(0)| = |p_d(0) - p_r(0)| is " << e0
        << " m, and the paper requires |e(0)| < rho(0) (move robot.initial_pose or raise rho_0)";
    throw ScenarioError(msg.str());
  }
}

}  // namespace sim
}  // namespace amigobot_tracking

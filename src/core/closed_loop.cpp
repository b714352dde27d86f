#include "amigobot_tracking/core/closed_loop.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "amigobot_tracking/core/avoidance.h"
#include "amigobot_tracking/core/unicycle.h"

namespace amigobot_tracking {
namespace core {

ClosedLoopSummary runClosedLoop(const ClosedLoopSetup& setup, const Reference& reference,
                                const ClosedLoopObserver& observer) {
  PerformanceController controller(setup.controller);
  ClosedLoopSummary summary;
  summary.min_clearance_offset = summary.min_clearance_body = std::numeric_limits<double>::infinity();
  Pose2 pose = setup.initial_pose;
  TargetSample sample;
  double next_sample_t = 0.0;
  const auto steps = static_cast<std::uint64_t>(std::llround(setup.duration / setup.control_period));
  const double body_radius = setup.controller.robot_radius;
  for (std::uint64_t k = 0; k <= steps; ++k) {
    const double t = static_cast<double>(k) * setup.control_period;
    const ReferenceState ref = reference.at(t);
    if (t + 1e-12 >= next_sample_t) {
      sample = {t, ref.position};
      next_sample_t += setup.sample_period > 0.0 ? setup.sample_period : setup.control_period;
    }
    const ControllerOutput out = controller.step(t, pose, sample, setup.obstacles);
    ++summary.steps;
    if (!out.valid) ++summary.invalid_steps;
    summary.max_error_ratio = std::max(summary.max_error_ratio, out.e.norm() / out.rho);
    summary.final_error = out.e.norm();
    summary.min_clearance_offset = std::min(summary.min_clearance_offset, out.min_clearance);
    summary.min_clearance_body =
        std::min(summary.min_clearance_body, clearance(pose.position(), body_radius, setup.obstacles));
    if (!controller.diamond().contains(out.u, 1e-9)) ++summary.diamond_violations;
    if (out.active.envelope_widened) ++summary.envelope_widenings;
    if (out.active.saturated) ++summary.saturated_steps;
    if (observer) observer({t, pose, ref, out});
    if (k < steps) pose = integrateUnicycle(pose, out.u, setup.control_period);
  }
  return summary;
}

}  // namespace core
}  // namespace amigobot_tracking

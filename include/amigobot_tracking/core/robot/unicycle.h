// Exact integration of the unicycle (1) under a constant input over one step.
#pragma once

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

// Moves the pose along the arc of constant (v, w) for h seconds (a straight line when
// w is ~0). Heading is wrapped to (-pi, pi].
Pose2 integrateUnicycle(const Pose2& pose, const Twist2& u, double h);
// The same with heading = (cos, sin) of pose.theta already at hand.
Pose2 integrateUnicycle(const Pose2& pose, const Eigen::Vector2d& heading, const Twist2& u, double h);

}  // namespace core
}  // namespace amigobot_tracking

// Planar pose algebra of the localisation (a (+) b, inverse) through MRPT's CPose2D.
#pragma once

#include <cmath>

#include <mrpt/poses/CPose2D.h>

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace localization {

inline mrpt::poses::CPose2D toMrpt(const core::Pose2& p) { return mrpt::poses::CPose2D(p.x, p.y, p.theta); }
inline core::Pose2 fromMrpt(const mrpt::poses::CPose2D& p) { return core::Pose2{p.x(), p.y(), p.phi()}; }
// a (+) b: b expressed in a's frame, taken to a's parent frame.
inline core::Pose2 compose(const core::Pose2& a, const core::Pose2& b) { return fromMrpt(toMrpt(a) + toMrpt(b)); }
inline core::Pose2 inverse(const core::Pose2& a) {
  mrpt::poses::CPose2D p = toMrpt(a);
  p.inverse();
  return fromMrpt(p);
}
// How far apart two poses are [m], and how much their headings differ [rad, in [0, pi]]:
// the keyframe and update gates of the mapper and the localiser.
inline double travel(const core::Pose2& a, const core::Pose2& b) { return std::hypot(a.x - b.x, a.y - b.y); }
inline double turn(const core::Pose2& a, const core::Pose2& b) { return std::abs(core::wrapAngle(a.theta - b.theta)); }

}  // namespace localization
}  // namespace amigobot_tracking

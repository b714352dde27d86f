// Planar pose algebra of the localisation (a (+) b, inverse) through MRPT's CPose2D.
#pragma once

#include <mrpt/poses/CPose2D.h>

#include "amigobot_tracking/core/types.h"

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

}  // namespace localization
}  // namespace amigobot_tracking

// When two disks are one obstacle for the offset point.
#pragma once

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

// True when the zones of a and b -- each disk grown by `reach` -- overlap:
// |c_a - c_b| <= r_a + r_b + 2 reach. With reach = R_eff + delta these are the detection zones
// of the offset point: where they overlap it can feel both disks at once, and a per-disk escape
// (one tangent per disk) can be trapped between them (avoidance.h: tangentialTerm).
bool zonesOverlap(const Disk& a, const Disk& b, double reach);

}  // namespace core
}  // namespace amigobot_tracking

#include "amigobot_tracking/core/law/disk_clusters.h"

namespace amigobot_tracking {
namespace core {

bool zonesOverlap(const Disk& a, const Disk& b, double reach) {
  const double limit = a.radius + b.radius + 2.0 * reach;
  return (a.center - b.center).squaredNorm() <= limit * limit;
}

}  // namespace core
}  // namespace amigobot_tracking

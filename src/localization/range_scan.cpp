#include "amigobot_tracking/localization/range_scan.h"

#include <algorithm>
#include <cmath>

#include <mrpt/poses/CPose3D.h>

namespace amigobot_tracking {
namespace localization {

bool RangeScan::valid(int beam, double range_cap) const {
  const double r = ranges[static_cast<std::size_t>(beam)];
  return std::isfinite(r) && r >= range_min && r <= std::min(range_max, range_cap);
}

std::vector<Eigen::Vector2d> scanPoints(const RangeScan& scan, double range_cap, int max_points) {
  const int n = static_cast<int>(scan.ranges.size());
  int count = 0;
  for (int i = 0; i < n; ++i) count += scan.valid(i, range_cap);
  const double stride = std::max(1.0, static_cast<double>(count) / std::max(1, max_points));
  std::vector<Eigen::Vector2d> points;
  points.reserve(static_cast<std::size_t>(std::min(count, max_points)));
  const double c = std::cos(scan.mount.theta), s = std::sin(scan.mount.theta);
  double next = 0.0;
  int k = 0;
  for (int i = 0; i < n; ++i) {
    if (!scan.valid(i, range_cap)) continue;
    if (k++ < next) continue;
    next += stride;
    const double a = scan.angle_min + scan.angle_increment * i, r = scan.ranges[static_cast<std::size_t>(i)];
    const double lx = r * std::cos(a), ly = r * std::sin(a);
    points.emplace_back(scan.mount.x + c * lx - s * ly, scan.mount.y + s * lx + c * ly);
  }
  return points;
}

void toPointsMap(const std::vector<Eigen::Vector2d>& points, mrpt::maps::CSimplePointsMap* out) {
  out->clear();
  out->reserve(points.size());
  for (const Eigen::Vector2d& p : points) out->insertPointFast(static_cast<float>(p.x()), static_cast<float>(p.y()), 0.0f);
  out->mark_as_modified();
}

mrpt::obs::CObservation2DRangeScan::Ptr toObservation(const RangeScan& scan, double range_cap) {
  auto obs = mrpt::obs::CObservation2DRangeScan::Create();
  const std::size_t n = scan.ranges.size();
  obs->resizeScan(n);
  obs->aperture = static_cast<float>(scan.angle_increment * (n > 1 ? n - 1 : 1));
  obs->rightToLeft = true;
  obs->maxRange = static_cast<float>(std::min(scan.range_max, range_cap));
  const double middle = scan.angle_min + 0.5 * scan.angle_increment * (n > 1 ? n - 1 : 0);
  obs->sensorPose = mrpt::poses::CPose3D(scan.mount.x, scan.mount.y, 0.0, scan.mount.theta + middle, 0.0, 0.0);
  obs->sensorLabel = "laser";
  for (std::size_t i = 0; i < n; ++i) {
    const bool ok = scan.valid(static_cast<int>(i), range_cap);
    obs->setScanRange(i, ok ? scan.ranges[i] : obs->maxRange);
    obs->setScanRangeValidity(i, ok);
  }
  return obs;
}

}  // namespace localization
}  // namespace amigobot_tracking

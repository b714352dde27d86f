#include "amigobot_tracking/world/raycast.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "amigobot_tracking/world/geometry.h"

namespace amigobot_tracking {
namespace world {

using core::Disk;
using core::Pose2;
using core::ScanGeometry;

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// A segment seen from the sensor: its start relative to the sensor and its edge vector,
// with the one cross product that does not depend on the beam.
struct RelativeSegment {
  Eigen::Vector2d start, edge;
  double start_cross_edge;
};

bool insideSomething(const Eigen::Vector2d& point, const World& world) {
  for (const Disk& d : world.obstacles) {
    if ((point - d.center).squaredNorm() <= d.radius * d.radius) return true;
  }
  for (const Polygon& p : world.polygons) {
    if (insidePolygon(point, p)) return true;
  }
  return false;
}

}  // namespace

double rayDiskDistance(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, const Disk& disk) {
  // |origin + s d - c|^2 = r^2 with |d| = 1: s^2 + 2 b s + q = 0.
  const Eigen::Vector2d offset = origin - disk.center;
  const double q = offset.squaredNorm() - disk.radius * disk.radius;
  if (q <= 0.0) return 0.0;
  const double b = offset.dot(direction);
  if (b >= 0.0) return -1.0;  // pointing away
  const double discriminant = b * b - q;
  if (discriminant < 0.0) return -1.0;
  return -b - std::sqrt(discriminant);
}

double raySegmentDistance(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, const Segment& segment) {
  // origin + s d = from + u e: s = (a x e) / (d x e), u = (a x d) / (d x e) with a = from - origin.
  const Eigen::Vector2d a = segment.from - origin, e = segment.to - segment.from;
  const double denominator = cross(direction, e);
  if (std::abs(denominator) < 1e-15) return -1.0;
  const double s = cross(a, e) / denominator, u = cross(a, direction) / denominator;
  return s >= 0.0 && u >= 0.0 && u <= 1.0 ? s : -1.0;
}

std::vector<float> raycastScan(const Pose2& sensor, const World& world, const ScanGeometry& geometry, int beams) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  std::vector<float> ranges(static_cast<size_t>(std::max(0, beams)));
  const Eigen::Vector2d origin = sensor.position();
  if (insideSomething(origin, world)) {
    std::fill(ranges.begin(), ranges.end(), geometry.range_min > 0.0 ? -kInf : 0.0f);
    return ranges;
  }
  // Per scan: the segments relative to the sensor, so each beam costs two cross products
  // and a division per segment; segments wholly beyond range_max are left out.
  std::vector<RelativeSegment> segments;
  for (const Segment& s : surfaceSegments(world)) {
    if (pointSegmentDistance(origin, s) > geometry.range_max) continue;
    const Eigen::Vector2d start = s.from - origin, edge = s.to - s.from;
    segments.push_back({start, edge, cross(start, edge)});
  }
  for (size_t i = 0; i < ranges.size(); ++i) {
    const double angle = sensor.theta + geometry.angle_min + geometry.angle_increment * static_cast<double>(i);
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    double nearest = std::numeric_limits<double>::infinity();
    for (const Disk& disk : world.obstacles) {
      const double s = rayDiskDistance(origin, direction, disk);
      if (s >= 0.0 && s < nearest) nearest = s;
    }
    for (const RelativeSegment& seg : segments) {
      const double denominator = cross(direction, seg.edge);
      if (std::abs(denominator) < 1e-15) continue;
      const double s = seg.start_cross_edge / denominator;
      if (s < 0.0 || s >= nearest) continue;
      const double u = cross(seg.start, direction) / denominator;
      if (u >= 0.0 && u <= 1.0) nearest = s;
    }
    if (nearest > geometry.range_max) {
      ranges[i] = kInf;
    } else if (nearest < geometry.range_min) {
      ranges[i] = -kInf;
    } else {
      ranges[i] = static_cast<float>(nearest);
    }
  }
  return ranges;
}

}  // namespace world
}  // namespace amigobot_tracking

#include "amigobot_tracking/world/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "amigobot_tracking/core/law/avoidance.h"

namespace amigobot_tracking {
namespace world {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The part of `segment` where normal . (p - origin) >= 0, as the parameter interval
// [*t0, *t1] of from + t (to - from); false when none of it is.
bool clipToHalfPlane(const Segment& segment, const Eigen::Vector2d& origin, const Eigen::Vector2d& normal, double* t0,
                     double* t1) {
  const double f0 = normal.dot(segment.from - origin);
  const double df = normal.dot(segment.to - segment.from);
  if (std::abs(df) < 1e-15) return f0 >= 0.0;
  const double root = -f0 / df;  // f(t) = f0 + t df crosses zero here
  if (df > 0.0) {
    *t0 = std::max(*t0, root);
  } else {
    *t1 = std::min(*t1, root);
  }
  return *t0 <= *t1;
}

}  // namespace

std::vector<Segment> surfaceSegments(const World& world) {
  std::vector<Segment> segments = world.walls;
  for (const Polygon& polygon : world.polygons) {
    for (std::size_t i = 0; i < polygon.points.size(); ++i) {
      segments.push_back({polygon.points[i], polygon.points[(i + 1) % polygon.points.size()]});
    }
  }
  return segments;
}

double pointSegmentDistance(const Eigen::Vector2d& point, const Segment& segment) {
  const Eigen::Vector2d edge = segment.to - segment.from;
  const double length2 = edge.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((point - segment.from).dot(edge) / length2, 0.0, 1.0) : 0.0;
  return (segment.from + t * edge - point).norm();
}

bool insidePolygon(const Eigen::Vector2d& point, const Polygon& polygon) {
  bool inside = false;
  const std::size_t n = polygon.points.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d& a = polygon.points[i];
    const Eigen::Vector2d& b = polygon.points[j];
    if ((a.y() > point.y()) != (b.y() > point.y()) &&
        point.x() < (b.x() - a.x()) * (point.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

double clearance(const World& world, const Eigen::Vector2d& center, double radius) {
  double best = core::clearance(center, radius, world.obstacles);
  for (const Segment& wall : world.walls) best = std::min(best, pointSegmentDistance(center, wall) - radius);
  for (const Polygon& polygon : world.polygons) {
    double edge = kInf;
    for (std::size_t i = 0; i < polygon.points.size(); ++i) {
      edge = std::min(edge, pointSegmentDistance(center, {polygon.points[i], polygon.points[(i + 1) % polygon.points.size()]}));
    }
    best = std::min(best, (insidePolygon(center, polygon) ? -edge : edge) - radius);
  }
  return best;
}

double coneRange(const World& world, const core::Pose2& sensor, double half_cone) {
  const Eigen::Vector2d origin = sensor.position();
  double best = kInf;
  for (const core::Disk& d : world.obstacles) {
    const Eigen::Vector2d to_center = d.center - origin;
    const double distance = to_center.norm();
    if (distance <= d.radius) return 0.0;
    // Seen when any part of the disk is inside the cone; range to its surface.
    const double bearing = std::abs(core::wrapAngle(std::atan2(to_center.y(), to_center.x()) - sensor.theta));
    if (bearing <= half_cone + std::asin(d.radius / distance)) best = std::min(best, distance - d.radius);
  }
  for (const Polygon& polygon : world.polygons) {
    if (insidePolygon(origin, polygon)) return 0.0;
  }
  // The cone (half_cone < pi/2) is the intersection of two half-planes through the sensor;
  // the part of a segment inside both is a sub-segment, whose nearest point is the range.
  const double left = sensor.theta + half_cone, right = sensor.theta - half_cone;
  const Eigen::Vector2d inside_left(std::sin(left), -std::cos(left));     // right-hand normal of the left edge
  const Eigen::Vector2d inside_right(-std::sin(right), std::cos(right));  // left-hand normal of the right edge
  for (const Segment& s : surfaceSegments(world)) {
    double t0 = 0.0, t1 = 1.0;
    if (!clipToHalfPlane(s, origin, inside_left, &t0, &t1) || !clipToHalfPlane(s, origin, inside_right, &t0, &t1)) {
      continue;
    }
    const Eigen::Vector2d edge = s.to - s.from;
    best = std::min(best, pointSegmentDistance(origin, {s.from + t0 * edge, s.from + t1 * edge}));
  }
  return best;
}

}  // namespace world
}  // namespace amigobot_tracking

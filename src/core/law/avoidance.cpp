#include "amigobot_tracking/core/law/avoidance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "amigobot_tracking/core/law/disk_clusters.h"

namespace amigobot_tracking {
namespace core {
namespace {

// One obstacle as seen from p_r: the outward vector (floored away from zero), its distance
// and the margin to contact.
struct Relative {
  Eigen::Vector2d away;  // p_r - centre
  double distance;
  double margin;         // distance - contact, floored at min_margin
  double clearance;      // distance - contact, unfloored
};

Relative relativeTo(const Eigen::Vector2d& p_r, const Disk& obstacle, double robot_radius,
                    const Eigen::Vector2d& heading_hint, double min_margin) {
  Relative rel{p_r - obstacle.center, 0.0, 0.0, 0.0};
  rel.distance = rel.away.norm();
  const double contact = robot_radius + obstacle.radius;
  rel.clearance = rel.distance - contact;
  if (rel.distance < 1e-9) {  // on the centre: any direction is as good; back off
    rel.away = -heading_hint.normalized() * 1e-9;
    rel.distance = 1e-9;
  }
  rel.margin = std::max(rel.clearance, min_margin);
  return rel;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The passing side for the sine of the angle from -n to e_hat (> 0: the target lies
// counter-clockwise): kept while the sine does not exceed `hysteresis` on the other side.
int latchedSide(double sine, int previous_side, double hysteresis) {
  if (previous_side != 0 && !(sine * previous_side < -hysteresis)) return previous_side;
  return sine < 0.0 ? -1 : 1;  // exactly symmetric: counter-clockwise
}

// (10), and with `moving` the obstacle-velocity extension (see avoidance.h).
AvoidanceResult accumulateRepulsion(const Eigen::Vector2d& p_r, const std::vector<Disk>& obstacles,
                                    double robot_radius, double delta, double horizon, bool moving,
                                    const Eigen::Vector2d& heading_hint, double min_margin) {
  AvoidanceResult result;
  result.min_clearance = std::numeric_limits<double>::infinity();
  for (const Disk& obstacle : obstacles) {
    const Relative rel = relativeTo(p_r, obstacle, robot_radius, heading_hint, min_margin);
    result.min_clearance = std::min(result.min_clearance, rel.clearance);
    const Eigen::Vector2d normal = rel.away / rel.distance;
    const double approach = moving ? std::max(0.0, obstacle.velocity.dot(normal)) : 0.0;
    const double band = delta + approach * horizon;
    if (rel.clearance > band) continue;
    ++result.detected;
    result.u_c += (1.0 / rel.margin - 1.0 / band) * rel.away;
    if (moving) result.u_c += approach * normal;
  }
  return result;
}

}  // namespace

AvoidanceResult repulsiveTerm(const Eigen::Vector2d& p_r, const std::vector<Disk>& obstacles,
                              double robot_radius, double delta, const Eigen::Vector2d& heading_hint,
                              double min_margin) {
  return accumulateRepulsion(p_r, obstacles, robot_radius, delta, 0.0, false, heading_hint, min_margin);
}

AvoidanceResult movingRepulsiveTerm(const Eigen::Vector2d& p_r, const std::vector<Disk>& obstacles,
                                    double robot_radius, double delta, double horizon,
                                    const Eigen::Vector2d& heading_hint, double min_margin) {
  return accumulateRepulsion(p_r, obstacles, robot_radius, delta, horizon, true, heading_hint, min_margin);
}

TangentialResult tangentialTerm(const Eigen::Vector2d& p_r, const std::vector<Disk>& obstacles,
                                double robot_radius, double delta, const Eigen::Vector2d& e_hat,
                                int previous_side, double hysteresis, double min_margin) {
  TangentialResult result;
  // The detected disks and their summed repulsion (10).
  std::vector<int> detected;
  Eigen::Vector2d repulsion = Eigen::Vector2d::Zero();
  for (size_t j = 0; j < obstacles.size(); ++j) {
    const Relative rel = relativeTo(p_r, obstacles[j], robot_radius, -e_hat, min_margin);
    if (rel.clearance > delta) continue;
    detected.push_back(static_cast<int>(j));
    repulsion += (1.0 / rel.margin - 1.0 / delta) * rel.away;
  }
  if (detected.empty()) return result;
  bool alone = detected.size() == 1;
  for (size_t i = 0; alone && i < obstacles.size(); ++i)
    alone = static_cast<int>(i) == detected.front() ||
            !zonesOverlap(obstacles[i], obstacles[detected.front()], robot_radius + delta);

  if (alone) {  // one disk on its own: along its tangent, w |u_c|
    const Relative rel = relativeTo(p_r, obstacles[detected.front()], robot_radius, -e_hat, min_margin);
    const Eigen::Vector2d normal = rel.away / rel.distance;
    const double opposition = std::max(0.0, -e_hat.dot(normal));
    if (opposition <= 0.0) return result;  // no conflict: released
    const double weight = opposition * (1.0 / rel.margin - 1.0 / delta) * rel.distance;
    if (!(weight > 0.0)) return result;
    result.side = latchedSide(weight * cross(normal, e_hat) / weight, previous_side, hysteresis);
    result.u_t = weight * result.side * Eigen::Vector2d(-normal.y(), normal.x());
    return result;
  }
  // A group (disks whose detection zones overlap): along the level line of the summed barrier,
  // i.e. around the union, at full strength (the controller's cap). Per disk, inside a gap the
  // tangents of the two sides point opposite ways, and at a concave mouth the weaker per-disk
  // term loses against the attraction's backward component: both stalled the robot.
  const double magnitude = repulsion.norm();
  if (!(magnitude > 0.0)) return result;
  const Eigen::Vector2d normal = repulsion / magnitude;
  if (-e_hat.dot(normal) <= 0.0) return result;  // the group does not oppose tracking
  result.side = latchedSide(cross(normal, e_hat), previous_side, hysteresis);
  result.u_t = result.side * Eigen::Vector2d(-normal.y(), normal.x());
  result.full_strength = true;
  return result;
}

double clearance(const Eigen::Vector2d& center, double radius, const std::vector<Disk>& obstacles) {
  double best = std::numeric_limits<double>::infinity();
  for (const Disk& obstacle : obstacles) {
    best = std::min(best, (center - obstacle.center).norm() - radius - obstacle.radius);
  }
  return best;
}

}  // namespace core
}  // namespace amigobot_tracking

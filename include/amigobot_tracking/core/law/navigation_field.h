// The recommended law's desired direction: a travel-time field to the target around the known
// disks, so a target behind a pillar or a U-shaped group is approached around it, and an
// unreachable target (inside a disk's zone) is approached to the best reachable standoff.
//
// The field phi solves the eikonal equation |grad phi| = f on a grid aligned to the world
// (first-order fast marching from the target's cell), with a slowness f that is 1 in free
// space, rises to 3 over `margin` outside each zone (|p - c_j| - R_eff - r_j) and to 20
// inside it: a continuous function of the geometry. Paths may cross a zone (at 20 times the
// cost), so phi is finite everywhere and the field has one minimum, the target: no local
// minima, hence no traps; a target inside a zone pulls toward the zone's boundary point
// nearest to it, where the safety filter holds the robot.
//
// The direction at p_r is -grad phi / max(1, |grad phi|), grad phi from central differences
// at the nodes, interpolated bilinearly: continuous in p_r. It is blended with the straight
// direction e_hat by beta = clamp(1 - q / margin, 0, 1), q the least clearance of the segment
// p_r -> p_d from the zones: with a clear line of sight (q >= margin) the direction is e_hat
// exactly and no field is computed.
//
// The field is seeded at `goal`, the blend judged on the segment to p_d: the recommended law
// passes a goal ahead of a target that is in or near a zone (recommended_law.h), so the robot
// heads for where the target comes out rather than waiting at the near side.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

struct NavigationFieldConfig {
  double robot_radius = 0.48;  // R_eff [m]
  double margin = 0.1;         // [m] width of the slowness ramp and of the line-of-sight blend
  double cell = 0.05;          // [m] grid spacing
  double padding = 2.5;        // [m] the grid spans p_r and p_d plus this on every side
  double max_extent = 24.0;    // [m] at most this wide and tall (centred on p_r)
};

struct NavigationDirection {
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();  // |direction| <= 1
  double blend = 0.0;       // beta: 0 straight at the target, 1 the field's direction
  bool field_used = false;  // the field was computed (beta > 0)
  int accepted_nodes = 0;   // fast-marching work (0 without the field)
};

// Least clearance of the segment [a, b] from the zones (|x - c_j| - R_eff - r_j); +inf without disks.
double segmentClearance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const std::vector<Disk>& obstacles,
                        double robot_radius);

// The slowness f(x) of the field (1 in free space).
// Disks from index bridges_from on are narrowGapsClosed's bridges (harder inside).
double fieldSlowness(const Eigen::Vector2d& x, const std::vector<Disk>& obstacles, const NavigationFieldConfig& config,
                     std::size_t bridges_from = static_cast<std::size_t>(-1));

// The disks as the field sees them: the sensed ones plus, between two whose zones leave a
// corridor w < 2a (a = 2 cells) the grid cannot resolve, a bridge disk at the corridor's middle
// whose zone grows continuously from nothing (zone radius -margin, no slowness) at w = 2a to
// w/2 + 3 cells at w <= a, which shuts the corridor. (A bridge's radius may be negative: only
// its zone R + r_b counts.) The safety filter still holds the true disks.
std::vector<Disk> narrowGapsClosed(const std::vector<Disk>& obstacles, const NavigationFieldConfig& config);

// The disks as the field sees moving ones: each disk with a velocity also repeated along the path
// it walks over `horizon` [s] (c + v t, 0 < t <= horizon, copies at most half its radius apart,
// at most kMaxPathCopies), so the field routes behind a person crossing the way rather than
// ahead of them, and out of the path of one coming from behind. Static disks as they are;
// horizon 0: the disks unchanged. Continuous in v except where a copy is added, which lies
// inside the others' union then (its zone adds nothing new at that instant).
// A copy the robot cannot reach before the disk has walked past it (t + R_j / |v_j| <
// |c_j(t) - from| / speed, R_j = `reach` + r_j the zone's radius) is left out: the person will
// have gone by then, so the robot may pass behind them. A disk standing after a walk (its
// resume_velocity) is seen along the path it would walk on, every copy kept: it may start at
// any moment, so the robot passes behind a person who stopped, not in front of them.
std::vector<Disk> withPredictedPaths(const std::vector<Disk>& obstacles, double horizon, const Eigen::Vector2d& from,
                                     double speed, double reach);
constexpr int kMaxPathCopies = 40;

// Where the field aims when `goal` lies on a moving disk's path: moved out of each such path
// (the capsule swept by the zone, radius robot_radius + r_j + margin, from c_j to c_j +
// v_j horizon) along the perpendicular, to its edge. So a robot whose target a person is about
// to walk through waits beside the person's path, rather than on it until the person is upon it
// (then the barrier can only push it ahead of them). The side is the goal's own; exactly on the
// path line, `side_hint`'s (p_r's). Continuous in the geometry except on that line. A standing
// disk's path is the one it would walk on (resume_velocity): the robot waits beside it.
Eigen::Vector2d goalOutOfPaths(const Eigen::Vector2d& goal, const Eigen::Vector2d& side_hint,
                               const std::vector<Disk>& obstacles, double horizon, double robot_radius, double margin);

// The field seeded at `goal` (p_d, or ahead of a blocked target: recommended_law.cpp), blended
// by the line of sight p_r -> p_d.
NavigationDirection navigationDirection(const Eigen::Vector2d& p_r, const Eigen::Vector2d& p_d,
                                        const Eigen::Vector2d& goal, const std::vector<Disk>& obstacles,
                                        const NavigationFieldConfig& config);

}  // namespace core
}  // namespace amigobot_tracking

#include "amigobot_tracking/core/law/navigation_field.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace amigobot_tracking {
namespace core {
namespace {

constexpr double kBandSlowness = 3.0;  // at a zone's boundary, from outside
constexpr double kZoneSlowness = 20.0; // deep inside a zone
constexpr double kInf = std::numeric_limits<double>::infinity();
// A corridor between two zones narrower than this many cells is not resolved by the grid: the
// field's direction in it flips from one node to the next (p_r wedged in a 7 cm corridor of a
// U's back wall, d = +-side on alternate steps, 0.8 rad/s bang-bang). narrowGapsClosed closes it.
constexpr double kResolvedGapCells = 2.0;
// A bridge's zone reaches this many cells beyond the corridor's middle: zones are soft (20x),
// so a bridge one cell thick was crossed rather than a 3 m detour taken round a U.
constexpr double kBridgeCells = 3.0;
// Deep inside a bridge: harder than a disk's zone (20), since a bridge stands for a gap the body
// cannot take; at 20 the field still sent p_r into such gaps of a U's back wall and the robot
// stood wedged there up to 30 s (5 of 50 runs; 28: 1.1 s). A disk's own zone stays soft (a
// target inside it pulls to the best standoff; 50 for every zone made p_r reverse round
// disks 5-14 times in test_recommended_law's scenes, 35 here 5 times in its U).
constexpr double kBridgeSlowness = 28.0;

// The grid: nodes at (i0 + i, j0 + j) * cell, i in [0, nx), j in [0, ny).
struct Grid {
  double cell;
  long i0, j0;
  int nx, ny;
  std::vector<double> phi, slowness;
  std::vector<char> accepted;
  int index(int i, int j) const { return j * nx + i; }
  Eigen::Vector2d position(int i, int j) const { return {(i0 + i) * cell, (j0 + j) * cell}; }
  bool inside(int i, int j) const { return i >= 0 && j >= 0 && i < nx && j < ny; }
};

// The first-order upwind update of node (i, j) from its accepted neighbours.
double upwind(const Grid& g, int i, int j) {
  auto value = [&](int a, int b) {
    return g.inside(a, b) && g.accepted[g.index(a, b)] ? g.phi[g.index(a, b)] : kInf;
  };
  const double a = std::min(value(i - 1, j), value(i + 1, j));
  const double b = std::min(value(i, j - 1), value(i, j + 1));
  const double step = g.slowness[g.index(i, j)] * g.cell;
  const double lo = std::min(a, b);
  if (!std::isfinite(lo)) return kInf;
  const double hi = std::max(a, b);
  if (!std::isfinite(hi) || hi - lo >= step) return lo + step;
  // (phi - a)^2 + (phi - b)^2 = step^2, the larger root.
  return 0.5 * (a + b + std::sqrt(2.0 * step * step - (a - b) * (a - b)));
}

}  // namespace

double segmentClearance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const std::vector<Disk>& obstacles,
                        double robot_radius) {
  double least = kInf;
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  for (const Disk& o : obstacles) {
    const double s = length2 > 0.0 ? std::clamp((o.center - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    least = std::min(least, (a + s * ab - o.center).norm() - robot_radius - o.radius);
  }
  return least;
}

double fieldSlowness(const Eigen::Vector2d& x, const std::vector<Disk>& obstacles, const NavigationFieldConfig& config,
                     std::size_t bridges_from) {
  double f = 1.0;
  for (std::size_t j = 0; j < obstacles.size(); ++j) {
    const Disk& o = obstacles[j];
    const double deep = j < bridges_from ? kZoneSlowness : kBridgeSlowness;
    const double h = (x - o.center).norm() - config.robot_radius - o.radius;
    if (h >= config.margin) continue;
    const double outside = 1.0 - std::max(h, 0.0) / config.margin;  // 0 at the ramp's edge, 1 at the boundary
    double value = 1.0 + (kBandSlowness - 1.0) * outside * outside;
    if (h < 0.0) value += (deep - kBandSlowness) * std::min(1.0, -2.0 * h / config.margin);
    f = std::max(f, value);
  }
  return f;
}

std::vector<Disk> narrowGapsClosed(const std::vector<Disk>& obstacles, const NavigationFieldConfig& config) {
  const double a = kResolvedGapCells * config.cell;
  std::vector<Disk> zones = obstacles;
  for (size_t j = 0; j < obstacles.size(); ++j)
    for (size_t k = j + 1; k < obstacles.size(); ++k) {
      const Eigen::Vector2d between = obstacles[k].center - obstacles[j].center;
      const double distance = between.norm();
      const double w = distance - obstacles[j].radius - obstacles[k].radius - 2.0 * config.robot_radius;
      const double t = std::clamp((2.0 * a - w) / a, 0.0, 1.0);
      const double closing = 0.5 * w + kBridgeCells * config.cell;  // the bridge's zone radius that shuts the corridor
      if (t <= 0.0 || closing <= -config.margin || distance < 1e-9) continue;
      // Zone radius from -margin (no slowness anywhere) at t = 0 to `closing` at t = 1.
      const double zone = -config.margin + t * (closing + config.margin);
      Disk bridge;
      bridge.center = obstacles[j].center + (obstacles[j].radius + config.robot_radius + 0.5 * w) / distance * between;
      bridge.radius = zone - config.robot_radius;
      zones.push_back(bridge);
    }
  return zones;
}

std::vector<Disk> withPredictedPaths(const std::vector<Disk>& obstacles, double horizon, const Eigen::Vector2d& from,
                                     double speed, double reach) {
  std::vector<Disk> out = obstacles;
  if (!(horizon > 0.0)) return out;
  for (const Disk& o : obstacles) {
    // A person standing after a walk may walk on at any moment: their path stays (no "gone by then").
    const bool standing = !(o.velocity.norm() > 0.0);
    const Eigen::Vector2d velocity = standing ? o.resume_velocity : o.velocity;
    const double travel = velocity.norm() * horizon;
    if (!(travel > 0.0) || !std::isfinite(travel)) continue;
    const double spacing = std::max(0.5 * o.radius, 0.05);
    const int copies = std::min(kMaxPathCopies, static_cast<int>(std::ceil(travel / spacing)));
    for (int k = 1; k <= copies; ++k) {
      Disk ahead = o;
      const double t = horizon * k / copies;
      ahead.center = o.center + velocity * t;
      if (!standing && t + (reach + o.radius) / velocity.norm() < (ahead.center - from).norm() / speed) continue;  // gone by then
      out.push_back(ahead);
    }
  }
  return out;
}

Eigen::Vector2d goalOutOfPaths(const Eigen::Vector2d& goal, const Eigen::Vector2d& side_hint,
                               const std::vector<Disk>& obstacles, double horizon, double robot_radius, double margin) {
  Eigen::Vector2d out = goal;
  if (!(horizon > 0.0)) return out;
  for (const Disk& o : obstacles) {
    const Eigen::Vector2d path = (o.velocity.norm() > 0.0 ? o.velocity : o.resume_velocity) * horizon;
    const double length2 = path.squaredNorm();
    if (!(length2 > 1e-12) || !path.allFinite()) continue;
    const double s = std::clamp((out - o.center).dot(path) / length2, 0.0, 1.0);
    const Eigen::Vector2d nearest = o.center + s * path;
    Eigen::Vector2d off = out - nearest;
    const double zone = robot_radius + o.radius + margin;
    const double distance = off.norm();
    if (distance >= zone) continue;
    if (distance < 1e-9) {  // on the path line: to p_r's side (left when that is on it too)
      const Eigen::Vector2d normal(-path.y(), path.x());
      off = (side_hint - o.center).dot(normal) < 0.0 ? Eigen::Vector2d(-normal) : normal;
    }
    out = nearest + zone * off.normalized();
  }
  return out;
}

NavigationDirection navigationDirection(const Eigen::Vector2d& p_r, const Eigen::Vector2d& p_d,
                                        const Eigen::Vector2d& goal, const std::vector<Disk>& sensed,
                                        const NavigationFieldConfig& config) {
  const std::vector<Disk> obstacles = narrowGapsClosed(sensed, config);
  NavigationDirection out;
  const Eigen::Vector2d e = p_d - p_r;
  const Eigen::Vector2d e_hat = e.norm() > 1e-12 ? Eigen::Vector2d(e / e.norm()) : Eigen::Vector2d::Zero();
  const double q = segmentClearance(p_r, p_d, obstacles, config.robot_radius);
  out.blend = std::clamp(1.0 - q / config.margin, 0.0, 1.0);
  out.direction = e_hat;
  if (out.blend <= 0.0) return out;

  // The grid, aligned to multiples of the cell so it does not shift with the robot.
  const double c = config.cell;
  const double half = 0.5 * config.max_extent;
  const Eigen::Vector2d pad = Eigen::Vector2d::Constant(config.padding), reach = Eigen::Vector2d::Constant(half);
  const Eigen::Vector2d lo = (p_r.cwiseMin(p_d).cwiseMin(goal) - pad).cwiseMax(p_r - reach);
  const Eigen::Vector2d hi = (p_r.cwiseMax(p_d).cwiseMax(goal) + pad).cwiseMin(p_r + reach);
  Grid g;
  g.cell = c;
  g.i0 = static_cast<long>(std::floor(lo.x() / c));
  g.j0 = static_cast<long>(std::floor(lo.y() / c));
  g.nx = static_cast<int>(std::ceil(hi.x() / c) - g.i0) + 1;
  g.ny = static_cast<int>(std::ceil(hi.y() / c) - g.j0) + 1;
  const size_t nodes = static_cast<size_t>(g.nx) * g.ny;
  g.phi.assign(nodes, kInf);
  g.slowness.resize(nodes);
  g.accepted.assign(nodes, 0);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) g.slowness[g.index(i, j)] = fieldSlowness(g.position(i, j), obstacles, config, sensed.size());

  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> trial;
  // Seeds: the nodes around the goal (clamped into the grid) at their exact straight
  // distance times the goal's slowness, so phi moves continuously with the goal.
  const double goal_slowness = fieldSlowness(goal, obstacles, config, sensed.size());
  const int ti = static_cast<int>(std::floor(goal.x() / c) - g.i0), tj = static_cast<int>(std::floor(goal.y() / c) - g.j0);
  for (int j = tj - 1; j <= tj + 2; ++j)
    for (int i = ti - 1; i <= ti + 2; ++i) {
      if (!g.inside(i, j)) continue;
      const double value = goal_slowness * (g.position(i, j) - goal).norm();
      g.phi[g.index(i, j)] = value;
      trial.emplace(value, g.index(i, j));
    }
  if (trial.empty()) return out;  // the target beyond max_extent: head straight for it
  // March until the 6 x 6 nodes around p_r's cell (its corners and their neighbours) are final.
  const int ri = static_cast<int>(std::floor(p_r.x() / c) - g.i0), rj = static_cast<int>(std::floor(p_r.y() / c) - g.j0);
  int needed = 0;
  for (int j = rj - 2; j <= rj + 3; ++j)
    for (int i = ri - 2; i <= ri + 3; ++i) needed += g.inside(i, j) ? 1 : 0;
  auto nearRobot = [&](int i, int j) { return i >= ri - 2 && i <= ri + 3 && j >= rj - 2 && j <= rj + 3; };
  while (!trial.empty() && needed > 0) {
    const auto [value, k] = trial.top();
    trial.pop();
    if (g.accepted[k] || value > g.phi[k]) continue;
    g.accepted[k] = 1;
    ++out.accepted_nodes;
    const int i = k % g.nx, j = k / g.nx;
    if (nearRobot(i, j)) --needed;
    const int di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
    for (int n = 0; n < 4; ++n) {
      const int a = i + di[n], b = j + dj[n];
      if (!g.inside(a, b) || g.accepted[g.index(a, b)]) continue;
      const double candidate = upwind(g, a, b);
      if (candidate < g.phi[g.index(a, b)]) {
        g.phi[g.index(a, b)] = candidate;
        trial.emplace(candidate, g.index(a, b));
      }
    }
  }
  auto phiAt = [&](int i, int j) {
    i = std::clamp(i, 0, g.nx - 1);
    j = std::clamp(j, 0, g.ny - 1);
    return g.phi[g.index(i, j)];
  };
  // Central differences at a node (one-sided at the grid's edge).
  auto gradientAt = [&](int i, int j) {
    const int il = std::max(i - 1, 0), ih = std::min(i + 1, g.nx - 1);
    const int jl = std::max(j - 1, 0), jh = std::min(j + 1, g.ny - 1);
    return Eigen::Vector2d((phiAt(ih, j) - phiAt(il, j)) / ((ih - il) * c),
                           (phiAt(i, jh) - phiAt(i, jl)) / ((jh - jl) * c));
  };
  const double fx = p_r.x() / c - (g.i0 + ri), fy = p_r.y() / c - (g.j0 + rj);
  const Eigen::Vector2d gradient = (1 - fx) * (1 - fy) * gradientAt(ri, rj) + fx * (1 - fy) * gradientAt(ri + 1, rj) +
                                   (1 - fx) * fy * gradientAt(ri, rj + 1) + fx * fy * gradientAt(ri + 1, rj + 1);
  out.field_used = true;
  Eigen::Vector2d field_direction = Eigen::Vector2d::Zero();
  if (gradient.allFinite()) field_direction = -gradient / std::max(1.0, gradient.norm());
  out.direction = (1.0 - out.blend) * e_hat + out.blend * field_direction;
  return out;
}

}  // namespace core
}  // namespace amigobot_tracking

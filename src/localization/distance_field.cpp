#include "amigobot_tracking/localization/distance_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace amigobot_tracking {
namespace localization {

namespace {

// Felzenszwalb & Huttenlocher's 1-D squared distance transform of f (n samples, in cells);
// "no obstacle" is a large finite value so that the parabola algebra stays finite.
constexpr double kFar = 1e12;

void transform1d(const std::vector<double>& f, int n, std::vector<double>* d, std::vector<int>* v, std::vector<double>* z) {
  int k = 0;
  (*v)[0] = 0;
  (*z)[0] = -std::numeric_limits<double>::infinity();
  (*z)[1] = std::numeric_limits<double>::infinity();
  for (int q = 1; q < n; ++q) {
    double s = 0.0;
    while (true) {
      const int p = (*v)[k];
      s = ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * q - 2.0 * p);
      if (s > (*z)[k]) break;  // ends at k = 0 at the latest: z[0] = -inf
      --k;
    }
    ++k;
    (*v)[k] = q;
    (*z)[k] = s;
    (*z)[k + 1] = std::numeric_limits<double>::infinity();
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while ((*z)[k + 1] < q) ++k;
    const int p = (*v)[k];
    (*d)[q] = double(q - p) * (q - p) + f[p];
  }
}

}  // namespace

DistanceField::DistanceField(const OccupancyMap& map, double cap) : map_(map), cap_(cap) {
  const int w = map.width, h = map.height;
  std::vector<double> grid(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) grid[static_cast<std::size_t>(y) * w + x] = map.occupied(x, y) ? 0.0 : kFar;
  const int n = std::max(w, h);
  std::vector<double> f(n), d(n), z(n + 1);
  std::vector<int> v(n);
  for (int x = 0; x < w; ++x) {
    for (int y = 0; y < h; ++y) f[y] = grid[static_cast<std::size_t>(y) * w + x];
    transform1d(f, h, &d, &v, &z);
    for (int y = 0; y < h; ++y) grid[static_cast<std::size_t>(y) * w + x] = d[y];
  }
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) f[x] = grid[static_cast<std::size_t>(y) * w + x];
    transform1d(f, w, &d, &v, &z);
    for (int x = 0; x < w; ++x) grid[static_cast<std::size_t>(y) * w + x] = d[x];
  }
  distance_.resize(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i)
    distance_[i] = static_cast<float>(std::min(cap_, std::sqrt(grid[i]) * map.resolution));
}

double DistanceField::distance(double x, double y) const {
  int cx = 0, cy = 0;
  map_.cellOf(x, y, &cx, &cy);
  if (!map_.contains(cx, cy)) return cap_;
  return distance_[static_cast<std::size_t>(cy) * map_.width + cx];
}

double DistanceField::matchFraction(const std::vector<Eigen::Vector2d>& points, const core::Pose2& pose, double match_distance) const {
  if (points.empty()) return 0.0;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  int matched = 0;
  for (const Eigen::Vector2d& p : points)
    matched += distance(pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y()) <= match_distance;
  return static_cast<double>(matched) / points.size();
}

double DistanceField::score(const std::vector<Eigen::Vector2d>& points, const core::Pose2& pose, double sigma) const {
  if (points.empty()) return 0.0;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta), k = -0.5 / (sigma * sigma);
  double sum = 0.0;
  for (const Eigen::Vector2d& p : points) {
    const double d = distance(pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y());
    sum += std::exp(k * d * d);
  }
  return sum / points.size();
}

}  // namespace localization
}  // namespace amigobot_tracking

#include "amigobot_tracking/localization/localizer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/slam/CICP.h>

#include "amigobot_tracking/localization/poses.h"

namespace amigobot_tracking {
namespace localization {

namespace {

// Distances beyond the farthest useful one do not matter to the scores.
constexpr double kFieldCap = 2.0;  // [m]

}  // namespace

Localizer::Localizer(const LocalizationConfig& config, const OccupancyMap& map)
    : config_(config), field_(map, kFieldCap), map_points_(std::make_unique<mrpt::maps::CSimplePointsMap>()) {
  if (map.empty()) throw std::invalid_argument("map: empty");
  std::vector<Eigen::Vector2d> occupied;
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x)
      if (map.occupied(x, y)) occupied.push_back(map.cellCenter(x, y));
  if (occupied.empty()) throw std::invalid_argument("map: no occupied cell to localise against");
  toPointsMap(occupied, map_points_.get());
  setPose(config.initial_pose, core::Pose2());
}

Localizer::~Localizer() = default;

void Localizer::setPose(const core::Pose2& map_base, const core::Pose2& odom_base) {
  estimate_ = PoseEstimate();
  estimate_.pose = map_base;
  estimate_.map_to_odom = compose(map_base, inverse(odom_base));
  match_covariance_ = Eigen::Vector3d(0.25, 0.25, 0.07).asDiagonal();  // unknown until a match
  estimate_.covariance = match_covariance_;
  last_match_odom_ = odom_base;
  settled_ = false;
}

core::Pose2 Localizer::align(const std::vector<Eigen::Vector2d>& points, const core::Pose2& guess, Eigen::Matrix3d* covariance,
                             double* goodness) const {
  mrpt::maps::CSimplePointsMap scan_points;
  toPointsMap(points, &scan_points);
  mrpt::slam::CICP icp;
  icp.options.maxIterations = static_cast<unsigned>(config_.icp.max_iterations);
  icp.options.thresholdDist = config_.icp.max_correspondence;
  icp.options.smallestThresholdDist = config_.icp.min_correspondence;
  icp.options.corresponding_points_decimation = 1;  // the scan is decimated already
  mrpt::slam::CICP::TReturnInfo info;
  const mrpt::poses::CPosePDF::Ptr pdf = icp.Align(map_points_.get(), &scan_points, toMrpt(guess), info);
  mrpt::poses::CPosePDFGaussian gaussian;
  gaussian.copyFrom(*pdf);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) (*covariance)(r, c) = gaussian.cov(r, c);
  *goodness = info.goodness;
  return fromMrpt(gaussian.mean);
}

const PoseEstimate& Localizer::update(const RangeScan& scan, const core::Pose2& odom_base) {
  const core::Pose2 predicted = compose(estimate_.map_to_odom, odom_base);
  const double moved = travel(odom_base, last_match_odom_);
  const bool due = !settled_ || moved >= config_.min_travel || turn(odom_base, last_match_odom_) >= config_.min_rotation;
  estimate_.pose = predicted;
  estimate_.matched = false;
  estimate_.correction = estimate_.correction_angle = 0.0;
  // Odometry alone since the last match: its uncertainty grows with the travel (10 %).
  estimate_.covariance = match_covariance_;
  estimate_.covariance(0, 0) += 0.01 * moved * moved;
  estimate_.covariance(1, 1) += 0.01 * moved * moved;
  // The match is measured on every scan (cheap), ICP runs only when due.
  const std::vector<Eigen::Vector2d> points = scanPoints(scan, config_.range_max, config_.icp.max_points);
  const double before = field_.matchFraction(points, predicted, config_.match_distance);
  estimate_.match = before;
  estimate_.lost = before < config_.min_match;
  if (!due || points.size() < 10) return estimate_;
  Eigen::Matrix3d covariance;
  double goodness = 0.0;
  const core::Pose2 corrected = align(points, predicted, &covariance, &goodness);
  const double after = field_.matchFraction(points, corrected, config_.match_distance);
  estimate_.icp_goodness = goodness;
  // ICP trapped in a worse minimum (e.g. a scan of mostly unmapped clutter) is refused.
  if (after < before) return estimate_;
  settled_ = travel(corrected, predicted) < 0.02 && turn(corrected, predicted) < 0.01;
  estimate_.pose = corrected;
  estimate_.map_to_odom = compose(corrected, inverse(odom_base));
  estimate_.match = after;
  estimate_.lost = after < config_.min_match;
  estimate_.matched = true;
  estimate_.correction = travel(corrected, predicted);
  estimate_.correction_angle = turn(corrected, predicted);
  estimate_.covariance = match_covariance_ = covariance;
  last_match_odom_ = odom_base;
  return estimate_;
}

GlobalSearch Localizer::relocalize(const RangeScan& scan, const core::Pose2& odom_base) {
  GlobalSearch result;
  const std::vector<Eigen::Vector2d> points = scanPoints(scan, config_.range_max, std::min(config_.icp.max_points, 120));
  if (points.size() < 10) return result;
  const GlobalConfig& g = config_.global;
  // The scan turned to every candidate heading once.
  const int headings = std::max(1, static_cast<int>(std::round(2.0 * M_PI / g.yaw_step)));
  std::vector<std::vector<Eigen::Vector2d>> turned(static_cast<std::size_t>(headings));
  for (int h = 0; h < headings; ++h) {
    const double a = 2.0 * M_PI * h / headings, c = std::cos(a), s = std::sin(a);
    for (const Eigen::Vector2d& p : points) turned[h].emplace_back(c * p.x() - s * p.y(), s * p.x() + c * p.y());
  }
  // Coarse scores: a likelihood field wide enough to forgive half a grid step.
  const double sigma = std::max(config_.match_distance, g.xy_step);
  const OccupancyMap& map = field_.map();
  struct Candidate {
    core::Pose2 pose;
    double score;
  };
  std::vector<Candidate> best;
  const int stride = std::max(1, static_cast<int>(std::round(g.xy_step / map.resolution)));
  for (int cy = stride / 2; cy < map.height; cy += stride) {
    for (int cx = stride / 2; cx < map.width; cx += stride) {
      if (map.at(cx, cy) != OccupancyMap::kFree) continue;
      const Eigen::Vector2d centre = map.cellCenter(cx, cy);
      if (field_.distance(centre.x(), centre.y()) < g.clearance) continue;
      for (int h = 0; h < headings; ++h) {
        ++result.candidates;
        const core::Pose2 pose{centre.x(), centre.y(), core::wrapAngle(2.0 * M_PI * h / headings)};
        const double score = field_.score(turned[h], core::Pose2{centre.x(), centre.y(), 0.0}, sigma);
        best.push_back({pose, score});
      }
    }
  }
  // The best candidates, at most one per neighbourhood (position and heading).
  std::sort(best.begin(), best.end(), [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
  std::vector<Candidate> kept;
  for (const Candidate& c : best) {
    if (static_cast<int>(kept.size()) >= g.candidates) break;
    const bool near = std::any_of(kept.begin(), kept.end(), [&](const Candidate& k) {
      return travel(k.pose, c.pose) < 2.0 * g.xy_step && turn(k.pose, c.pose) < 3.0 * g.yaw_step;
    });
    if (!near) kept.push_back(c);
  }
  // ICP from each (twice: the coarse pose may be far from the pairing distance).
  for (const Candidate& c : kept) {
    Eigen::Matrix3d covariance;
    double goodness = 0.0;
    core::Pose2 pose = align(points, c.pose, &covariance, &goodness);
    pose = align(points, pose, &covariance, &goodness);
    const double match = field_.matchFraction(points, pose, config_.match_distance);
    if (match > result.match) {
      result.match = match;
      result.pose = pose;
    }
  }
  result.found = result.match >= g.min_match;
  if (result.found) setPose(result.pose, odom_base);
  return result;
}

}  // namespace localization
}  // namespace amigobot_tracking

#include "amigobot_tracking/localization/graph_mapper.h"

#include <algorithm>
#include <cmath>

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/slam/CICP.h>

#include "amigobot_tracking/localization/map_drawing.h"
#include "amigobot_tracking/localization/mapper.h"
#include "amigobot_tracking/localization/poses.h"

namespace amigobot_tracking {
namespace localization {

namespace {

// The front end aligns against the keyframes of the last kLocalTravel of travel, at least the
// last kLocalKeyframes: a submap that keeps the walls behind a corner while the robot turns into
// the next corridor. With the last 8 keyframes only (6 m on the ACES building, where scans are
// 0.73 m apart) each corner added up to 2 deg of heading error; the online ATE there went from
// 0.397 m to 0.213 m (Intel lab 0.103 m to 0.092 m; last 30 keyframes: 0.175 m and 0.101 m).
constexpr int kLocalKeyframes = 8;
constexpr double kLocalTravel = 10.0;      // [m]
// A new keyframe is matched against the 3 nearest old places (keyframes more than 2 x kLoopSpan
// apart), not only the nearest: on the ACES building the loops went from 47 to 121 and the
// smoothed ATE from 0.113 m to 0.096 m (with the corridor edges below).
constexpr int kLoopCandidates = 3;
// Shifts probed in this many directions over half a turn, to find a corridor's axis.
constexpr int kProbeDirections = 8;
// [m] a corridor's loop edge: the position along it as uncertain as this (across it, 5 cm).
constexpr double kAlongCorridor = 3.0;
constexpr int kLoopSpan = 3;               // a loop is matched against the old keyframe and 3 each side
constexpr double kKeyframeRotation = 0.35;  // [rad] turn that makes a keyframe
constexpr double kProbe = 0.3;             // [m] shifts of a loop match that must fit worse
constexpr double kProbeTurn = 0.1;         // [rad] turns likewise
// Above 0.85 (a shifted pose fitting 85 % as well) the Intel log took 11 wrong loops (> 0.3 m
// off), at 0.85 it took 7 of 281 and the ATE fell from 0.34 m to 0.075 m.
constexpr double kMaxAmbiguity = 0.85;
constexpr double kMaxDrift = 0.05;         // [m/m] front-end drift bound for a loop's correction
// The front end refuses an ICP correction larger than 0.1 m + 20 % of the travel since the last
// match (the odometry then stands): on the Intel log the second scan, turning in place against
// one keyframe, slid 0.33 m and the online pose kept that offset until loops pulled it back;
// with this gate the online ATE went from 0.117 m to 0.091 m (0.05 m + 20 %: 0.106; 0.1 m +
// 10 %: 0.098; 0.15 m + 20 %: 0.090).
constexpr double kMaxSlide = 0.1;          // [m]
constexpr double kMaxSlidePerTravel = 0.2; // [m/m]
constexpr double kMinGoodness = 0.4;       // MRPT's fraction of paired points below which ICP is refused

// Information of an edge: a scan-matched motion known to a few centimetres and about a degree.
Eigen::Matrix3d edgeInformation() { return Eigen::Vector3d(1.0 / (0.05 * 0.05), 1.0 / (0.05 * 0.05), 1.0 / (0.02 * 0.02)).asDiagonal(); }

}  // namespace

GraphMapper::GraphMapper(const LocalizationConfig& config) : config_(config), pose_(config.initial_pose) {}

GraphMapper::~GraphMapper() = default;

void GraphMapper::collectPoints(int first, int last, mrpt::maps::CSimplePointsMap* out) const {
  out->clear();
  for (int k = std::max(0, first); k <= last && k < static_cast<int>(keyframes_.size()); ++k) {
    const core::Pose2& p = graph_.nodes()[static_cast<std::size_t>(k)];
    const double c = std::cos(p.theta), s = std::sin(p.theta);
    for (const Eigen::Vector2d& q : keyframes_[static_cast<std::size_t>(k)].points)
      out->insertPointFast(static_cast<float>(p.x + c * q.x() - s * q.y()), static_cast<float>(p.y + s * q.x() + c * q.y()), 0.0f);
  }
  out->mark_as_modified();
}

core::Pose2 GraphMapper::align(const mrpt::maps::CSimplePointsMap& reference, const std::vector<Eigen::Vector2d>& points,
                               const core::Pose2& guess, double first_pairing, Eigen::Matrix3d* covariance, double* goodness) const {
  mrpt::maps::CSimplePointsMap scan_points;
  toPointsMap(points, &scan_points);
  mrpt::slam::CICP icp;
  icp.options.maxIterations = static_cast<unsigned>(config_.icp.max_iterations);
  icp.options.thresholdDist = first_pairing;
  icp.options.smallestThresholdDist = config_.icp.min_correspondence;
  icp.options.corresponding_points_decimation = 1;
  mrpt::slam::CICP::TReturnInfo info;
  const mrpt::poses::CPosePDF::Ptr pdf = icp.Align(&reference, &scan_points, toMrpt(guess), info);
  mrpt::poses::CPosePDFGaussian gaussian;
  gaussian.copyFrom(*pdf);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) (*covariance)(r, c) = gaussian.cov(r, c);
  *goodness = info.goodness;
  return fromMrpt(gaussian.mean);
}

double GraphMapper::matchFraction(const mrpt::maps::CSimplePointsMap& reference, const std::vector<Eigen::Vector2d>& points,
                                  const core::Pose2& pose) const {
  if (points.empty() || reference.size() == 0) return 0.0;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta), limit = config_.match_distance * config_.match_distance;
  int matched = 0;
  for (const Eigen::Vector2d& q : points) {
    const float x = static_cast<float>(pose.x + c * q.x() - s * q.y()), y = static_cast<float>(pose.y + s * q.x() + c * q.y());
    matched += reference.kdTreeClosestPoint2DsqrError(x, y) <= limit;
  }
  return static_cast<double>(matched) / points.size();
}

void GraphMapper::addKeyframe(const RangeScan& scan, const std::vector<Eigen::Vector2d>& points) {
  const int index = graph_.addNode(pose_);
  keyframes_.push_back({scan, points});
  path_.push_back(index == 0 ? 0.0 : path_.back() + travel(graph_.nodes()[static_cast<std::size_t>(index - 1)], pose_));
  if (index > 0) {
    PoseGraphEdge edge;
    edge.from = index - 1;
    edge.to = index;
    edge.measurement = compose(inverse(graph_.nodes()[static_cast<std::size_t>(index - 1)]), pose_);
    edge.information = edgeInformation();
    graph_.addEdge(edge);
  }
}

bool GraphMapper::closeLoop(int k) {
  const core::Pose2 current = graph_.nodes()[static_cast<std::size_t>(k)];
  // Old keyframes within the loop radius, nearest first.
  std::vector<std::pair<double, int>> near;
  for (int j = 0; j + config_.graph.loop_min_gap <= k; ++j) {
    const double d = travel(graph_.nodes()[static_cast<std::size_t>(j)], current);
    if (d <= config_.graph.loop_radius) near.emplace_back(d, j);
  }
  std::sort(near.begin(), near.end());
  std::vector<int> tried;
  int added = 0;
  for (const auto& candidate : near) {
    if (static_cast<int>(tried.size()) >= kLoopCandidates) break;
    const int best = candidate.second;
    if (std::any_of(tried.begin(), tried.end(), [&](int t) { return std::abs(t - best) <= 2 * kLoopSpan; })) continue;
    tried.push_back(best);
    PoseGraphEdge edge;
    if (!matchLoop(k, best, &edge)) continue;
    graph_.addEdge(edge);
    ++added;
  }
  if (added == 0) return false;
  graph_.optimize(10);
  loops_ += added;
  return true;
}

bool GraphMapper::matchLoop(int k, int best, PoseGraphEdge* edge) const {
  const core::Pose2 current = graph_.nodes()[static_cast<std::size_t>(k)];
  mrpt::maps::CSimplePointsMap old_points;
  collectPoints(best - kLoopSpan, std::min(best + kLoopSpan, k - config_.graph.loop_min_gap), &old_points);
  const std::vector<Eigen::Vector2d>& points = keyframes_[static_cast<std::size_t>(k)].points;
  Eigen::Matrix3d covariance;
  double goodness = 0.0;
  // The drift since the old keyframe may exceed the front end's pairing distance.
  const double first_pairing = std::max(config_.icp.max_correspondence, 0.5 * config_.graph.loop_radius);
  core::Pose2 aligned = align(old_points, points, current, first_pairing, &covariance, &goodness);
  aligned = align(old_points, points, aligned, config_.icp.max_correspondence, &covariance, &goodness);
  const double fraction = matchFraction(old_points, points, aligned);
  if (goodness < kMinGoodness || fraction < config_.graph.loop_min_match) return false;
  auto ratio = [&](const core::Pose2& shift) { return matchFraction(old_points, points, compose(aligned, shift)) / fraction; };
  // A turn that fits as well: the match fixes nothing.
  if (std::max(ratio({0, 0, kProbeTurn}), ratio({0, 0, -kProbeTurn})) > kMaxAmbiguity) return false;
  // The direction along which a shift fits best (a corridor's axis), and the one across it.
  double slide = 0.0, slide_angle = 0.0;
  for (int i = 0; i < kProbeDirections; ++i) {
    const double a = M_PI * i / kProbeDirections, c = kProbe * std::cos(a), s = kProbe * std::sin(a);
    const double r = std::max(ratio({c, s, 0}), ratio({-c, -s, 0}));
    if (r > slide) {
      slide = r;
      slide_angle = a;
    }
  }
  edge->information = edgeInformation();
  if (slide > kMaxAmbiguity) {
    const double a = slide_angle + M_PI / 2, c = kProbe * std::cos(a), s = kProbe * std::sin(a);
    if (std::max(ratio({c, s, 0}), ratio({-c, -s, 0})) > kMaxAmbiguity) return false;  // open space: nothing fixed
    // A corridor: the match fixes the position across it and the heading, not along it.
    Eigen::Matrix2d r;
    r << std::cos(slide_angle), -std::sin(slide_angle), std::sin(slide_angle), std::cos(slide_angle);
    const Eigen::Matrix2d local = Eigen::Vector2d(1.0 / (kAlongCorridor * kAlongCorridor), 1.0 / (0.05 * 0.05)).asDiagonal();
    edge->information.topLeftCorner<2, 2>() = r * local * r.transpose();
  }
  // A correction larger than the front end can have drifted since is a wrong match.
  const double path = path_[static_cast<std::size_t>(k)] - path_[static_cast<std::size_t>(best)];
  if (travel(aligned, current) > std::max(0.2, kMaxDrift * path)) return false;
  edge->from = best;
  edge->to = k;
  edge->measurement = compose(inverse(graph_.nodes()[static_cast<std::size_t>(best)]), aligned);
  edge->robust = true;
  return true;
}

void GraphMapper::update(const RangeScan& scan, const core::Pose2& odom_base, PoseEstimate* estimate) {
  const std::vector<Eigen::Vector2d> points = scanPoints(scan, config_.range_max, config_.icp.max_points);
  if (keyframes_.empty()) {
    last_odom_ = last_match_odom_ = odom_base;
    addKeyframe(scan, points);
  } else {
    pose_ = compose(pose_, compose(inverse(last_odom_), odom_base));
    last_odom_ = odom_base;
    const bool due = travel(odom_base, last_match_odom_) >= config_.min_travel || turn(odom_base, last_match_odom_) >= config_.min_rotation;
    if (due && points.size() >= 10) {
      const int last = static_cast<int>(keyframes_.size()) - 1;
      mrpt::maps::CSimplePointsMap local;
      int first = last - kLocalKeyframes + 1;
      while (first > 0 && path_[static_cast<std::size_t>(last)] - path_[static_cast<std::size_t>(first - 1)] <= kLocalTravel) --first;
      collectPoints(first, last, &local);
      double goodness = 0.0;
      Eigen::Matrix3d covariance;
      const core::Pose2 aligned = align(local, points, pose_, config_.icp.max_correspondence, &covariance, &goodness);
      // A correction odometry cannot have erred by since the last match is a slide, not a fix.
      const bool plausible = travel(aligned, pose_) <= kMaxSlide + kMaxSlidePerTravel * travel(odom_base, last_match_odom_);
      if (goodness >= kMinGoodness && plausible) {
        pose_ = aligned;
        covariance_ = covariance;
      }
      last_match_odom_ = odom_base;
      const core::Pose2& key = graph_.nodes().back();
      if (travel(pose_, key) >= config_.graph.keyframe_travel || turn(pose_, key) >= kKeyframeRotation) {
        addKeyframe(scan, points);
        const int k = static_cast<int>(keyframes_.size()) - 1;
        const core::Pose2 before = graph_.nodes()[static_cast<std::size_t>(k)];
        if (closeLoop(k)) pose_ = compose(graph_.nodes()[static_cast<std::size_t>(k)], compose(inverse(before), pose_));
      }
    }
  }
  const int key = static_cast<int>(keyframes_.size()) - 1;
  scans_.push_back({key, compose(inverse(graph_.nodes()[static_cast<std::size_t>(key)]), pose_)});
  estimate->pose = pose_;
  estimate->map_to_odom = compose(pose_, inverse(odom_base));
  estimate->covariance = covariance_;
  ++estimate->scans;
}

std::vector<core::Pose2> GraphMapper::trajectory() const {
  std::vector<core::Pose2> poses;
  poses.reserve(scans_.size());
  for (const ScanPose& s : scans_) poses.push_back(compose(graph_.nodes()[static_cast<std::size_t>(s.keyframe)], s.offset));
  return poses;
}

OccupancyMap GraphMapper::map() const {
  std::vector<const RangeScan*> scans;
  for (const Keyframe& k : keyframes_) scans.push_back(&k.scan);
  return drawMap(scans, graph_.nodes(), config_.resolution, config_.range_max);
}

}  // namespace localization
}  // namespace amigobot_tracking

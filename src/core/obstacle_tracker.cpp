#include "amigobot_tracking/core/obstacle_tracker.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace amigobot_tracking {
namespace core {

std::string ObstacleTrackerConfig::validate() const {
  std::ostringstream err;
  if (!(std::isfinite(gate) && gate > 0.0)) err << "gate must be > 0, got " << gate;
  else if (!(position_gain > 0.0 && position_gain <= 1.0)) err << "position_gain must be in (0, 1], got " << position_gain;
  else if (!(velocity_gain > 0.0 && velocity_gain < 2.0)) err << "velocity_gain must be in (0, 2), got " << velocity_gain;
  else if (!(std::isfinite(max_speed) && max_speed > 0.0)) err << "max_speed must be > 0, got " << max_speed;
  else if (!(std::isfinite(still_speed) && still_speed >= 0.0)) err << "still_speed must be >= 0, got " << still_speed;
  else if (!(std::isfinite(forget_after) && forget_after > 0.0)) err << "forget_after must be > 0, got " << forget_after;
  else if (min_hits < 1) err << "min_hits must be >= 1, got " << min_hits;
  return err.str();
}

ObstacleTracker::ObstacleTracker(const ObstacleTrackerConfig& config) : config_(config) {}

void ObstacleTracker::clear() {
  tracks_.clear();
  started_ = false;
}

void ObstacleTracker::update(double stamp, const std::vector<Disk>& detections) {
  if (!std::isfinite(stamp)) return;
  if (started_ && !(stamp > last_stamp_)) clear();
  started_ = true;
  last_stamp_ = stamp;

  // Candidate pairs within the gate, nearest first; each track and detection used once.
  struct Pair {
    double distance;
    size_t track, detection;
  };
  std::vector<Pair> pairs;
  std::vector<Eigen::Vector2d> predicted(tracks_.size());
  for (size_t i = 0; i < tracks_.size(); ++i) {
    predicted[i] = tracks_[i].disk.center + tracks_[i].disk.velocity * (stamp - tracks_[i].last_seen);
    for (size_t j = 0; j < detections.size(); ++j) {
      const double d = (detections[j].center - predicted[i]).norm();
      if (d <= config_.gate) pairs.push_back({d, i, j});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.distance < b.distance; });
  std::vector<bool> track_used(tracks_.size(), false), detection_used(detections.size(), false);
  for (const Pair& p : pairs) {
    if (track_used[p.track] || detection_used[p.detection]) continue;
    track_used[p.track] = detection_used[p.detection] = true;
    TrackedObstacle& track = tracks_[p.track];
    const double dt = stamp - track.last_seen;
    const Eigen::Vector2d residual = detections[p.detection].center - predicted[p.track];
    track.disk.center = predicted[p.track] + config_.position_gain * residual;
    track.disk.velocity += (config_.velocity_gain / dt) * residual;
    const double speed = track.disk.velocity.norm();
    if (speed > config_.max_speed) track.disk.velocity *= config_.max_speed / speed;
    track.disk.radius = detections[p.detection].radius;
    track.last_seen = stamp;
    ++track.hits;
  }
  // Unseen tracks coast until forgotten; unmatched detections start new tracks.
  std::vector<TrackedObstacle> kept;
  for (size_t i = 0; i < tracks_.size(); ++i) {
    if (stamp - tracks_[i].last_seen <= config_.forget_after) kept.push_back(tracks_[i]);
  }
  for (size_t j = 0; j < detections.size(); ++j) {
    if (detection_used[j] || !detections[j].center.allFinite() || !std::isfinite(detections[j].radius)) continue;
    TrackedObstacle track;
    track.id = next_id_++;
    track.disk = {detections[j].center, detections[j].radius, Eigen::Vector2d::Zero()};
    track.last_seen = stamp;
    track.hits = 1;
    kept.push_back(track);
  }
  tracks_ = std::move(kept);
}

Eigen::Vector2d ObstacleTracker::reportedVelocity(const TrackedObstacle& track) const {
  if (track.hits < config_.min_hits || track.disk.velocity.norm() < config_.still_speed) {
    return Eigen::Vector2d::Zero();
  }
  return track.disk.velocity;
}

std::vector<Disk> ObstacleTracker::obstaclesAt(double stamp) const {
  std::vector<Disk> out;
  out.reserve(tracks_.size());
  for (const TrackedObstacle& track : tracks_) {
    const Eigen::Vector2d velocity = reportedVelocity(track);
    out.push_back({track.disk.center + velocity * std::max(0.0, stamp - track.last_seen), track.disk.radius, velocity});
  }
  return out;
}

}  // namespace core
}  // namespace amigobot_tracking

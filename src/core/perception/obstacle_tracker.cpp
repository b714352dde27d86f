#include "amigobot_tracking/core/perception/obstacle_tracker.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace amigobot_tracking {
namespace core {

const FieldTable<ObstacleTrackerConfig>& obstacleTrackerFields() {
  using T = ObstacleTrackerConfig;
  static const FieldTable<T> table = {
      field("gate", &T::gate, "m",
            "largest distance between a track's predicted centre and a detection it is matched to (nearest pairs "
            "first)",
            positive()),
      field("position_gain", &T::position_gain, "-",
            "alpha of the alpha-beta filter, in (0, 1]: the share of the residual added to the predicted centre",
            interval(0, true, 1, false)),
      field("velocity_gain", &T::velocity_gain, "-",
            "beta of the alpha-beta filter, in (0, 2): the velocity gains beta x residual / time since last seen",
            interval(0, true, 2, true)),
      field("max_speed", &T::max_speed, "m/s", "track velocities are clamped to this", positive()),
      field("still_speed", &T::still_speed, "m/s", "slower tracks count as static (no velocity reported)",
            nonNegative()),
      field("forget_after", &T::forget_after, "s",
            "a track unseen this long is dropped (until then it coasts at its velocity)", duration()),
      field("min_hits", &T::min_hits, "-",
            "detections of a track, the first included, before its velocity is used (until then it is static)",
            atLeast(1)),
      field("walking_speed", &T::walking_speed, "m/s",
            "a track at least this fast is walking; when it then stands, the velocity it last walked at is "
            "reported as where it may walk on (resume_velocity; 0: never)",
            nonNegative()),
  };
  return table;
}

std::string ObstacleTrackerConfig::validate() const { return checkFields(obstacleTrackerFields(), *this); }

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
    // The walk's top speed in its latest direction: the filter's velocity decays through
    // walking_speed as a person stops, and that decay is not how they would walk on.
    const double now = track.disk.velocity.norm();
    if (config_.walking_speed > 0.0 && track.hits >= config_.min_hits && now >= config_.walking_speed) {
      const double top = track.walking ? std::max(now, track.walked.norm()) : now;
      track.walked = track.disk.velocity * (top / now);
      track.walking = true;
    } else {
      track.walking = false;
    }
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
    // Walking on: no memory needed. Standing after a walk: where it may go next.
    const Eigen::Vector2d resume = velocity.norm() > 0.0 ? Eigen::Vector2d::Zero() : track.walked;
    out.push_back({track.disk.center + velocity * std::max(0.0, stamp - track.last_seen), track.disk.radius, velocity,
                   resume});
  }
  return out;
}

}  // namespace core
}  // namespace amigobot_tracking

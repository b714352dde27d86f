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
      field("max_object_radius", &T::max_object_radius, "m",
            "an object (disks of one scan no farther apart than scan/cluster_tolerance) wider than this from its "
            "centre is static and not tracked: a wall, furniture, a person beside either",
            positive()),
  };
  return table;
}

std::string ObstacleTrackerConfig::validate() const { return checkFields(obstacleTrackerFields(), *this); }

ObstacleTracker::ObstacleTracker(const ObstacleTrackerConfig& config, double group_gap)
    : config_(config), group_gap_(group_gap) {}

void ObstacleTracker::clear() {
  tracks_.clear();
  static_.clear();
  started_ = false;
}

namespace {

// A scan's disks no farther apart than `gap` (transitively): one object.
struct SeenObject {
  // The middle of its disks' bounding box: where the scan cuts the object moves it less than it
  // moves the mean of the disks' centres (0.109 against 0.178 m/s of velocity error, a person).
  Eigen::Vector2d center;
  double extent;           // the farthest disk edge from it
  std::vector<Disk> parts;
  bool hidden = false;     // one of its clusters ends out of sight
};

// The scan's clusters that describe `detections` (each within it, in order); empty otherwise.
bool clustersFit(const std::vector<ScanCluster>* clusters, size_t detections) {
  if (!clusters) return false;
  size_t next = 0;
  for (const ScanCluster& c : *clusters) {
    if (c.first_disk < next || c.end_disk < c.first_disk || c.end_disk > detections) return false;
    next = c.end_disk;
  }
  return true;
}

std::vector<SeenObject> groupIntoObjects(const std::vector<Disk>& detections, double gap,
                                         const std::vector<ScanCluster>* clusters) {
  std::vector<size_t> root(detections.size());
  for (size_t i = 0; i < root.size(); ++i) root[i] = i;
  auto find = [&root](size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  auto join = [&](size_t i, size_t j) { root[find(j)] = find(i); };
  std::vector<bool> usable(detections.size());
  for (size_t i = 0; i < detections.size(); ++i)
    usable[i] = detections[i].center.allFinite() && std::isfinite(detections[i].radius);
  for (size_t i = 0; i < detections.size(); ++i) {
    if (!usable[i]) continue;
    for (size_t j = i + 1; j < detections.size(); ++j) {
      if (usable[j] && (detections[i].center - detections[j].center).norm() <=
                           detections[i].radius + detections[j].radius + gap)
        join(i, j);
    }
  }
  // A cluster's disks are one object, and so are clusters beside each other in the scan.
  std::vector<bool> hidden(detections.size(), false);
  const bool fit = clustersFit(clusters, detections.size());
  if (fit) {
    const std::vector<ScanCluster>& c = *clusters;
    for (size_t k = 0; k < c.size(); ++k) {
      if (c[k].first_disk == c[k].end_disk) continue;
      for (size_t i = c[k].first_disk + 1; i < c[k].end_disk; ++i) join(c[k].first_disk, i);
      const ScanCluster& next = c[(k + 1) % c.size()];
      if (c[k].end == ClusterEnd::kBeside && next.start == ClusterEnd::kBeside && next.first_disk < next.end_disk)
        join(c[k].first_disk, next.first_disk);
      if (c[k].start == ClusterEnd::kHidden || c[k].end == ClusterEnd::kHidden)
        for (size_t i = c[k].first_disk; i < c[k].end_disk; ++i) hidden[i] = true;
    }
  }
  std::vector<SeenObject> objects;
  std::vector<int> index(detections.size(), -1);
  for (size_t i = 0; i < detections.size(); ++i) {
    if (!usable[i]) continue;
    const size_t r = find(i);
    if (index[r] < 0) {
      index[r] = static_cast<int>(objects.size());
      objects.push_back({Eigen::Vector2d::Zero(), 0.0, {}});
    }
    objects[index[r]].parts.push_back(detections[i]);
    objects[index[r]].hidden = objects[index[r]].hidden || hidden[i];
  }
  for (SeenObject& o : objects) {
    Eigen::Vector2d low = o.parts[0].center, high = low;
    for (const Disk& d : o.parts) {
      low = low.cwiseMin(d.center - Eigen::Vector2d::Constant(d.radius));
      high = high.cwiseMax(d.center + Eigen::Vector2d::Constant(d.radius));
    }
    o.center = 0.5 * (low + high);
    for (const Disk& d : o.parts) o.extent = std::max(o.extent, (d.center - o.center).norm() + d.radius);
  }
  return objects;
}

}  // namespace

void ObstacleTracker::update(double stamp, const std::vector<Disk>& seen, const std::vector<ScanCluster>* clusters) {
  if (!std::isfinite(stamp)) return;
  if (started_ && !(stamp > last_stamp_)) clear();
  started_ = true;
  last_stamp_ = stamp;

  std::vector<SeenObject> detections;
  static_.clear();
  for (SeenObject& o : groupIntoObjects(seen, group_gap_, clusters)) {
    if (o.extent > config_.max_object_radius || o.hidden) {
      static_.insert(static_.end(), o.parts.begin(), o.parts.end());
    } else {
      detections.push_back(std::move(o));
    }
  }

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
    track.disk.radius = detections[p.detection].extent;
    track.parts = std::move(detections[p.detection].parts);
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
    if (stamp - tracks_[i].last_seen <= config_.forget_after) kept.push_back(std::move(tracks_[i]));
  }
  for (size_t j = 0; j < detections.size(); ++j) {
    if (detection_used[j]) continue;
    TrackedObstacle track;
    track.id = next_id_++;
    track.disk = {detections[j].center, detections[j].extent, Eigen::Vector2d::Zero()};
    track.parts = std::move(detections[j].parts);
    track.last_seen = stamp;
    track.hits = 1;
    kept.push_back(std::move(track));
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
  std::vector<Disk> out(static_);
  for (const TrackedObstacle& track : tracks_) {
    const Eigen::Vector2d velocity = reportedVelocity(track);
    // Walking on: no memory needed. Standing after a walk: where it may go next.
    const Eigen::Vector2d resume = velocity.norm() > 0.0 ? Eigen::Vector2d::Zero() : track.walked;
    const Eigen::Vector2d moved = velocity * std::max(0.0, stamp - track.last_seen);
    for (const Disk& part : track.parts) out.push_back({part.center + moved, part.radius, velocity, resume});
  }
  return out;
}

}  // namespace core
}  // namespace amigobot_tracking

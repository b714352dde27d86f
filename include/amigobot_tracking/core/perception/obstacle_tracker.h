// Velocity of detected obstacles by associating them across scans (beyond the paper).
//
// What is tracked is an object, not a disk: each scan's disks are first grouped into objects
// (disks whose gap is at most `group_gap`, the scan's cluster_tolerance: a cluster stays one
// object), because a laser cuts a person into several disks along the arc it sees and where
// it cuts moves as they walk; tracked one by one, those pieces slid along the arc and the
// pieces of a wall along the wall, up to max_speed (a wall piece beside a passing person's
// shadow reported 2 m/s). An object wider than `max_object_radius` (a wall, furniture) is
// static and not tracked. The objects are matched one-to-one to the tracks predicted to the
// scan's stamp (constant velocity), greedily by increasing distance within a gate, so two
// obstacles that cross keep their ids: a detection is never given to two tracks, and a track
// that finds no detection (e.g. the two blobs merged for a scan) coasts on its velocity until
// `forget_after`. With the scan's clusters (scan_obstacles.h), clusters that lie beside each
// other (adjacent returns at about one range) are one object too, and an object with a cluster
// end hidden (behind something nearer, or at the scan's edge) is static: where the view of it
// ends moves with the robot, not with the object. Matched tracks update their centre (the middle of their disks' bounding
// box) with an alpha-beta filter and carry the disks last seen. Velocities are reported only after
// `min_hits` matches and below `still_speed` they are zero, so static clutter (pillars that
// jitter between scans) stays static. A track that walked (at least `walking_speed`) and
// then stands reports the velocity it last walked at as its resume_velocity: a person who
// stopped may walk on that way at any moment.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "amigobot_tracking/core/perception/scan_obstacles.h"
#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

struct ObstacleTrackerConfig {
  double gate = 0.4;            // [m] largest distance between prediction and detection
  double position_gain = 0.6;   // alpha [-], (0, 1]
  double velocity_gain = 0.3;   // beta [-], (0, 2)
  double max_speed = 2.0;       // [m/s] velocities are clamped to this
  double still_speed = 0.05;    // [m/s] slower tracks report zero velocity
  double forget_after = 0.5;    // [s] a track unseen this long is dropped
  int min_hits = 3;             // matches before a velocity is reported
  double walking_speed = 0.25;  // [m/s] a track this fast walks; standing, it keeps that velocity (0: never)
  double max_object_radius = 0.5;  // [m] wider objects (walls, furniture) are static, not tracked

  std::string validate() const;  // empty when valid, else "key: reason" for the first bad field
};

// Its fields (ROS parameters under ~obstacle_tracker/).
const FieldTable<ObstacleTrackerConfig>& obstacleTrackerFields();

struct TrackedObstacle {
  std::uint32_t id = 0;
  Disk disk;                    // the filtered centre and velocity; radius: the object's extent from it
  std::vector<Disk> parts;      // the object's disks as last seen (at last_seen)
  Eigen::Vector2d walked = Eigen::Vector2d::Zero();  // [m/s] its last walk: top speed, latest direction
  bool walking = false;                              // at walking speed at its last match
  double last_seen = 0.0;       // [s]
  int hits = 0;
};

class ObstacleTracker {
 public:
  // group_gap [m]: disks this close are one object (the scan's cluster_tolerance).
  explicit ObstacleTracker(const ObstacleTrackerConfig& config = ObstacleTrackerConfig(), double group_gap = 0.1);

  // Feeds one scan's disks taken at `stamp` [s]; a stamp not after the last one resets the
  // tracker (time jumped back, e.g. a bag restarted). `clusters`, when given, are the scan's
  // clusters over `detections` as scanToObstacles made them (clusters out of range are ignored).
  void update(double stamp, const std::vector<Disk>& detections, const std::vector<ScanCluster>* clusters = nullptr);
  // The disks of the live tracks (coasting ones included), moved to `stamp`, with their
  // track's velocity as reported (zero until trusted), and the latest scan's static disks.
  std::vector<Disk> obstaclesAt(double stamp) const;
  const std::vector<TrackedObstacle>& tracks() const { return tracks_; }
  void clear();

 private:
  Eigen::Vector2d reportedVelocity(const TrackedObstacle& track) const;

  ObstacleTrackerConfig config_;
  double group_gap_;
  std::vector<TrackedObstacle> tracks_;
  std::vector<Disk> static_;  // the latest scan's disks of objects wider than max_object_radius or hidden
  double last_stamp_ = 0.0;
  bool started_ = false;
  std::uint32_t next_id_ = 1;
};

}  // namespace core
}  // namespace amigobot_tracking

// Laser scan -> disk obstacles for the repulsive term (10). Pure, Eigen only.
//
// Method (one pass over the beams, O(n), no allocation once `out` has capacity):
//  1. Beam filter, REP 117: a range is used only when it is finite and within
//     [range_min, range_max] of the scan (and not beyond max_range). NaN (no measurement),
//     +Inf (nothing within range_max) and -Inf (too close to measure: cannot be placed)
//     are dropped.
//  2. Clustering in scan order: a valid point joins the current cluster when it lies within
//     cluster_tolerance of the previous valid point, otherwise it starts a new cluster
//     (dropped beams in between do not break a cluster by themselves). Clusters with fewer
//     than min_cluster_points points are dropped.
//  3. Disks of bounded radius: each cluster is cut greedily, in scan order, into chunks
//     whose axis-aligned bounding box has a half-diagonal <= max_disk_radius. A chunk
//     becomes one disk centred on its box centre with the radius of the farthest point
//     (<= max_disk_radius, floored at min_disk_radius). A long wall becomes a row of disks
//     of about max_disk_radius, whatever the beam count.
//  4. Disk centres are mapped to the global frame with the sensor pose (a rigid 2-D map;
//     a laser mounted upside down is a reflection, which also keeps distances).
// Why: one disk per beam makes u_c grow with the number of beams (each beam adds a term);
// one disk per cluster lets a wall become a huge disk. Bounded disks make u_c depend on the
// geometry only: doubling the resolution moves chunk boundaries by one beam spacing.
// A disk covers its points; on a straight wall it bulges at most max_disk_radius towards
// the robot (conservative).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

struct ScanObstacleConfig {
  double cluster_tolerance = 0.10;  // [m] max gap between consecutive points of one cluster.
  double max_disk_radius = 0.10;    // [m] bound on every disk's radius.
  double min_disk_radius = 0.03;    // [m] radius of a one-point disk (and floor of all).
  int min_cluster_points = 1;       // [-] smaller clusters are noise (1 keeps thin legs).
  double max_range = 1e9;           // [m] beams farther than this are ignored (besides range_max).

  // Empty when valid, otherwise "key: reason" naming the first bad field.
  std::string validate() const;
};

// Its fields (ROS parameters under ~scan/).
const FieldTable<ScanObstacleConfig>& scanObstacleFields();

// The geometry of a sensor_msgs/LaserScan, without ROS.
struct ScanGeometry {
  double angle_min = 0.0;        // [rad] angle of the first beam in the sensor frame
  double angle_increment = 0.0;  // [rad] between beams (may be negative)
  double range_min = 0.0;        // [m]
  double range_max = 0.0;        // [m]

  // "" when usable (finite angles, 0 <= range_min < range_max, increment != 0), else
  // "field: reason, got value" naming the first bad field (the tracking node logs it).
  std::string problem() const;
  bool isValid() const { return problem().empty(); }
};

// Why the beams of a scan cannot be used, naming the field ("" when they can). The `count`
// beams from angle_min at angle_increment must end at angle_max within one increment (100,000
// ranges under a 270-degree header are not that laser's scan), sweep at most one turn, and at
// least one beam must be a reading: finite and >= range_min, or +inf (nothing within
// range_max). A scan of only NaN, -inf or negative ranges is a blind or covered laser, not an
// empty room: it must not refresh the scan's age. The geometry is checked first (problem()).
std::string scanBeamsProblem(const ScanGeometry& geometry, double angle_max, const float* ranges, std::size_t count);

// What the laser saw next beyond one end of a cluster (the nearest beam past it that is not NaN).
// Why: a cluster is only an object's outline where the object ends. Where something nearer hides
// the rest of it, where a wall seen at a grazing angle falls apart into pieces, or at the scan's
// edge, the cluster's end is where the view ends, and it moves as the robot moves: the tracker
// took such pieces for people walking at up to 1.9 m/s (test_tracker_on_scans).
enum class ClusterEnd : unsigned char {
  kOpen,    // a return farther by more than cluster_tolerance, or none (nothing within range): it ends here
  kHidden,  // a return nearer by more than cluster_tolerance, one too close to measure, or the scan's
            // edge: it may go on out of sight
  kBeside,  // a return at about its range (within cluster_tolerance): the next cluster, the same surface
};

// One cluster of a scan: its disks out[first_disk, end_disk) and how it ends on both sides.
struct ScanCluster {
  std::size_t first_disk = 0, end_disk = 0;
  std::size_t first_beam = 0, last_beam = 0;  // indices into the scan's ranges
  ClusterEnd start = ClusterEnd::kHidden;     // before first_beam, in scan order
  ClusterEnd end = ClusterEnd::kHidden;       // after last_beam
};

struct ScanObstacleStats {
  std::size_t valid_beams = 0;
  std::size_t clusters = 0;
  std::size_t disks = 0;
};

// Appends the disks of one scan, in the frame of `sensor_to_global`, to *out (cleared
// first), and with `clusters` the scan's clusters in scan order (cleared first). A scan that
// sweeps a whole turn wraps: its first beam is next to its last. Returns false (and leaves
// both empty) when the geometry is invalid.
bool scanToObstacles(const ScanGeometry& geometry, const float* ranges, std::size_t count,
                     const Eigen::Affine2d& sensor_to_global, const ScanObstacleConfig& config,
                     std::vector<Disk>* out, ScanObstacleStats* stats = nullptr,
                     std::vector<ScanCluster>* clusters = nullptr);

inline bool scanToObstacles(const ScanGeometry& geometry, const std::vector<float>& ranges,
                            const Eigen::Affine2d& sensor_to_global, const ScanObstacleConfig& config,
                            std::vector<Disk>* out, ScanObstacleStats* stats = nullptr,
                            std::vector<ScanCluster>* clusters = nullptr) {
  return scanToObstacles(geometry, ranges.data(), ranges.size(), sensor_to_global, config, out, stats, clusters);
}

// Removes the disks whose centre lies within `radius` of `point` (the followed robot seen
// by the laser is the target, not an obstacle). radius <= 0 removes nothing.
void dropDisksNear(const Eigen::Vector2d& point, double radius, std::vector<Disk>* disks);

}  // namespace core
}  // namespace amigobot_tracking

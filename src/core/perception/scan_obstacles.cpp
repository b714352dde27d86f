#include "amigobot_tracking/core/perception/scan_obstacles.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace amigobot_tracking {
namespace core {
namespace {

// Axis-aligned bounding box of the points of one chunk (in the sensor frame).
struct Box {
  double min_x, max_x, min_y, max_y;

  explicit Box(const Eigen::Vector2d& p) : min_x(p.x()), max_x(p.x()), min_y(p.y()), max_y(p.y()) {}
  double halfDiagonalWith(const Eigen::Vector2d& p) const {
    return 0.5 * std::hypot(std::max(max_x, p.x()) - std::min(min_x, p.x()),
                            std::max(max_y, p.y()) - std::min(min_y, p.y()));
  }
  void add(const Eigen::Vector2d& p) {
    min_x = std::min(min_x, p.x());
    max_x = std::max(max_x, p.x());
    min_y = std::min(min_y, p.y());
    max_y = std::max(max_y, p.y());
  }
  Eigen::Vector2d center() const { return {0.5 * (min_x + max_x), 0.5 * (min_y + max_y)}; }
  double halfDiagonal() const { return 0.5 * std::hypot(max_x - min_x, max_y - min_y); }
};

// How a cluster whose end point is at range `r` ends where the next beam reads `beam`; false
// for a NaN beam, which says nothing (look further).
bool beamEnds(double beam, double r, double range_min, double far, double tolerance, ClusterEnd* end) {
  if (std::isnan(beam)) return false;
  if (beam < range_min) {  // -inf, negative: something too close to measure
    *end = ClusterEnd::kHidden;
  } else if (beam > far) {  // +inf: nothing within range; or ignored as too far
    *end = ClusterEnd::kOpen;
  } else if (beam < r - tolerance) {
    *end = ClusterEnd::kHidden;
  } else if (beam > r + tolerance) {
    *end = ClusterEnd::kOpen;
  } else {
    *end = ClusterEnd::kBeside;
  }
  return true;
}

// How the cluster ending at beam `from` ends in direction `step` (+1, -1): the first beam past
// it that is not NaN decides; past the scan's edge it is hidden, unless the scan is a whole
// turn and wraps.
ClusterEnd clusterEnd(const float* ranges, std::size_t count, std::size_t from, int step, bool wraps,
                      double range_min, double far, double tolerance) {
  const double r = ranges[from];
  std::size_t j = from;
  for (std::size_t seen = 1; seen < count; ++seen) {
    if (step > 0) {
      if (j + 1 == count && !wraps) break;
      j = j + 1 == count ? 0 : j + 1;
    } else {
      if (j == 0 && !wraps) break;
      j = j == 0 ? count - 1 : j - 1;
    }
    ClusterEnd end;
    if (beamEnds(ranges[j], r, range_min, far, tolerance, &end)) return end;
  }
  return ClusterEnd::kHidden;
}

}  // namespace

const FieldTable<ScanObstacleConfig>& scanObstacleFields() {
  using S = ScanObstacleConfig;
  static const FieldTable<S> table = {
      field("cluster_tolerance", &S::cluster_tolerance, "m",
            "max gap between consecutive points (in scan order) of one cluster", positive()),
      field("max_disk_radius", &S::max_disk_radius, "m",
            "bound on each obstacle disk's radius: a cluster is cut into disks no larger, so a wall becomes a row "
            "of disks and u_c does not grow with the beam count",
            boundedRadius()),
      field("min_disk_radius", &S::min_disk_radius, "m",
            "radius of a one-point disk, floor of all disks (<= max_disk_radius)", boundedRadius()),
      field("min_cluster_points", &S::min_cluster_points, "-",
            "clusters of fewer points are dropped as noise (1 keeps thin table legs)", atLeast(1)),
      // +inf allowed: no limit besides the scan's range_max.
      field("max_range", &S::max_range, "m",
            "beams farther than this are ignored, besides the scan's range_max (in YAML write 1.0e+9: YAML 1.1 "
            "reads 1.0e9 as a string)",
            allowInfinite(positive())),
  };
  return table;
}

std::string ScanObstacleConfig::validate() const {
  const std::string bad = checkFields(scanObstacleFields(), *this);
  if (!bad.empty()) return bad;
  std::ostringstream err;
  if (min_disk_radius > max_disk_radius)
    err << "min_disk_radius: must be <= max_disk_radius = " << max_disk_radius << ", got " << min_disk_radius;
  return err.str();
}

std::string ScanGeometry::problem() const {
  std::ostringstream err;
  if (!std::isfinite(angle_min)) {
    err << "angle_min: must be finite, got " << angle_min;
  } else if (!(std::isfinite(angle_increment) && angle_increment != 0.0)) {
    err << "angle_increment: must be finite and non-zero, got " << angle_increment;
  } else if (!(std::isfinite(range_min) && range_min >= 0.0)) {
    err << "range_min: must be a finite number >= 0, got " << range_min;
  } else if (!(std::isfinite(range_max) && range_max > range_min)) {
    err << "range_max: must be finite and > range_min = " << range_min << ", got " << range_max;
  }
  return err.str();
}

std::string scanBeamsProblem(const ScanGeometry& geometry, double angle_max, const float* ranges, std::size_t count) {
  std::string bad = geometry.problem();
  if (!bad.empty()) return bad;
  std::ostringstream err;
  if (count == 0 || ranges == nullptr) {
    err << "ranges: empty";
    return err.str();
  }
  const double step = std::abs(geometry.angle_increment);
  const double last = geometry.angle_min + geometry.angle_increment * static_cast<double>(count - 1);
  // One increment of slack: drivers differ on whether angle_max is the last beam or one past it.
  if (!(std::isfinite(angle_max) && std::abs(last - angle_max) <= step + 1e-6)) {
    err << "ranges: " << count << " beams from angle_min " << geometry.angle_min << " at angle_increment "
        << geometry.angle_increment << " end at " << last << ", not at angle_max " << angle_max;
    return err.str();
  }
  if (std::abs(last - geometry.angle_min) > 2.0 * M_PI + step) {
    err << "angle_max: the scan sweeps " << std::abs(last - geometry.angle_min) << " rad, more than one turn";
    return err.str();
  }
  std::size_t nan = 0, too_close = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const float r = ranges[i];
    if (std::isnan(r)) {
      ++nan;
    } else if (r < geometry.range_min) {  // -inf and negative ranges included
      ++too_close;
    } else {
      return "";  // a reading (+inf: nothing within range_max)
    }
  }
  err << "ranges: none of the " << count << " beams is a reading (" << nan << " NaN, " << too_close
      << " below range_min " << geometry.range_min << " or negative)";
  return err.str();
}

bool scanToObstacles(const ScanGeometry& geometry, const float* ranges, std::size_t count,
                     const Eigen::Affine2d& sensor_to_global, const ScanObstacleConfig& config,
                     std::vector<Disk>* out, ScanObstacleStats* stats, std::vector<ScanCluster>* clusters) {
  out->clear();
  if (clusters) clusters->clear();
  ScanObstacleStats local;
  ScanObstacleStats& s = stats ? *stats : local;
  s = ScanObstacleStats();
  if (!geometry.isValid() || (count > 0 && ranges == nullptr)) return false;

  const double far = std::min(static_cast<double>(geometry.range_max), config.max_range);
  // Beam directions by rotation recurrence: no sin/cos per beam (the benchmark's budget).
  const double step_c = std::cos(geometry.angle_increment), step_s = std::sin(geometry.angle_increment);
  double c = std::cos(geometry.angle_min), sn = std::sin(geometry.angle_min);

  bool in_cluster = false;
  std::size_t cluster_points = 0, cluster_first_disk = 0, cluster_first_beam = 0, previous_beam = 0;
  Eigen::Vector2d previous = Eigen::Vector2d::Zero();
  Box box(previous);

  auto emit = [&](const Box& chunk) {
    out->push_back({sensor_to_global * chunk.center(), std::max(chunk.halfDiagonal(), config.min_disk_radius)});
  };
  auto close_cluster = [&]() {
    emit(box);
    if (static_cast<int>(cluster_points) < config.min_cluster_points) {
      out->resize(cluster_first_disk);  // too small: noise
    } else {
      ++s.clusters;
      if (clusters) {
        ScanCluster cluster;
        cluster.first_disk = cluster_first_disk;
        cluster.end_disk = out->size();
        cluster.first_beam = cluster_first_beam;
        cluster.last_beam = previous_beam;
        clusters->push_back(cluster);
      }
    }
  };

  for (std::size_t i = 0; i < count; ++i) {
    const double r = ranges[i];
    const Eigen::Vector2d p(r * c, r * sn);
    const double next_c = c * step_c - sn * step_s;
    sn = sn * step_c + c * step_s;
    c = next_c;
    // REP 117: NaN, +-Inf and out-of-range readings carry no usable point.
    if (!(std::isfinite(r) && r >= geometry.range_min && r <= far)) continue;
    ++s.valid_beams;
    if (in_cluster && (p - previous).norm() <= config.cluster_tolerance) {
      ++cluster_points;
      if (box.halfDiagonalWith(p) > config.max_disk_radius) {
        emit(box);
        box = Box(p);
      } else {
        box.add(p);
      }
    } else {
      if (in_cluster) close_cluster();
      in_cluster = true;
      cluster_points = 1;
      cluster_first_disk = out->size();
      cluster_first_beam = i;
      box = Box(p);
    }
    previous = p;
    previous_beam = i;
  }
  if (in_cluster) close_cluster();
  s.disks = out->size();
  if (clusters) {
    // A whole turn (within half a beam): the first beam is next to the last.
    const bool wraps = std::abs(geometry.angle_increment) * static_cast<double>(count) >=
                       2.0 * M_PI - 0.5 * std::abs(geometry.angle_increment);
    for (ScanCluster& cluster : *clusters) {
      cluster.start = clusterEnd(ranges, count, cluster.first_beam, -1, wraps, geometry.range_min, far,
                                 config.cluster_tolerance);
      cluster.end = clusterEnd(ranges, count, cluster.last_beam, +1, wraps, geometry.range_min, far,
                               config.cluster_tolerance);
    }
  }
  return true;
}

void dropDisksNear(const Eigen::Vector2d& point, double radius, std::vector<Disk>* disks) {
  if (!(radius > 0.0)) return;
  disks->erase(std::remove_if(disks->begin(), disks->end(),
                              [&](const Disk& d) { return (d.center - point).norm() <= radius; }),
               disks->end());
}

}  // namespace core
}  // namespace amigobot_tracking

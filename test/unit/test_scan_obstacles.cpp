// Laser scan -> bounded disks (core/perception/scan_obstacles.h) on synthetic scans.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "amigobot_tracking/core/law/avoidance.h"
#include "amigobot_tracking/core/perception/scan_obstacles.h"

using namespace amigobot_tracking::core;

namespace {

struct Scan {
  ScanGeometry geometry;
  std::vector<float> ranges;
};

// Ray from the sensor origin along `angle`: distance to the first surface, +inf when none.
using World = std::function<double(double angle)>;

double rayToLineX(double angle, double x_wall) {  // wall x = x_wall, infinite in y
  const double c = std::cos(angle);
  return c > 1e-9 ? x_wall / c : std::numeric_limits<double>::infinity();
}

double rayToCircle(double angle, const Eigen::Vector2d& center, double radius) {
  const Eigen::Vector2d d(std::cos(angle), std::sin(angle));
  const double b = d.dot(center), disc = b * b - (center.squaredNorm() - radius * radius);
  if (disc < 0.0 || b - std::sqrt(disc) <= 0.0) return std::numeric_limits<double>::infinity();
  return b - std::sqrt(disc);
}

// A scan of `beams` beams over [angle_min, angle_max], as a driver fills it (REP 117:
// +inf when nothing is within range_max).
Scan makeScan(int beams, double angle_min, double angle_max, const World& world, double range_max = 10.0) {
  Scan scan;
  scan.geometry = {angle_min, (angle_max - angle_min) / (beams - 1), 0.05, range_max};
  for (int i = 0; i < beams; ++i) {
    const double r = world(angle_min + i * scan.geometry.angle_increment);
    scan.ranges.push_back(r <= range_max ? static_cast<float>(r) : std::numeric_limits<float>::infinity());
  }
  return scan;
}

std::vector<Disk> extract(const Scan& scan, const ScanObstacleConfig& config = {},
                          const Eigen::Affine2d& pose = Eigen::Affine2d::Identity(),
                          ScanObstacleStats* stats = nullptr) {
  std::vector<Disk> disks;
  EXPECT_TRUE(scanToObstacles(scan.geometry, scan.ranges, pose, config, &disks, stats));
  return disks;
}

// Every usable beam's point lies inside at least one disk.
void expectCovered(const Scan& scan, const std::vector<Disk>& disks, const Eigen::Affine2d& pose) {
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double r = scan.ranges[i];
    if (!std::isfinite(r) || r < scan.geometry.range_min || r > scan.geometry.range_max) continue;
    const double a = scan.geometry.angle_min + i * scan.geometry.angle_increment;
    const Eigen::Vector2d p = pose * Eigen::Vector2d(r * std::cos(a), r * std::sin(a));
    bool covered = false;
    for (const Disk& d : disks) covered = covered || (p - d.center).norm() <= d.radius + 1e-6;
    EXPECT_TRUE(covered) << "beam " << i << " at (" << p.transpose() << ") is in no disk";
  }
}

const World kWall = [](double a) { return rayToLineX(a, 1.0); };

}  // namespace

TEST(ScanObstacles, WallBecomesARowOfBoundedDisks) {
  const ScanObstacleConfig config;
  const Scan scan = makeScan(720, -M_PI / 3, M_PI / 3, kWall);  // wall x = 1 from y = -1.73 to 1.73
  ScanObstacleStats stats;
  const std::vector<Disk> disks = extract(scan, config, Eigen::Affine2d::Identity(), &stats);
  EXPECT_EQ(stats.clusters, 1u);
  EXPECT_EQ(stats.valid_beams, 720u);
  const double length = 2.0 * std::sqrt(3.0);
  // Greedy chunks of at most 2 max_disk_radius, each at least half of that (otherwise the
  // next point would have fitted): between L / (2 r_max) and twice that.
  EXPECT_GE(disks.size(), static_cast<std::size_t>(length / (2 * config.max_disk_radius)));
  EXPECT_LE(disks.size(), static_cast<std::size_t>(2 * length / (2 * config.max_disk_radius) + 2));
  for (const Disk& d : disks) {
    EXPECT_LE(d.radius, config.max_disk_radius + 1e-12);
    EXPECT_GE(d.radius, config.min_disk_radius);
    EXPECT_NEAR(d.center.x(), 1.0, 1e-5);  // chords of a straight wall stay on it (float ranges)
  }
  expectCovered(scan, disks, Eigen::Affine2d::Identity());
}

TEST(ScanObstacles, DisksOfCylindersStayInsideTheirBoundingDisk) {
  const Eigen::Vector2d a(2.0, 0.3), b(-0.5, 1.5);
  const World world = [&](double angle) { return std::min(rayToCircle(angle, a, 0.25), rayToCircle(angle, b, 0.05)); };
  const ScanObstacleConfig config;
  const Scan scan = makeScan(720, -M_PI, M_PI, world);
  ScanObstacleStats stats;
  const std::vector<Disk> disks = extract(scan, config, Eigen::Affine2d::Identity(), &stats);
  EXPECT_EQ(stats.clusters, 2u);
  ASSERT_GE(disks.size(), 2u);
  for (const Disk& d : disks) {
    const double to_a = (d.center - a).norm(), to_b = (d.center - b).norm();
    // Each disk belongs to one cylinder and does not reach beyond its far side.
    EXPECT_TRUE(to_a + d.radius <= 0.25 + config.max_disk_radius + 1e-9 ||
                to_b + d.radius <= 0.05 + config.min_disk_radius + 1e-9)
        << d.center.transpose() << " r " << d.radius;
    EXPECT_LE(d.radius, config.max_disk_radius + 1e-12);
  }
  expectCovered(scan, disks, Eigen::Affine2d::Identity());
}

TEST(ScanObstacles, Rep117ReadingsCarryNoPoint) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  Scan scan = makeScan(8, -0.5, 0.5, kWall);
  scan.ranges = {nan, inf, -inf, 0.01f /* < range_min */, 12.0f /* > range_max */, nan, inf, -inf};
  ScanObstacleStats stats;
  EXPECT_TRUE(extract(scan, {}, Eigen::Affine2d::Identity(), &stats).empty());
  EXPECT_EQ(stats.valid_beams, 0u);
}

TEST(ScanObstacles, InvalidBeamsInsideAWallDoNotSplitIt) {
  const Scan clean = makeScan(720, -M_PI / 3, M_PI / 3, kWall);
  Scan holes = clean;
  const float bad[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                       -std::numeric_limits<float>::infinity(), 0.0f, 99.0f};
  for (std::size_t i = 1; i < holes.ranges.size(); i += 2) holes.ranges[i] = bad[(i / 2) % 5];
  ScanObstacleStats stats;
  const std::vector<Disk> disks = extract(holes, {}, Eigen::Affine2d::Identity(), &stats);
  EXPECT_EQ(stats.clusters, 1u);
  EXPECT_EQ(stats.valid_beams, 360u);
  for (const Disk& d : disks) EXPECT_TRUE(d.center.allFinite() && std::isfinite(d.radius));
  expectCovered(holes, disks, Eigen::Affine2d::Identity());
}

TEST(ScanObstacles, DoubledResolutionGivesTheSameRepulsiveTerm) {
  // The offset point 0.6 m from the wall, effective radius 0.48, delta 0.25: several disks
  // are detected. One disk per beam would double u_c; bounded disks keep it.
  const Eigen::Vector2d p_r(0.4, 0.1), heading(1.0, 0.0);
  const double radius = 0.48, delta = 0.25;
  for (const double fov : {M_PI / 3, M_PI / 2}) {
    const std::vector<Disk> coarse = extract(makeScan(360, -fov, fov, kWall));
    const std::vector<Disk> fine = extract(makeScan(720, -fov, fov, kWall));
    const std::vector<Disk> finer = extract(makeScan(1440, -fov, fov, kWall));
    const AvoidanceResult a = repulsiveTerm(p_r, coarse, radius, delta, heading);
    const AvoidanceResult b = repulsiveTerm(p_r, fine, radius, delta, heading);
    const AvoidanceResult c = repulsiveTerm(p_r, finer, radius, delta, heading);
    ASSERT_GT(b.detected, 1);
    ASSERT_GT(b.u_c.norm(), 0.0);
    EXPECT_LT(b.u_c.x(), 0.0);  // pushes away from the wall
    EXPECT_NEAR(a.u_c.norm() / b.u_c.norm(), 1.0, 0.15);
    EXPECT_NEAR(c.u_c.norm() / b.u_c.norm(), 1.0, 0.15);
    EXPECT_LT(std::abs(a.u_c.normalized().dot(Eigen::Vector2d(0.0, 1.0))), 0.2);
    EXPECT_NEAR(c.min_clearance, b.min_clearance, 0.02);
  }
}

TEST(ScanObstacles, CentresFollowTheSensorPoseIncludingAnUpsideDownMount) {
  const Scan scan = makeScan(720, -M_PI / 3, M_PI / 3, kWall);
  const std::vector<Disk> local = extract(scan);
  Eigen::Affine2d pose = Eigen::Translation2d(3.0, -1.0) * Eigen::Rotation2Dd(0.7);
  Eigen::Affine2d flipped = Eigen::Affine2d::Identity();
  flipped.linear() << 1.0, 0.0, 0.0, -1.0;  // laser upside down: y mirrored
  for (const Eigen::Affine2d& t : {pose, Eigen::Affine2d(pose * flipped)}) {
    const std::vector<Disk> global = extract(scan, {}, t);
    ASSERT_EQ(global.size(), local.size());
    for (std::size_t i = 0; i < local.size(); ++i) {
      EXPECT_LT((global[i].center - t * local[i].center).norm(), 1e-9);
      EXPECT_DOUBLE_EQ(global[i].radius, local[i].radius);
    }
    expectCovered(scan, global, t);
  }
}

TEST(ScanObstacles, SmallClustersAreDroppedOnlyWhenAsked) {
  Scan scan = makeScan(720, -M_PI / 3, M_PI / 3, kWall);
  for (float& r : scan.ranges) r = std::numeric_limits<float>::infinity();
  scan.ranges[100] = 2.0f;  // one isolated return
  ScanObstacleConfig config;
  ASSERT_EQ(extract(scan, config).size(), 1u);
  EXPECT_DOUBLE_EQ(extract(scan, config)[0].radius, config.min_disk_radius);
  config.min_cluster_points = 2;
  EXPECT_TRUE(extract(scan, config).empty());
}

TEST(ScanObstacles, MaxRangeIgnoresFarPoints) {
  const Scan scan = makeScan(720, -M_PI / 3, M_PI / 3, kWall);
  ScanObstacleConfig config;
  config.max_range = 1.5;  // the wall is 1 m ahead, 2 m at the edges of the fan
  ScanObstacleStats stats;
  for (const Disk& d : extract(scan, config, Eigen::Affine2d::Identity(), &stats)) {
    EXPECT_LE(d.center.norm(), 1.5 + 1e-9);
  }
  EXPECT_LT(stats.valid_beams, 720u);
  EXPECT_GT(stats.valid_beams, 0u);
}

TEST(ScanObstacles, InvalidGeometryIsRefused) {
  Scan scan = makeScan(10, -0.5, 0.5, kWall);
  std::vector<Disk> disks{{}};
  for (auto spoil : std::vector<std::function<void(ScanGeometry&)>>{
           [](ScanGeometry& g) { g.angle_increment = 0.0; },
           [](ScanGeometry& g) { g.angle_min = std::numeric_limits<double>::quiet_NaN(); },
           [](ScanGeometry& g) { g.range_max = g.range_min; },
           [](ScanGeometry& g) { g.range_min = -1.0; }}) {
    ScanGeometry g = scan.geometry;
    spoil(g);
    EXPECT_FALSE(scanToObstacles(g, scan.ranges, Eigen::Affine2d::Identity(), {}, &disks));
    EXPECT_TRUE(disks.empty());
  }
}

// The tracking node logs these reasons: each must name the field of sensor_msgs/LaserScan.
TEST(ScanObstacles, InvalidGeometryNamesTheField) {
  const Scan scan = makeScan(10, -0.5, 0.5, kWall);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto problemWith = [&](const std::function<void(ScanGeometry&)>& spoil) {
    ScanGeometry g = scan.geometry;
    spoil(g);
    return g.problem();
  };
  EXPECT_EQ(scan.geometry.problem(), "");
  EXPECT_EQ(problemWith([&](ScanGeometry& g) { g.angle_min = nan; }), "angle_min: must be finite, got nan");
  EXPECT_EQ(problemWith([](ScanGeometry& g) { g.angle_increment = 0.0; }),
            "angle_increment: must be finite and non-zero, got 0");
  EXPECT_EQ(problemWith([](ScanGeometry& g) { g.range_min = -1.0; }), "range_min: must be a finite number >= 0, got -1");
  EXPECT_EQ(problemWith([](ScanGeometry& g) { g.range_min = 20.0; }),
            "range_max: must be finite and > range_min = 20, got 10");
}

TEST(ScanObstacles, BeamsThatCannotBeUsedAreNamed) {
  const Scan scan = makeScan(10, -0.5, 0.5, kWall);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  auto problemOf = [&](const std::vector<float>& ranges, double angle_max = 0.5) {
    return scanBeamsProblem(scan.geometry, angle_max, ranges.data(), ranges.size());
  };
  EXPECT_EQ(problemOf(scan.ranges), "");
  EXPECT_EQ(problemOf(scan.ranges, 0.5 + scan.geometry.angle_increment), "") << "angle_max one past the last beam";
  EXPECT_EQ(problemOf({}), "ranges: empty");
  // 100,000 ranges under the 10-beam header: the array is not this scan's.
  const std::string many = problemOf(std::vector<float>(100000, 1.0f));
  EXPECT_EQ(many.rfind("ranges: 100000 beams from angle_min -0.5", 0), 0u) << many;
  EXPECT_NE(many.find("not at angle_max 0.5"), std::string::npos) << many;
  // 100,000 beams over one turn are a (fine) scan; two turns are not.
  ScanGeometry fine = scan.geometry;
  fine.angle_min = -M_PI;
  fine.angle_increment = 2.0 * M_PI / 99999.0;
  const std::vector<float> lots(100000, inf);
  EXPECT_EQ(scanBeamsProblem(fine, M_PI, lots.data(), lots.size()), "");
  fine.angle_increment *= 2.0;
  EXPECT_EQ(scanBeamsProblem(fine, 3.0 * M_PI, lots.data(), lots.size()).rfind("angle_max: the scan sweeps", 0), 0u);
  // All NaN / negative / -inf: a blind laser. +inf alone is an empty room; one reading is enough.
  EXPECT_EQ(problemOf(std::vector<float>(10, nan)),
            "ranges: none of the 10 beams is a reading (10 NaN, 0 below range_min 0.05 or negative)");
  EXPECT_EQ(problemOf({nan, -1.0f, -inf, 0.01f, nan, nan, -2.0f, nan, nan, nan}),
            "ranges: none of the 10 beams is a reading (6 NaN, 4 below range_min 0.05 or negative)");
  EXPECT_EQ(problemOf(std::vector<float>(10, inf)), "");
  EXPECT_EQ(problemOf({nan, -1.0f, -inf, 0.01f, nan, 2.0f, -2.0f, nan, nan, nan}), "");
  ScanGeometry flat = scan.geometry;
  flat.angle_increment = 0.0;
  EXPECT_EQ(scanBeamsProblem(flat, 0.5, scan.ranges.data(), scan.ranges.size()).rfind("angle_increment:", 0), 0u)
      << "the geometry first";
}

TEST(ScanObstacles, ConfigValidationNamesTheField) {
  const ScanObstacleConfig good;
  EXPECT_EQ(good.validate(), "");
  auto first_word = [](ScanObstacleConfig c) { return c.validate().substr(0, c.validate().find(':')); };
  ScanObstacleConfig c = good;
  c.cluster_tolerance = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(first_word(c), "cluster_tolerance");
  c = good;
  c.max_disk_radius = -1.0;
  EXPECT_EQ(first_word(c), "max_disk_radius");
  c = good;
  c.max_disk_radius = 1e308;  // upper bound: 100 m
  EXPECT_EQ(first_word(c), "max_disk_radius");
  c = good;
  c.min_disk_radius = 0.5;  // above max_disk_radius
  EXPECT_EQ(first_word(c), "min_disk_radius");
  c = good;
  c.min_cluster_points = 0;
  EXPECT_EQ(first_word(c), "min_cluster_points");
  c = good;
  c.max_range = 0.0;
  EXPECT_EQ(first_word(c), "max_range");
}

TEST(ScanObstacles, DisksOnTheFollowedRobotAreDropped) {
  std::vector<Disk> disks = {{{1.0, 1.0}, 0.1}, {{1.2, 1.1}, 0.1}, {{2.0, 1.0}, 0.1}};
  dropDisksNear({1.0, 1.0}, 0.0, &disks);  // off
  EXPECT_EQ(disks.size(), 3u);
  dropDisksNear({1.0, 1.0}, 0.3, &disks);
  ASSERT_EQ(disks.size(), 1u);
  EXPECT_EQ(disks[0].center, Eigen::Vector2d(2.0, 1.0));
}

// How each cluster ends: a pole in front of a wall ends against the farther wall on both sides
// (open); the wall's pieces beside its shadow end against the nearer pole (hidden), and at the
// edges of a 120-degree scan (hidden: the wall goes on out of view).
TEST(ScanObstacles, ClusterEndsSayWhetherTheObjectEndsOrTheViewDoes) {
  const Eigen::Vector2d pole(1.0, 0.0);
  const Scan scan = makeScan(720, -M_PI / 3, M_PI / 3, [&](double a) {
    return std::min(rayToLineX(a, 2.0), rayToCircle(a, pole, 0.15));
  });
  std::vector<Disk> disks;
  std::vector<ScanCluster> clusters;
  ASSERT_TRUE(scanToObstacles(scan.geometry, scan.ranges, Eigen::Affine2d::Identity(), {}, &disks, nullptr, &clusters));
  ASSERT_EQ(clusters.size(), 3u);  // wall, pole, wall
  EXPECT_EQ(clusters[0].start, ClusterEnd::kHidden);
  EXPECT_EQ(clusters[0].end, ClusterEnd::kHidden);
  EXPECT_EQ(clusters[1].start, ClusterEnd::kOpen);
  EXPECT_EQ(clusters[1].end, ClusterEnd::kOpen);
  EXPECT_EQ(clusters[2].start, ClusterEnd::kHidden);
  EXPECT_EQ(clusters[2].end, ClusterEnd::kHidden);
  EXPECT_EQ(clusters[1].first_disk, clusters[0].end_disk);
  EXPECT_EQ(clusters[2].end_disk, disks.size());
  for (std::size_t i = clusters[1].first_disk; i < clusters[1].end_disk; ++i)
    EXPECT_LT((disks[i].center - pole).norm(), 0.16);
}

// A wall seen at a grazing angle falls apart into pieces (gaps above cluster_tolerance): each
// piece's near end is hidden by the piece before it. Beams too close to measure hide; beams
// with nothing in range open; NaN beams are looked past.
TEST(ScanObstacles, GrazingWallPiecesAndUnusableBeamsEndAsTheyShould) {
  // Wall y = 0.3 beside the sensor, seen from 60 to 2 degrees: points 0.1 m apart beyond ~5 m.
  const Scan grazing = makeScan(100, 2.0 * M_PI / 180.0, M_PI / 3.0, [](double a) { return 0.3 / std::sin(a); }, 20.0);
  std::vector<Disk> disks;
  std::vector<ScanCluster> clusters;
  ASSERT_TRUE(scanToObstacles(grazing.geometry, grazing.ranges, Eigen::Affine2d::Identity(), {}, &disks, nullptr,
                              &clusters));
  ASSERT_GT(clusters.size(), 3u);
  std::size_t hidden = 0;
  for (std::size_t k = 0; k + 1 < clusters.size(); ++k) {  // scan order: from far to near
    EXPECT_NE(clusters[k].end, ClusterEnd::kOpen) << "piece " << k;  // beside: joined to the next
    hidden += clusters[k].end == ClusterEnd::kHidden;
  }
  EXPECT_GE(hidden, clusters.size() / 2);
  ScanGeometry g{0.0, 0.01, 0.05, 10.0};
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const std::vector<float> ranges = {-inf, nan, 1.0f, 1.0f, nan, inf, 2.0f, 2.0f, 2.0f, nan, 1.95f, 1.95f, 0.01f};
  ASSERT_TRUE(scanToObstacles(g, ranges, Eigen::Affine2d::Identity(), {}, &disks, nullptr, &clusters));
  ASSERT_EQ(clusters.size(), 2u);  // 1 m at beams 2-3; 2 m at beams 6-8 and 10-11 (0.05 m apart: one)
  EXPECT_EQ(clusters[0].start, ClusterEnd::kHidden);  // -inf, past a NaN
  EXPECT_EQ(clusters[0].end, ClusterEnd::kOpen);      // +inf, past a NaN
  EXPECT_EQ(clusters[1].start, ClusterEnd::kOpen);
  EXPECT_EQ(clusters[1].end, ClusterEnd::kHidden);    // 0.01 m: below range_min
}

// A 360-degree scan wraps: a wall in front ends open on both sides (nothing in range beyond it);
// a wall behind, across the first and last beams, is cut by the seam into two clusters that end
// beside each other there.
TEST(ScanObstacles, AWholeTurnWrapsAtItsSeam) {
  const int beams = 360;
  Scan scan = makeScan(beams, -M_PI, M_PI - 2.0 * M_PI / beams, [](double a) {
    return std::cos(a) > 0.7 ? 1.0 / std::cos(a) : std::numeric_limits<double>::infinity();
  });
  std::vector<Disk> disks;
  std::vector<ScanCluster> clusters;
  ASSERT_TRUE(scanToObstacles(scan.geometry, scan.ranges, Eigen::Affine2d::Identity(), {}, &disks, nullptr, &clusters));
  ASSERT_EQ(clusters.size(), 1u);  // a wall x = 1 within 45 degrees: the middle of the scan
  EXPECT_EQ(clusters[0].start, ClusterEnd::kOpen);
  EXPECT_EQ(clusters[0].end, ClusterEnd::kOpen);
  // Behind the sensor: a wall x = -1 across the seam (beam 0 at -180 degrees).
  scan = makeScan(beams, -M_PI, M_PI - 2.0 * M_PI / beams, [](double a) {
    return std::cos(a) < -0.5 ? -1.0 / std::cos(a) : std::numeric_limits<double>::infinity();
  });
  ASSERT_TRUE(scanToObstacles(scan.geometry, scan.ranges, Eigen::Affine2d::Identity(), {}, &disks, nullptr, &clusters));
  ASSERT_EQ(clusters.size(), 2u);  // split by the seam
  EXPECT_EQ(clusters[0].start, ClusterEnd::kBeside);
  EXPECT_EQ(clusters[1].end, ClusterEnd::kBeside);
  EXPECT_EQ(clusters[0].end, ClusterEnd::kOpen);
  EXPECT_EQ(clusters[1].start, ClusterEnd::kOpen);
}

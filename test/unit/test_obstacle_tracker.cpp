// Association of laser obstacles across scans and their velocities.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "amigobot_tracking/core/perception/obstacle_tracker.h"

using namespace amigobot_tracking::core;

namespace {

const TrackedObstacle* nearest(const ObstacleTracker& tracker, const Eigen::Vector2d& p) {
  const TrackedObstacle* best = nullptr;
  for (const auto& t : tracker.tracks()) {
    if (!best || (t.disk.center - p).norm() < (best->disk.center - p).norm()) best = &t;
  }
  return best;
}

}  // namespace

TEST(ObstacleTracker, ConstantVelocityIsEstimatedAndIdKept) {
  ObstacleTracker tracker;
  const Eigen::Vector2d v(0.4, -0.2);
  std::uint32_t id = 0;
  for (int k = 0; k < 40; ++k) {  // 10 Hz scans
    const double t = 0.1 * k;
    tracker.update(t, {{Eigen::Vector2d(1.0, 2.0) + v * t, 0.2}});
    ASSERT_EQ(tracker.tracks().size(), 1u);
    if (k == 0) id = tracker.tracks()[0].id;
    EXPECT_EQ(tracker.tracks()[0].id, id);
  }
  const std::vector<Disk> obstacles = tracker.obstaclesAt(3.9);
  EXPECT_LT((obstacles[0].velocity - v).norm(), 1e-3);
  EXPECT_NEAR(obstacles[0].radius, 0.2, 1e-12);
}

TEST(ObstacleTracker, StaticClutterStaysStatic) {
  ObstacleTracker tracker;
  std::mt19937 rng(4);
  std::normal_distribution<double> jitter(0.0, 0.01);
  for (int k = 0; k < 50; ++k) {
    tracker.update(0.1 * k, {{{2.0 + jitter(rng), jitter(rng)}, 0.15}, {{0.0, 1.0 + jitter(rng)}, 0.15}});
  }
  ASSERT_EQ(tracker.tracks().size(), 2u);
  for (const Disk& d : tracker.obstaclesAt(4.9)) EXPECT_EQ(d.velocity, Eigen::Vector2d::Zero());
}

// A person walks 3 s at 0.7 m/s and stands: once the filter has settled they are static, and
// the way they walked is kept as where they may go next; a jittering wall never gets one.
TEST(ObstacleTracker, APersonWhoStopsKeepsTheWayTheyWalked) {
  ObstacleTracker tracker;
  std::mt19937 rng(7);
  std::normal_distribution<double> jitter(0.0, 0.01);
  Eigen::Vector2d at(0.0, -2.0);
  for (int k = 0; k < 100; ++k) {  // 10 Hz: walks until t = 3 s, then stands
    const double t = 0.1 * k;
    if (t > 0.0 && t <= 3.0 + 1e-9) at.y() += 0.07;
    tracker.update(t, {{at, 0.25}, {{2.0 + jitter(rng), 1.0 + jitter(rng)}, 0.2}});
    if (k == 25) {  // walking: the velocity, no resume
      const Disk walking = tracker.obstaclesAt(t)[0];
      EXPECT_GT(walking.velocity.y(), 0.5);
      EXPECT_TRUE(walking.resume_velocity.isZero());
    }
  }
  ASSERT_EQ(tracker.tracks().size(), 2u);
  const std::vector<Disk> now = tracker.obstaclesAt(9.9);
  const Disk& person = (now[0].center - at).norm() < 0.1 ? now[0] : now[1];
  const Disk& wall = &person == &now[0] ? now[1] : now[0];
  EXPECT_TRUE(person.velocity.isZero()) << "standing for 7 s";
  EXPECT_GT(person.resume_velocity.y(), 0.5) << "the way they walked";
  EXPECT_LT(std::abs(person.resume_velocity.x()), 0.1);
  EXPECT_TRUE(wall.resume_velocity.isZero());
  // walking_speed 0: no memory.
  ObstacleTrackerConfig forgetful;
  forgetful.walking_speed = 0.0;
  ObstacleTracker plain(forgetful);
  at = {0.0, -2.0};
  for (int k = 0; k < 100; ++k) {
    if (k > 0 && k <= 30) at.y() += 0.07;
    plain.update(0.1 * k, {{at, 0.25}});
  }
  EXPECT_TRUE(plain.obstaclesAt(9.9)[0].resume_velocity.isZero());
}

TEST(ObstacleTracker, CrossingObstaclesKeepTheirIdsAndAreNotMerged) {
  // Two people crossing in an X at 1 m/s, with a scan where their blobs merge into one
  // (group_gap 0: blobs that do not touch are two objects).
  ObstacleTracker tracker(ObstacleTrackerConfig(), 0.0);
  auto a = [](double t) { return Eigen::Vector2d(-2.0 + t, -2.0 + t); };
  auto b = [](double t) { return Eigen::Vector2d(-2.0 + t, 2.0 - t); };
  std::map<std::uint32_t, char> label;
  for (int k = 0; k <= 40; ++k) {
    const double t = 0.1 * k;
    if (k == 20) {
      tracker.update(t, {{a(t), 0.3}});  // merged: one blob at the crossing point
    } else {
      tracker.update(t, {{a(t), 0.08}, {b(t), 0.08}});  // apart: 0.2 m at k = 19 and 21
    }
    if (k == 5) {
      label[nearest(tracker, a(t))->id] = 'a';
      label[nearest(tracker, b(t))->id] = 'b';
      ASSERT_EQ(label.size(), 2u);
    }
    if (k > 5 && k != 20) {
      EXPECT_EQ(label[nearest(tracker, a(t))->id], 'a') << "t=" << t;
      EXPECT_EQ(label[nearest(tracker, b(t))->id], 'b') << "t=" << t;
    }
  }
  EXPECT_EQ(tracker.tracks().size(), 2u);
}

TEST(ObstacleTracker, UnseenTracksAreForgottenAndTimeJumpsReset) {
  ObstacleTracker tracker;
  tracker.update(0.0, {{{1.0, 1.0}, 0.2}});
  tracker.update(0.3, {});
  EXPECT_EQ(tracker.tracks().size(), 1u);  // coasting
  tracker.update(0.7, {});
  EXPECT_TRUE(tracker.tracks().empty());
  tracker.update(1.0, {{{1.0, 1.0}, 0.2}});
  tracker.update(0.5, {{{3.0, 1.0}, 0.2}});  // back in time: start afresh
  ASSERT_EQ(tracker.tracks().size(), 1u);
  EXPECT_EQ(tracker.tracks()[0].hits, 1);
}

TEST(ObstacleTracker, ValidateNamesTheBadField) {
  ObstacleTrackerConfig c;
  EXPECT_EQ(c.validate(), "");
  c.velocity_gain = 2.0;
  EXPECT_EQ(c.validate().rfind("velocity_gain", 0), 0u);
  c = ObstacleTrackerConfig();
  c.min_hits = 0;
  EXPECT_EQ(c.validate().rfind("min_hits", 0), 0u);
}

// With the scan's clusters: an object whose outline ends hidden (behind something nearer, at
// the scan's edge) is static however it moves, since what moves may be the view's edge; two
// clusters beside each other (adjacent returns at one range) are one object, so two pieces of a
// grazing wall 0.7 m apart are one wall, not two small things.
TEST(ObstacleTracker, HiddenEndsAreStaticAndCloseNeighboursInTheScanAreOneObject) {
  const auto cluster = [](std::size_t first, std::size_t end, ClusterEnd start, ClusterEnd stop) {
    ScanCluster c;
    c.first_disk = first;
    c.end_disk = end;
    c.start = start;
    c.end = stop;
    return c;
  };
  ObstacleTracker tracker;
  const Eigen::Vector2d v(0.5, 0.0);
  for (int k = 0; k < 20; ++k) {
    const double t = 0.1 * k;
    const std::vector<Disk> seen = {{Eigen::Vector2d(0.0, 1.0) + v * t, 0.1},   // open: walks
                                    {Eigen::Vector2d(0.0, 3.0) + v * t, 0.1},   // hidden on one side
                                    {Eigen::Vector2d(0.0, 5.0) + v * t, 0.1},   // beside the next:
                                    {Eigen::Vector2d(0.0, 5.9) + v * t, 0.1}};  // together 1.1 m long
    const std::vector<ScanCluster> clusters = {cluster(0, 1, ClusterEnd::kOpen, ClusterEnd::kOpen),
                                               cluster(1, 2, ClusterEnd::kOpen, ClusterEnd::kHidden),
                                               cluster(2, 3, ClusterEnd::kOpen, ClusterEnd::kBeside),
                                               cluster(3, 4, ClusterEnd::kBeside, ClusterEnd::kOpen)};
    tracker.update(t, seen, &clusters);
  }
  const std::vector<Disk> out = tracker.obstaclesAt(1.9);
  ASSERT_EQ(out.size(), 4u);
  for (const Disk& d : out) {
    if (d.center.y() < 2.0) {
      EXPECT_LT((d.velocity - v).norm(), 0.01);
    } else {
      EXPECT_EQ(d.velocity, Eigen::Vector2d::Zero()) << "at y " << d.center.y();
    }
  }
  // Without the clusters the same disks are three walking things.
  ObstacleTracker blind;
  for (int k = 0; k < 20; ++k) {
    const double t = 0.1 * k;
    blind.update(t, {{Eigen::Vector2d(0.0, 3.0) + v * t, 0.1}, {Eigen::Vector2d(0.0, 5.0) + v * t, 0.1},
                     {Eigen::Vector2d(0.0, 5.9) + v * t, 0.1}});
  }
  for (const Disk& d : blind.obstaclesAt(1.9)) EXPECT_GT(d.velocity.norm(), 0.4);
}

// ScanIntake: which scans the tracking node uses, their disks, their age and their tracks.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "amigobot_tracking/core/supervision/scan_intake.h"

using namespace amigobot_tracking::core;

namespace {

constexpr float kNone = std::numeric_limits<float>::infinity();

ScanGeometry halfCircle() {  // 181 beams, 1 degree apart, facing +x
  ScanGeometry g;
  g.angle_min = -M_PI / 2.0;
  g.angle_increment = M_PI / 180.0;
  g.range_min = 0.05;
  g.range_max = 10.0;
  return g;
}
const double kAngleMax = M_PI / 2.0;

// A post 1 m ahead of the sensor, `shift` m to the left of its axis (beams within 3 degrees of
// it return, the rest see nothing within range).
std::vector<float> postAhead(double shift) {
  std::vector<float> ranges(181, kNone);
  const double bearing = std::atan2(shift, 1.0);
  for (int i = 0; i < 181; ++i) {
    const double a = -M_PI / 2.0 + i * M_PI / 180.0;
    if (std::abs(a - bearing) <= 3.0 * M_PI / 180.0) ranges[i] = static_cast<float>(std::hypot(1.0, shift));
  }
  return ranges;
}

}  // namespace

TEST(ScanIntake, AScanThatSeesNothingIsRefusedAndKeepsThePreviousDisksAndAge) {
  ScanIntake intake(ScanObstacleConfig(), ObstacleTrackerConfig(), 0.0);
  const std::vector<float> post = postAhead(0.0);
  ASSERT_EQ(intake.refusal(halfCircle(), kAngleMax, post.data(), post.size()), "");
  intake.take(halfCircle(), post.data(), post.size(), Eigen::Affine2d::Identity(), 10.0, 10.01);
  ASSERT_FALSE(intake.disks().empty());
  EXPECT_NEAR(intake.disks()[0].center.x(), 1.0, 0.1);
  EXPECT_NEAR(intake.age(10.2).age, 0.2, 1e-9);

  // Max range everywhere: a blind or covered laser, not an empty room (unless open_space).
  const std::vector<float> nothing(181, kNone);
  const std::string why = intake.refusal(halfCircle(), kAngleMax, nothing.data(), nothing.size());
  EXPECT_EQ(why.rfind("laser sees nothing", 0), 0u) << why;
  EXPECT_FALSE(intake.disks().empty()) << "a refused scan keeps the previous disks";
  EXPECT_NEAR(intake.age(11.0).age, 1.0, 1e-9) << "and does not count as fresh";
  ScanIntake open(ScanObstacleConfig(), ObstacleTrackerConfig(), 0.0, 0.1, true);
  EXPECT_EQ(open.refusal(halfCircle(), kAngleMax, nothing.data(), nothing.size()), "");

  // A header whose beam count does not match: refused, naming why.
  EXPECT_NE(intake.refusal(halfCircle(), kAngleMax, post.data(), 100), "");
}

TEST(ScanIntake, AStampInTheFutureIsNotFresh) {
  ScanIntake intake(ScanObstacleConfig(), ObstacleTrackerConfig(), 0.0, 0.1);
  const std::vector<float> post = postAhead(0.0);
  intake.take(halfCircle(), post.data(), post.size(), Eigen::Affine2d::Identity(), 40.0, 10.0);
  EXPECT_TRUE(std::isinf(intake.age(10.0).age));
  EXPECT_FALSE(intake.age(10.0).problem.empty());
}

// The tracker counts from `epoch` and moves its disks to the time asked; the plain disks are
// the last scan's, still.
TEST(ScanIntake, MovingObstaclesAreTheTrackedDisks) {
  ScanIntake intake(ScanObstacleConfig(), ObstacleTrackerConfig(), 1000.0);
  for (int k = 0; k < 10; ++k) {  // the post walks left at 0.5 m/s, scans at 10 Hz
    const std::vector<float> post = postAhead(0.05 * k);
    intake.take(halfCircle(), post.data(), post.size(), Eigen::Affine2d::Identity(), 1000.0 + 0.1 * k,
                1000.0 + 0.1 * k);
  }
  std::vector<Disk> still, moving;
  intake.obstacles(false, 1001.0, &still);
  intake.obstacles(true, 1001.0, &moving);
  ASSERT_FALSE(still.empty());
  ASSERT_EQ(moving.size(), still.size());
  for (const Disk& d : still) EXPECT_TRUE(d.velocity.isZero());
  EXPECT_NEAR(moving[0].velocity.y(), 0.5, 0.1);
  EXPECT_NEAR(moving[0].center.y() - still[0].center.y(), 0.1 * moving[0].velocity.y(), 1e-9) << "moved to now";
}

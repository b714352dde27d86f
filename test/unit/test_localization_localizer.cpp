// The Localizer on a synthetic room (ray-cast scans with 1 cm noise): converges from a wrong
// initial pose, tracks a moving robot whose odometry drifts, finds a kidnapped robot by the
// global search, says when its scans do not fit the map; and the config's rules.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "amigobot_tracking/localization/localizer.h"
#include "synthetic_room.h"

using namespace amigobot_tracking;
using namespace amigobot_tracking::localization;
using amigobot_test::roomMap;
using amigobot_test::scanAt;

namespace {

double positionError(const core::Pose2& a, const core::Pose2& b) { return std::hypot(a.x - b.x, a.y - b.y); }
double headingError(const core::Pose2& a, const core::Pose2& b) { return std::abs(core::wrapAngle(a.theta - b.theta)); }

LocalizationConfig config() {
  LocalizationConfig c;
  c.map_file = "room.yaml";
  return c;
}

}  // namespace

TEST(Localizer, ConvergesFromAWrongInitialPoseWithinTenScans) {
  std::mt19937 random(1);
  const core::Pose2 truth{1.0, 0.5, 0.3};
  const core::Pose2 odom{0.0, 0.0, 0.0};  // odometry's own frame: anywhere
  Localizer localizer(config(), roomMap());
  localizer.setPose(core::Pose2{truth.x + 0.4, truth.y - 0.3, truth.theta + 20.0 * M_PI / 180.0}, odom);
  int scans = 0;
  while (scans < 10 && (positionError(localizer.estimate().pose, truth) > 0.03 || headingError(localizer.estimate().pose, truth) > 0.02)) {
    localizer.update(scanAt(truth, 360, &random), odom);
    ++scans;
  }
  EXPECT_LT(positionError(localizer.estimate().pose, truth), 0.03) << "after " << scans << " scans";
  EXPECT_LT(headingError(localizer.estimate().pose, truth), 0.02);
  EXPECT_GT(localizer.estimate().match, 0.9);
  EXPECT_FALSE(localizer.estimate().lost);
  // The correction makes the odometry pose the true one.
  EXPECT_LT(positionError(compose(localizer.estimate().map_to_odom, odom), truth), 0.03);
  // Settled and still: further scans leave the pose alone (odometry only).
  localizer.update(scanAt(truth, 360, &random), odom);
  localizer.update(scanAt(truth, 360, &random), odom);
  EXPECT_FALSE(localizer.estimate().matched);
}

TEST(Localizer, TracksAMovingRobotWhoseOdometryDrifts) {
  std::mt19937 random(2);
  std::normal_distribution<double> noise(0.0, 1.0);
  LocalizationConfig c = config();
  c.initial_pose = amigobot_test::kLoopStart;
  Localizer localizer(c, roomMap());
  // 1.6 loops through the room at 0.3 m/s, 10 scans per second; odometry reads 4 % long and
  // turns 3 % too much, with noise: it ends off by decimetres.
  core::Pose2 truth = c.initial_pose, odom{};
  double worst_position = 0.0, worst_heading = 0.0, odometry_error = 0.0;
  for (int step = 0; step < 400; ++step) {
    const double v = 0.03, w = v / amigobot_test::kLoopRadius;  // per scan
    truth = compose(truth, core::Pose2{v, 0.0, w});
    odom = compose(odom, core::Pose2{v * 1.04 + 0.002 * noise(random), 0.001 * noise(random), w * 1.03 + 0.002 * noise(random)});
    const PoseEstimate& e = localizer.update(scanAt(truth, 360, &random), odom);
    worst_position = std::max(worst_position, positionError(e.pose, truth));
    worst_heading = std::max(worst_heading, headingError(e.pose, truth));
    odometry_error = positionError(compose(c.initial_pose, odom), truth);
  }
  EXPECT_GT(odometry_error, 0.2) << "the odometry alone must drift for the test to mean anything";
  EXPECT_LT(worst_position, 0.06);
  EXPECT_LT(worst_heading, 0.04);
}

TEST(Localizer, GlobalRelocalisationFindsAKidnappedRobot) {
  std::mt19937 random(3);
  Localizer localizer(config(), roomMap());
  const core::Pose2 odom{0.3, -0.2, 0.1};
  for (const core::Pose2& truth : {core::Pose2{3.5, 2.0, -2.0}, core::Pose2{0.2, -0.3, 1.2}, core::Pose2{1.6, 0.6, 3.0}}) {
    localizer.setPose(core::Pose2{4.0, -0.5, 0.0}, odom);  // believed elsewhere
    const GlobalSearch found = localizer.relocalize(scanAt(truth, 360, &random), odom);
    ASSERT_TRUE(found.found) << "best match " << found.match;
    EXPECT_GT(found.candidates, 1000);
    EXPECT_LT(positionError(found.pose, truth), 0.05) << truth.x << ", " << truth.y;
    EXPECT_LT(headingError(found.pose, truth), 0.03);
    EXPECT_LT(positionError(localizer.estimate().pose, truth), 0.05) << "the pose jumps to the relocalised one";
  }
}

TEST(Localizer, ScansThatDoNotFitTheMapAreLostAndDoNotDragThePose) {
  std::mt19937 random(4);
  Localizer localizer(config(), roomMap());
  const core::Pose2 truth{1.0, 0.5, 0.3};
  localizer.setPose(truth, core::Pose2());
  localizer.update(scanAt(truth, 360, &random), core::Pose2());
  EXPECT_FALSE(localizer.estimate().lost);
  // People all around the robot, 0.6 m away: most beams end on them, not on the map.
  std::vector<core::Disk> crowd;
  for (int i = 0; i < 14; ++i) {
    const double a = 2.0 * M_PI * i / 14;
    crowd.push_back(core::Disk{Eigen::Vector2d(truth.x + 0.6 * std::cos(a), truth.y + 0.6 * std::sin(a)), 0.12});
  }
  for (int i = 0; i < 5; ++i) localizer.update(scanAt(truth, 360, &random, 0.01, crowd), core::Pose2());
  EXPECT_TRUE(localizer.estimate().lost) << "match " << localizer.estimate().match;
  EXPECT_LT(positionError(localizer.estimate().pose, truth), 0.1);
  // A scan with no echo at all: lost, nothing matched, nothing found.
  RangeScan empty = amigobot_test::emptyScan(360);
  empty.ranges.assign(360, std::numeric_limits<float>::infinity());
  localizer.setPose(truth, core::Pose2());
  localizer.update(empty, core::Pose2());
  EXPECT_TRUE(localizer.estimate().lost);
  EXPECT_FALSE(localizer.estimate().matched);
  EXPECT_FALSE(localizer.relocalize(empty, core::Pose2()).found);
}

TEST(LocalizationConfig, ValidateNamesTheBadKey) {
  EXPECT_EQ(config().validate(), "");
  LocalizationConfig c = config();
  c.map_file.clear();
  EXPECT_EQ(c.validate().rfind("map_file:", 0), 0u) << c.validate();
  c.mode = "mapping";
  EXPECT_EQ(c.validate(), "") << "mapping needs no map";
  c.mode = "slam";
  EXPECT_EQ(c.validate().rfind("mode:", 0), 0u);
  c = config();
  c.tf_rate = 10.0;
  EXPECT_EQ(c.validate().rfind("tf_rate:", 0), 0u) << c.validate();
  c = config();
  c.icp.min_correspondence = 1.0;
  EXPECT_EQ(c.validate().rfind("icp/min_correspondence:", 0), 0u) << c.validate();
  c = config();
  c.odom_frame = "map";
  EXPECT_EQ(c.validate().rfind("odom_frame:", 0), 0u) << c.validate();
  c = config();
  c.initial_pose.x = std::nan("");
  EXPECT_EQ(c.validate().rfind("initial_pose/x:", 0), 0u) << c.validate();
  EXPECT_THROW(Localizer(config(), OccupancyMap()), std::invalid_argument);
  EXPECT_THROW(Localizer(config(), makeMap(0.05, 0, 0, 10, 10, OccupancyMap::kFree)), std::invalid_argument);
}

// ground_truth_localization: the map -> odom correction, its parameters, and the status
// client it reads (aria/emulator_status.h) against the real emulator, including the
// emulator going away.
#include <algorithm>
#include <cmath>
#include <optional>

#include <gtest/gtest.h>

#include "amigobot_tracking/aria/emulator_status.h"
#include "amigobot_tracking/ros/ground_truth.h"
#include "emulator_process.h"

using namespace amigobot_tracking;

TEST(GroundTruth, MapToOdomComposesToTheTruth) {
  const core::Pose2 truth{2.0, -1.0, 2.5};
  const core::Pose2 odom_base{0.7, 0.3, -1.2};
  const core::Pose2 m = ros_layer::mapToOdom(truth, odom_base);
  // (map -> odom) * (odom -> base)
  const double c = std::cos(m.theta), s = std::sin(m.theta);
  EXPECT_NEAR(m.x + c * odom_base.x - s * odom_base.y, truth.x, 1e-12);
  EXPECT_NEAR(m.y + s * odom_base.x + c * odom_base.y, truth.y, 1e-12);
  EXPECT_NEAR(core::wrapAngle(m.theta + odom_base.theta - truth.theta), 0.0, 1e-12);
}

// A robot driving at 0.3 m/s with odometry every 0.1 s, reaching the ground truth node late:
// each true pose is paired with the odometry of its own instant, so map -> odom is exactly the
// odometry's offset; the truth of now with the latest odometry was off by v x its age.
TEST(GroundTruth, PairsEachTruthWithTheOdometryOfItsInstant) {
  const core::Pose2 offset{1.0, -0.5, 0.4};  // map -> odom, what a perfect pairing finds
  auto truthAt = [](double t) { return core::Pose2{0.3 * t, 0.0, 0.0}; };
  auto compose = [](const core::Pose2& a, const core::Pose2& b) {
    const double c = std::cos(a.theta), s = std::sin(a.theta);
    return core::Pose2{a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y, core::wrapAngle(a.theta + b.theta)};
  };
  const core::Pose2 inverse_offset = ros_layer::mapToOdom(core::Pose2{}, offset);  // odom -> map
  double odom_reaches = -1.0;                                                      // newest odometry stamp
  const ros_layer::TruthPairing::OdometryAt odom_at = [&](double stamp, core::Pose2* p) {
    if (stamp > odom_reaches) return false;
    *p = compose(inverse_offset, truthAt(stamp));  // odom -> base at that instant
    return true;
  };
  ros_layer::TruthPairing pairing;
  EXPECT_FALSE(pairing.correction(odom_at)) << "no odometry yet";
  double worst_latest = 0.0;
  std::optional<core::Pose2> m;
  int pairs = 0;
  for (int i = 0; i <= 40; ++i) {
    const double now = 0.05 * i;
    odom_reaches = 0.1 * std::floor(now / 0.1 + 1e-9) - 0.15;  // a SIP period apart, 0.15 s late (load)
    pairing.add(now, truthAt(now));
    const auto paired = pairing.correction(odom_at);
    if (odom_reaches < 0.0) {
      EXPECT_FALSE(paired);
      continue;
    }
    pairs += paired.has_value();
    if (paired) m = paired;  // between pairs the node broadcasts the last one again
    ASSERT_TRUE(m) << "t " << now;
    EXPECT_NEAR(m->x, offset.x, 1e-9);
    EXPECT_NEAR(m->y, offset.y, 1e-9);
    EXPECT_NEAR(m->theta, offset.theta, 1e-9);
    // What the truth of now and the latest odometry gave.
    core::Pose2 latest;
    odom_at(odom_reaches, &latest);
    const core::Pose2 naive = ros_layer::mapToOdom(truthAt(now), latest);
    worst_latest = std::max(worst_latest, std::hypot(naive.x - offset.x, naive.y - offset.y));
    // Only poses newer than the odometry wait: at most (0.15 s late + 0.1 s apart) / 0.05 s + 1.
    EXPECT_LE(pairing.pending(), 6u) << "used and older poses are dropped";
  }
  EXPECT_GE(pairs, 15) << "about one pair per odometry sample";
  EXPECT_GT(worst_latest, 0.05) << "the naive pairing's error this test guards against";
}

TEST(GroundTruth, PairingForgetsOldTruthAndRestartsWhenTimeGoesBack) {
  ros_layer::TruthPairing pairing(1.0);
  for (int i = 0; i < 100; ++i) pairing.add(0.1 * i, core::Pose2{});
  EXPECT_LE(pairing.pending(), 11u);
  pairing.add(0.0, core::Pose2{});
  EXPECT_EQ(pairing.pending(), 1u);
  EXPECT_FALSE(pairing.correction([](double, core::Pose2*) { return false; }));
  EXPECT_EQ(pairing.pending(), 1u) << "kept until odometry reaches it";
}

TEST(GroundTruth, ValidateNamesTheBadField) {
  ros_layer::GroundTruthConfig c;
  EXPECT_EQ(c.validate(), "");
  c.port = 0;
  EXPECT_NE(c.validate().find("port"), std::string::npos);
  c = ros_layer::GroundTruthConfig();
  c.rate = -1;
  EXPECT_NE(c.validate().find("rate"), std::string::npos);
}

TEST(GroundTruth, ClientReadsTheEmulatorAndReportsItsLoss) {
  amigobot_test::EmulatorProcess emu;
  aria::StatusClient client("127.0.0.1", emu.statusPort(), 5.0);
  aria::EmulatorStatus s;
  ASSERT_EQ(client.query(&s), "");
  EXPECT_TRUE(client.connected());
  EXPECT_NEAR(s.pose.x, 0.0, 1e-9);  // default world: the robot starts at the origin
  aria::EmulatorStatus later;
  ASSERT_EQ(client.query(&later), "");
  EXPECT_GE(later.t, s.t);
  emu.kill(SIGTERM);
  std::string error;
  for (int i = 0; i < 5 && error.empty(); ++i) error = client.query(&s);  // the first send may still succeed
  EXPECT_FALSE(error.empty());
  EXPECT_FALSE(client.connected());
  EXPECT_NE(client.query(&s).find("cannot connect"), std::string::npos);
}

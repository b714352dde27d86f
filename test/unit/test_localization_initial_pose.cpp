// /initialpose checked where it enters (localization/initial_pose.h): NaN, zero or non-unit
// quaternion, wrong frame and far outside the map refused by name; a good pose passes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "amigobot_tracking/localization/initial_pose.h"

using amigobot_tracking::core::Quaternion4;
using amigobot_tracking::core::Translation3;
using amigobot_tracking::localization::initialPoseProblem;
using amigobot_tracking::localization::makeMap;
using amigobot_tracking::localization::OccupancyMap;

namespace {
// 10 m x 6 m from (-2, -1).
const OccupancyMap kMap = makeMap(0.05, -2.0, -1.0, 200, 120, OccupancyMap::kFree);
const Quaternion4 kYaw90{0.0, 0.0, std::sqrt(0.5), std::sqrt(0.5)};
const double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

TEST(InitialPose, AGoodPoseOnTheMapPasses) {
  EXPECT_EQ(initialPoseProblem("map", "map", {1.0, 2.0, 0.0}, kYaw90, kMap), "");
  EXPECT_EQ(initialPoseProblem("", "map", {1.0, 2.0, 0.0}, kYaw90, kMap), "") << "an empty frame is the map's";
  EXPECT_EQ(initialPoseProblem("map", "map", {8.5, 5.5, 0.0}, kYaw90, kMap), "") << "just past the edge: within the margin";
  EXPECT_EQ(initialPoseProblem("map", "map", {1.0, 2.0, 0.0}, {0.0, 0.0, 0.0, 0.9995}, kMap), "") << "normalised";
}

TEST(InitialPose, NaNIsRefusedByField) {
  EXPECT_EQ(initialPoseProblem("map", "map", {kNaN, 2.0, 0.0}, kYaw90, kMap), "position x is nan");
  EXPECT_EQ(initialPoseProblem("map", "map", {1.0, 2.0, 0.0}, {kNaN, kNaN, kNaN, kNaN}, kMap), "orientation x is nan");
}

TEST(InitialPose, ZeroAndNonUnitQuaternionsAreRefused) {
  const std::string zero = initialPoseProblem("map", "map", {1.0, 2.0, 0.0}, {0.0, 0.0, 0.0, 0.0}, kMap);
  EXPECT_EQ(zero.rfind("orientation is not a unit quaternion (norm 0.000", 0), 0u) << zero;
  EXPECT_NE(initialPoseProblem("map", "map", {1.0, 2.0, 0.0}, {0.0, 0.0, 0.0, 2.0}, kMap), "");
}

TEST(InitialPose, AnotherFrameIsRefused) {
  EXPECT_EQ(initialPoseProblem("odom", "map", {1.0, 2.0, 0.0}, kYaw90, kMap), "frame 'odom' is not 'map'");
}

TEST(InitialPose, FarOutsideTheMapIsRefused) {
  const std::string far = initialPoseProblem("map", "map", {50.0, 2.0, 0.0}, kYaw90, kMap);
  EXPECT_EQ(far, "(50.00, 2.00) is more than 1.0 m outside the map ([-2.00, 8.00] x [-1.00, 5.00] m)");
  EXPECT_NE(initialPoseProblem("map", "map", {1.0, -2.5, 0.0}, kYaw90, kMap), "");
  // Mapping: no map bounds yet, only the pose itself is checked.
  EXPECT_EQ(initialPoseProblem("map", "map", {50.0, 2.0, 0.0}, kYaw90, OccupancyMap{}), "");
}

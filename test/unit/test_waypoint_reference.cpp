// Piecewise-linear waypoint reference (core/reference/waypoint_reference.h).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "amigobot_tracking/core/reference/reference.h"
#include "amigobot_tracking/core/reference/waypoint_reference.h"

using namespace amigobot_tracking::core;

namespace {
const std::vector<Eigen::Vector2d> kSquareCorner{{0, 0}, {2, 0}, {2, 1}};  // 3 m of path
}

TEST(WaypointReference, MovesAlongTheSegmentsAtConstantSpeed) {
  const WaypointReference ref(kSquareCorner, 0.5, false);
  EXPECT_DOUBLE_EQ(ref.period(), 6.0);
  for (double t = 0.05; t < 6.0; t += 0.1) {
    const ReferenceState s = ref.at(t);
    EXPECT_NEAR(s.velocity.norm(), 0.5, 1e-12);
    // Numerical derivative agrees with the reported velocity away from the corner.
    if (std::abs(t - 4.0) > 0.02) {
      EXPECT_LT(((ref.at(t + 1e-4).position - ref.at(t - 1e-4).position) / 2e-4 - s.velocity).norm(), 1e-6);
    }
  }
  EXPECT_LT((ref.at(2.0).position - Eigen::Vector2d(1.0, 0.0)).norm(), 1e-12);
  EXPECT_LT((ref.at(5.0).position - Eigen::Vector2d(2.0, 0.5)).norm(), 1e-12);
}

TEST(WaypointReference, StopsAtTheEndOrLoops) {
  const WaypointReference once(kSquareCorner, 0.5, false);
  EXPECT_EQ(once.at(100.0).position, Eigen::Vector2d(2.0, 1.0));
  EXPECT_EQ(once.at(100.0).velocity, Eigen::Vector2d::Zero());
  EXPECT_EQ(once.at(-3.0).position, Eigen::Vector2d(0.0, 0.0));  // before the start: first point

  const WaypointReference loop(kSquareCorner, 0.5, true);
  const double lap = loop.period();  // 3 m + sqrt(5) m back to the start
  EXPECT_NEAR(lap, (3.0 + std::sqrt(5.0)) / 0.5, 1e-12);
  for (double t = 0.3; t < lap; t += 0.7) {
    EXPECT_LT((loop.at(t).position - loop.at(t + 2 * lap).position).norm(), 1e-9);
  }
}

TEST(WaypointReference, RejectsUnusableInput) {
  EXPECT_THROW(WaypointReference({{0, 0}}, 0.5, false), std::invalid_argument);
  EXPECT_THROW(WaypointReference(kSquareCorner, 0.0, false), std::invalid_argument);
  EXPECT_THROW(WaypointReference({{1, 1}, {1, 1}}, 0.5, false), std::invalid_argument);
  EXPECT_THROW(WaypointReference({{0, 0}, {NAN, 1}}, 0.5, false), std::invalid_argument);
}

// The rose of Section 5.2 (k = 3) closes after pi, not 2 pi: the shipped 2 pi s are two laps.
TEST(RoseReference, PeriodIsPiForOddK) {
  const RoseReference rose(3.0, 3.0, 1.0);
  for (double t : {0.1, 0.7, 2.0}) {
    EXPECT_LT((rose.at(t + M_PI).position - rose.at(t).position).norm(), 1e-12) << t;
    EXPECT_LT((rose.at(t + M_PI).velocity - rose.at(t).velocity).norm(), 1e-12) << t;
    EXPECT_GT((rose.at(t + 0.5 * M_PI).position - rose.at(t).position).norm(), 0.1) << t;
  }
}

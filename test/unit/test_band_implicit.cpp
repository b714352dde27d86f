// The band-implicit repulsive term (core/law/band_implicit.h): on hand-made approaches to a disk
// it agrees with a fine explicit reference at steps 50-100x longer, it never ends a step
// inside the disk, and the clearance it reports is the one the held command reaches.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "amigobot_tracking/core/law/avoidance.h"
#include "amigobot_tracking/core/law/band_implicit.h"
#include "amigobot_tracking/core/robot/offset_point.h"
#include "amigobot_tracking/core/robot/unicycle.h"

using namespace amigobot_tracking::core;

namespace {

constexpr double kOffset = 0.3, kBandRadius = 0.2, kBandDelta = 0.016, kMinMargin = 1e-3;
const DiamondSet kBandDiamond(15.0, 15.0);
const Disk kBandDisk{Eigen::Vector2d(0.0, 0.0), 0.15, Eigen::Vector2d::Zero()};

double clearanceOf(const Pose2& pose) {
  return clearance(offsetPoint(pose, kOffset), kBandRadius, {kBandDisk});
}

// u_r = rest + u_c (k_o = 1) through (11)-(12), held for h.
Pose2 hold(const Pose2& pose, const Eigen::Vector2d& rest, const Eigen::Vector2d& u_c, double h) {
  const Twist2 u = *kBandDiamond.saturate(offsetVelocityToTwist(rest + u_c, pose.theta, kOffset));
  return integrateUnicycle(pose, u, h);
}

// The problem of a step held for h from `pose` with the constant rest of (9).
BandImplicitProblem problem(const Pose2& pose, const Eigen::Vector2d& rest, double h) {
  // pose, offset, rest, k_o, obstacle, robot_radius, delta, min_margin, h
  return {pose, kOffset, rest, 1.0, kBandDisk, kBandRadius, kBandDelta, kMinMargin, h};
}

// One step of the loop: explicit (10) at the start of the step, or the band-implicit term.
Pose2 step(const Pose2& pose, const Eigen::Vector2d& rest, double h, bool implicit) {
  if (!implicit) {
    const AvoidanceResult a = repulsiveTerm(offsetPoint(pose, kOffset), {kBandDisk}, kBandRadius, kBandDelta,
                                            Eigen::Vector2d(std::cos(pose.theta), std::sin(pose.theta)), kMinMargin);
    return hold(pose, rest, a.u_c, h);
  }
  return hold(pose, rest, solveBandImplicit(problem(pose, rest, h), kBandDiamond).u_c, h);
}

// The offset point starts `clearance` outside contact, on the ray at angle `bearing` from the
// disk's centre, heading back toward it; `rest` is a constant pull of `pull` m/s toward a point
// beyond the disk (the tracking part of (9) when the target is behind the obstacle).
struct Approach {
  Pose2 start;
  Eigen::Vector2d rest;
};
Approach approach(double bearing, double clearance, double pull, double slant) {
  const Eigen::Vector2d out(std::cos(bearing), std::sin(bearing));
  const Eigen::Vector2d p_r = (kBandRadius + kBandDisk.radius + clearance) * out;
  Pose2 pose;
  pose.theta = bearing + M_PI;
  pose.x = p_r.x() - kOffset * std::cos(pose.theta);
  pose.y = p_r.y() - kOffset * std::sin(pose.theta);
  const Eigen::Vector2d inward = -out, along(-out.y(), out.x());
  return {pose, pull * (std::cos(slant) * inward + std::sin(slant) * along)};
}

}  // namespace

TEST(BandImplicit, ReportedClearanceIsTheOneTheHeldCommandReaches) {
  for (double h : {0.0005, 0.005, 0.02}) {
    for (double slant : {0.0, 0.6, 1.2}) {
      const Approach a = approach(0.4, 0.01, 12.0, slant);
      const BandImplicitResult r = solveBandImplicit(problem(a.start, a.rest, h), kBandDiamond);
      ASSERT_TRUE(r.solved) << h << " " << slant;
      EXPECT_LT(r.iterations, 40) << h << " " << slant;
      EXPECT_GT(r.end_clearance, 0.0);
      EXPECT_NEAR(clearanceOf(hold(a.start, a.rest, r.u_c, h)), r.end_clearance, 1e-8) << h << " " << slant;
    }
  }
}

TEST(BandImplicit, AgreesWithAFineExplicitReferenceOnApproachesToADisk) {
  // A slanted pull: the offset point enters the band and slides along the disk, pressed
  // against it (head-on it would sit on the saddle behind the disk, where any two solutions
  // part ways). 60 ms covers the approach from outside the band and the slide.
  for (double slant : {0.4, 0.8}) {
    const Approach a = approach(-0.7, 0.04, 10.0, slant);
    constexpr double kFine = 2e-6, kLong = 0.005, kDuration = 0.06;
    Pose2 fine = a.start, coarse = a.start, coarse_explicit = a.start;
    double worst_gap = 0.0, min_fine = 1.0, min_coarse = 1.0, min_explicit = 1.0;
    const int fine_per_long = static_cast<int>(std::lround(kLong / kFine));
    for (int k = 0; k < static_cast<int>(std::lround(kDuration / kLong)); ++k) {
      for (int i = 0; i < fine_per_long; ++i) {
        fine = step(fine, a.rest, kFine, false);
        min_fine = std::min(min_fine, clearanceOf(fine));
      }
      coarse = step(coarse, a.rest, kLong, true);
      coarse_explicit = step(coarse_explicit, a.rest, kLong, false);
      worst_gap = std::max(worst_gap, std::abs(clearanceOf(coarse) - clearanceOf(fine)));
      min_coarse = std::min(min_coarse, clearanceOf(coarse));
      min_explicit = std::min(min_explicit, clearanceOf(coarse_explicit));
    }
    std::printf("slant %.1f: clearance fine %.5f coarse %.5f (worst gap %.5f), min fine %.5f coarse %.5f explicit %.5f, "
                "position gap %.5f\n", slant, clearanceOf(fine), clearanceOf(coarse), worst_gap, min_fine, min_coarse,
                min_explicit, (offsetPoint(coarse, kOffset) - offsetPoint(fine, kOffset)).norm());
    EXPECT_LT(min_fine, 0.85 * kBandDelta) << slant << ": the reference never went deep into the band";
    // The closest approach and the clearance at the end within half a millimetre of the
    // reference, 2500x finer; on entering the band (the offset point covers 5 cm per long
    // step there) within 3 mm.
    EXPECT_NEAR(min_coarse, min_fine, 5e-4) << slant;
    EXPECT_NEAR(clearanceOf(coarse), clearanceOf(fine), 5e-4) << slant;
    EXPECT_LT(worst_gap, 3e-3) << slant;
    // The explicit term over the same long step overshoots: it dives twice as deep or more.
    EXPECT_LT(min_explicit, 0.5 * min_coarse) << slant;
    // And the positions agree too (the slide along the disk is resolved, not just the distance).
    EXPECT_LT((offsetPoint(coarse, kOffset) - offsetPoint(fine, kOffset)).norm(), 0.005) << slant;
  }
}

TEST(BandImplicit, NeverEndsAStepInsideTheDisk) {
  // Full pull straight at the disk from just outside the band, steps up to 50 ms (the offset
  // point could cross 0.75 m, more than the disk's contact diameter, in one step).
  for (double h : {0.001, 0.01, 0.05}) {
    for (double pull : {5.0, 15.0, 40.0}) {
      const Approach a = approach(2.0, 0.02, pull, 0.0);
      Pose2 pose = a.start;
      for (int k = 0; k < 40; ++k) {
        pose = step(pose, a.rest, h, true);
        ASSERT_GT(clearanceOf(pose), 0.0) << "h " << h << " pull " << pull << " step " << k;
      }
    }
  }
}

TEST(BandImplicit, FarFromTheBandTheTermIsZeroAndWithoutAStepItIsTheExplicitOne) {
  const Approach far = approach(1.0, 0.5, 10.0, 0.0);
  // 5 ms: 7.5 cm at most, the band stays out of reach.
  const BandImplicitResult r = solveBandImplicit(problem(far.start, far.rest, 0.005), kBandDiamond);
  EXPECT_TRUE(r.solved);
  EXPECT_TRUE(r.u_c.isZero(0.0));
  EXPECT_GT(r.end_clearance, kBandDelta);

  const Approach near = approach(1.0, 0.008, 10.0, 0.0);
  const BandImplicitResult none = solveBandImplicit(problem(near.start, near.rest, 0.0), kBandDiamond);
  EXPECT_FALSE(none.solved);
  const AvoidanceResult explicit_term = repulsiveTerm(offsetPoint(near.start, kOffset), {kBandDisk}, kBandRadius, kBandDelta,
                                                      Eigen::Vector2d::UnitX(), kMinMargin);
  EXPECT_LT((none.u_c - explicit_term.u_c).norm(), 1e-9 * explicit_term.u_c.norm());
}

// The recommended law's look-ahead for people it cannot outrun (yield_rollout.h): a command that
// the base, on its ramps, would carry into a moving disk is replaced by a manoeuvre that keeps
// the body clear; with no one moving, or no one near, nothing changes.
#include <gtest/gtest.h>

#include <vector>

#include "amigobot_tracking/core/law/yield_rollout.h"

using namespace amigobot_tracking::core;

namespace {

Disk disk(double x, double y, double radius, double vx = 0.0, double vy = 0.0) {
  Disk d;
  d.center = {x, y};
  d.radius = radius;
  d.velocity = {vx, vy};
  return d;
}

// The robot at the origin heading +x at v_bar, the filter's command: on at v_bar.
YieldInput driving() {
  YieldInput in;
  in.pose = {0.0, 0.0, 0.0};
  in.previous = {0.3, 0.0};
  in.filtered = {0.3, 0.0};
  in.target = {1.3, 0.0};
  in.target_velocity = {0.2, 0.0};
  in.horizon = 5.0;
  in.enough = 0.15;
  return in;
}

const DiamondSet kDiamond(0.3, 0.8);

}  // namespace

// A person 2 m behind on the robot's line at 0.8 m/s: fleeing at v_bar meets them; the
// manoeuvre chosen instead keeps the body clear on the base's ramps.
TEST(YieldRollout, StepsOutOfTheWayOfAPersonItCannotOutrun) {
  const std::vector<Disk> behind = {disk(-2.0, 0.05, 0.25, 0.8, 0.0)};
  const YieldResult r = yieldToMovingDisks(driving(), kDiamond, behind);
  EXPECT_LT(r.filtered_clearance, 0.0) << "the held command should meet the person for this test to mean anything";
  ASSERT_TRUE(r.acted);
  // One manoeuvre judged once (the law chooses again at every step, closed loop:
  // test_yield_to_people): it must gain on fleeing, and step to the side away from the
  // person, who walks 5 cm left of the robot's line.
  EXPECT_GT(r.chosen_clearance, r.filtered_clearance + 0.2);
  EXPECT_LT(r.u.omega, 0.0) << "stepped toward the person's side";
  EXPECT_LE(std::abs(r.u.v) / 0.3 + std::abs(r.u.omega) / 0.8, 1.0 + 1e-12) << "outside the diamond";
  EXPECT_GT(r.candidates, 20);
}

TEST(YieldRollout, LeavesTheCommandAloneWithoutAPersonInTheWay) {
  // No one moving: not even judged.
  const std::vector<Disk> still = {disk(0.8, 0.0, 0.25)};
  YieldResult r = yieldToMovingDisks(driving(), kDiamond, still);
  EXPECT_FALSE(r.acted);
  EXPECT_EQ(r.u.v, 0.3);
  // Someone walking away, far off: clear enough as it is.
  const std::vector<Disk> away = {disk(3.0, 1.5, 0.25, 0.5, 0.5)};
  r = yieldToMovingDisks(driving(), kDiamond, away);
  EXPECT_FALSE(r.acted);
  EXPECT_GE(r.filtered_clearance, 0.15);
  // No horizon: off.
  YieldInput off = driving();
  off.horizon = 0.0;
  EXPECT_FALSE(yieldToMovingDisks(off, kDiamond, {disk(-2.0, 0.05, 0.25, 0.8, 0.0)}).acted);
}

// (The person 2.6 m behind: far enough for a manoeuvre that keeps clear.) The manoeuvre under
// way is kept while it keeps the body clear, without a search, and for at
// most 3 s; one that would now meet the person is dropped for a fresh choice.
TEST(YieldRollout, KeepsTheManoeuvreUnderWayWhileItIsClear) {
  const std::vector<Disk> behind = {disk(-2.6, 0.05, 0.25, 0.8, 0.0)};
  const YieldResult first = yieldToMovingDisks(driving(), kDiamond, behind);
  ASSERT_TRUE(first.acted);
  ASSERT_GE(first.chosen_clearance, 0.0);
  YieldInput again = driving();
  again.committed = first.manoeuvre;
  again.committed->held = 0.05;
  YieldResult kept = yieldToMovingDisks(again, kDiamond, behind);
  ASSERT_TRUE(kept.acted);
  EXPECT_EQ(kept.candidates, 0) << "searched although the manoeuvre under way was clear";
  EXPECT_EQ(kept.u.v, first.u.v);
  EXPECT_EQ(kept.u.omega, first.u.omega);
  // Held past the span: chosen afresh.
  again.committed->held = 3.5;
  EXPECT_GT(yieldToMovingDisks(again, kDiamond, behind).candidates, 0);
  // A manoeuvre that drives straight back into the person is dropped.
  again.committed = YieldManoeuvre{{-0.3, 0.0}, 0.0, {-0.3, 0.0}, 0.05};
  const YieldResult dropped = yieldToMovingDisks(again, kDiamond, behind);
  EXPECT_GT(dropped.candidates, 0);
  EXPECT_FALSE(dropped.u.v == -0.3 && dropped.u.omega == 0.0);
}

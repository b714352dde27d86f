// The recommended law's look-ahead for people it cannot outrun (yield_rollout.h): a command that
// the base, on its ramps, would carry into a moving disk is replaced by a manoeuvre that keeps
// the body clear; with no one moving, or no one near, nothing changes.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "amigobot_tracking/core/law/yield_rollout.h"
#include "amigobot_tracking/core/robot/actuator_model.h"

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
  again.committed = YieldManoeuvre{{-0.3, 0.0}, 0.0, {-0.3, 0.0}};
  again.committed->held = 0.05;
  const YieldResult dropped = yieldToMovingDisks(again, kDiamond, behind);
  EXPECT_GT(dropped.candidates, 0);
  EXPECT_FALSE(dropped.u.v == -0.3 && dropped.u.omega == 0.0);
}

namespace {

// Where the base is after the manoeuvre's horizon on its ramps (from rest-ish at `previous`).
Pose2 endOf(const YieldInput& in, const YieldManoeuvre& m) {
  ActuatorModel base(in.limits, kAmigoHalfTrack);
  base.step(in.previous, 2.0);
  Pose2 pose = in.pose;
  for (double t = 0.0; t < in.horizon - 1e-9; t += 0.1) pose = driveBody(&base, pose, m.commandAt(t), 0.1, 0.02);
  return pose;
}

}  // namespace

// A person walks head-on down a corridor 1.7 m wide (disks of 0.2 m at y = +-1.05) at 0.45 m/s.
// Backing away down the corridor keeps the most clearance (the person never reaches a robot
// that flees) and loses the target; the manoeuvre chosen steps aside and waits beside them,
// keeping at least half of `enough` on the base's ramps.
TEST(YieldRollout, StepsAsideAndWaitsInACorridorRatherThanBackingDownIt) {
  std::vector<Disk> corridor = {disk(2.2, 0.05, 0.25, -0.45, 0.0)};
  for (double x = -4.0; x <= 5.0; x += 0.4) {
    corridor.push_back(disk(x, 1.05, 0.2));
    corridor.push_back(disk(x, -1.05, 0.2));
  }
  YieldInput in = driving();
  in.previous = in.filtered = {0.2, 0.0};
  const YieldResult r = yieldToMovingDisks(in, kDiamond, corridor);
  ASSERT_LT(r.filtered_clearance, 0.0) << "driving on should meet the person for this test to mean anything";
  ASSERT_TRUE(r.acted);
  EXPECT_GE(r.chosen_clearance, 0.5 * in.enough);
  const Pose2 end = endOf(in, r.manoeuvre);
  EXPECT_GT(end.x, -0.3) << "backed down the corridor ahead of the person";
  EXPECT_GT(std::abs(end.y), 0.3) << "did not step aside";
  EXPECT_EQ(r.manoeuvre.commandAt(in.horizon).v, 0.0) << "does not wait: drives on into the wall or away";
}

// A person 3.5 m ahead walking at the robot: a stop keeps clear over the horizon, driving on
// does not. The look-ahead acts (it once sent the filter's command whenever a stop kept clear,
// and the robot drove on until nothing did).
TEST(YieldRollout, ActsWhenOnlyAStopKeepsClear) {
  const std::vector<Disk> ahead = {disk(3.5, 0.0, 0.25, -0.4, 0.0)};
  const YieldResult r = yieldToMovingDisks(driving(), kDiamond, ahead);
  ASSERT_LT(r.filtered_clearance, 0.0);
  ASSERT_GE(r.stopped_clearance, 0.15) << "a stop should keep clear for this test to mean anything";
  EXPECT_TRUE(r.acted);
  EXPECT_GE(r.chosen_clearance, 0.075);
  EXPECT_LT(r.u.v, 0.3) << "drove on at v_bar toward the person";
}

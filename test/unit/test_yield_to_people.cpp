// The recommended law among people, closed loop on the AmigoBot's ramped dynamics: the
// pedestrian benchmark's overtaking scene (a person walks up from behind along the robot's line
// at 0.7 m/s, faster than the diamond's 0.3 m/s). Without the look-ahead (yield_horizon 0) the
// robot fled along the person's line and was caught; with it, it steps aside. And its stopping
// scene: a person stands 8 s 0.3 m beside the target's line, then walks on across it. And a
// person crossing ahead of the target, whom it lets by without backing off.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "amigobot_tracking/sim/scenario.h"

using namespace amigobot_tracking;

namespace {

const std::string kScenes = std::string(AMIGOBOT_SOURCE_DIR) + "/config/scenarios/pedestrians/";
const std::string kOvertaking = kScenes + "overtaking.yaml";

// The least true clearance of the body from the people over the run, and how often the law yielded;
// `retreat`: the most the body fell back along +x (the target's way) below the farthest it had been.
double leastClearance(const std::vector<std::string>& sets, int* yielded, const std::string& scene = kOvertaking,
                      const std::function<void(sim::Scenario*)>& change = nullptr, double* retreat = nullptr) {
  std::vector<std::string> all = {"controller.variant=recommended"};
  all.insert(all.end(), sets.begin(), sets.end());
  sim::Scenario s = sim::loadScenario(scene, all);
  if (change) change(&s);
  const auto reference = s.makeReference();
  double least = std::numeric_limits<double>::infinity();
  *yielded = 0;
  double farthest = -std::numeric_limits<double>::infinity(), fell_back = 0.0;
  sim::runClosedLoop(s.setup, *reference, [&](const sim::ClosedLoopStep& step) {
    for (const core::Disk& o : *step.obstacles)
      least = std::min(least, (step.pose.position() - o.center).norm() - s.setup.controller.robot_radius - o.radius);
    *yielded += step.output.active.yielding ? 1 : 0;
    farthest = std::max(farthest, step.pose.x);
    fell_back = std::max(fell_back, farthest - step.pose.x);
  });
  if (retreat) *retreat = fell_back;
  return least;
}

// The crossing_ahead scene with one variant's start, person and walk (the benchmark's variant
// file, target noise left out): the least body clearance; `retreat` as above.
double crossingAhead(const core::Pose2& start, const Eigen::Vector2d& center, double start_time, double walk_time,
                     double speed, double* retreat) {
  int yielded = 0;
  return leastClearance(
      {}, &yielded, kScenes + "crossing_ahead.yaml",
      [&](sim::Scenario* s) {
        s->setup.initial_pose = start;
        core::ObstacleMotion& walk = s->setup.obstacle_motions.at(0);
        s->setup.obstacles.at(0).center = center;
        walk.start = center;
        walk.start_time = start_time;
        walk.legs = {{walk_time, {0.0, speed}}};
      },
      retreat);
}

}  // namespace

TEST(YieldToPeople, StepsAsideForAPersonOvertakingFromBehind) {
  int yielded_off = 0, yielded_on = 0;
  const double off = leastClearance({"controller.yield_horizon=0"}, &yielded_off);
  EXPECT_LT(off, 0.0) << "without the look-ahead the person should reach the robot for this test to mean anything";
  EXPECT_EQ(yielded_off, 0);
  const double on = leastClearance({}, &yielded_on);
  EXPECT_GT(on, 0.0) << "the person reached the robot";
  EXPECT_GT(yielded_on, 0);
}

// The benchmark's variant 000 of `stopping` (speed 0.76 m/s, 4.6 cm off the nominal line): the
// law passed 0.11 m in front of the standing person, who then walked into its side (body
// clearance -0.27 m). A person who stopped is now seen along the way they would walk on
// (Disk::resume_velocity), so the robot passes behind them.
TEST(YieldToPeople, PassesBehindAPersonWhoStoppedNotInFrontOfThem) {
  int yielded = 0;
  const double least = leastClearance({}, &yielded, kScenes + "stopping.yaml", [](sim::Scenario* s) {
    core::ObstacleMotion& walk = s->setup.obstacle_motions.at(0);
    s->setup.obstacles.at(0).center = {4.4636, -3.3783};
    walk.start = s->setup.obstacles[0].center;
    walk.start_time = 10.2748;
    walk.legs = {{4.1865, {0.0, 0.7643}}, {8.0, {0.0, 0.0}}, {10.0, {0.0, 0.7643}}};
  });
  EXPECT_GE(least, 0.03) << "the person who walked on reached the robot (the issue's least body clearance: 3 cm)";
}

// The benchmark's variant 025 of `crossing_ahead`: a person at 0.47 m/s crosses the target's line
// 0.4 m ahead of the target. The moving disk was widened by r times its whole pace over v_bar,
// so p_r's zone reached past the target and the robot backed 0.29 m here (0.32 m in the
// benchmark's run, true ASE 0.134 m^2); widened by the speed at which the person closed on p_r,
// it gave way by less than half that (0.09 m in the benchmark's run), as clear of them; now not
// widened (the body's row holds the stretch they walk, personSpan).
TEST(YieldToPeople, GivesWayToAPersonCrossingAheadWithoutBackingOff) {
  double retreat = 0.0;
  const double least = crossingAhead({0.00603, 0.03869, 0.20140}, {3.9996, -3.3692}, 8.8804, 14.9667, 0.4677, &retreat);
  EXPECT_GE(least, 0.03) << "the crossing person came within 3 cm of the body";
  EXPECT_LT(retreat, 0.15) << "the robot backed from a person crossing ahead of the target";
}

// The benchmark's variant 044 of `crossing_ahead`: a person at 1.0 m/s crosses the target's line
// 0.4 m ahead of the target, their path 0.38 m clear of the waiting body. The body's row took
// them from where they were, closing at 0.87 m/s along the line of centres, and their disk was
// widened by r on top: the robot backed 0.29 m here (from 2 m away; 0.7 m behind the target in
// the benchmark's run). Now the row holds the body off the stretch they walk while the base
// stops (personSpan), which passes beside it, and the robot backs 0.07 m.
TEST(YieldToPeople, WaitsForAFastPersonCrossingAheadWithoutBackingOff) {
  double retreat = 0.0;
  const double least = crossingAhead({-0.1122, 0.1212, -0.2313}, {3.9701, -3.5501}, 12.8835, 6.9417, 1.0084, &retreat);
  EXPECT_GE(least, 0.03) << "the crossing person came within 3 cm of the body";
  EXPECT_LT(retreat, 0.12) << "the robot backed from a fast person crossing ahead of the target";
}

// The recommended law among people, closed loop on the AmigoBot's ramped dynamics: the
// pedestrian benchmark's overtaking scene (a person walks up from behind along the robot's line
// at 0.7 m/s, faster than the diamond's 0.3 m/s). Without the look-ahead (yield_horizon 0) the
// robot fled along the person's line and was caught; with it, it steps aside.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "amigobot_tracking/sim/scenario.h"

using namespace amigobot_tracking;

namespace {

const std::string kOvertaking = std::string(AMIGOBOT_SOURCE_DIR) + "/config/scenarios/pedestrians/overtaking.yaml";

// The least true clearance of the body from the person over the run, and how often the law yielded.
double leastClearance(const std::vector<std::string>& sets, int* yielded) {
  std::vector<std::string> all = {"controller.variant=recommended"};
  all.insert(all.end(), sets.begin(), sets.end());
  sim::Scenario s = sim::loadScenario(kOvertaking, all);
  const auto reference = s.makeReference();
  double least = std::numeric_limits<double>::infinity();
  *yielded = 0;
  sim::runClosedLoop(s.setup, *reference, [&](const sim::ClosedLoopStep& step) {
    for (const core::Disk& o : *step.obstacles)
      least = std::min(least, (step.pose.position() - o.center).norm() - s.setup.controller.robot_radius - o.radius);
    *yielded += step.output.active.yielding ? 1 : 0;
  });
  return least;
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

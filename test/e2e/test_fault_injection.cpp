// End to end, issue 25's fault injection (fault_injection_*.test): a target that dies with a
// last sample stamped 30 s ahead, and a second cmd_vel publisher at 100 Hz. Judged from the
// emulator's ground truth and its journal of the commands on the wire (judge.h).
// One case each of the test_e2e executable (main in test_e2e.cpp; the .test file picks it).
#include <gtest/gtest.h>

#include <geometry_msgs/Twist.h>

#include <cmath>
#include <string>

#include "circle_target.h"
#include "experiment.h"
#include "fault_run.h"
#include "judge.h"

using e2e::CircleTarget;
using e2e::EmulatorStatus;
using e2e::requiredParam;

namespace {

// config/tracking.yaml pose_timeout; the driver's next command slot (min_command_interval
// 0.05 s, found by its 20 ms poll), as in test_target_loss.cpp.
constexpr double kPoseTimeout = 0.5, kDriverSlot = 0.05 + 0.02;

}  // namespace

// The old ageOf() clamped a future stamp to age 0: tracking went on for 32 s to a frozen
// target. Now a sample stamped beyond future_stamp_tolerance is stale at once, and a silent
// stream ages on the receiver's clock: zero within pose_timeout + 0.1 s on the wire.
TEST(E2E, ATargetStampedAheadThenSilentStops) {
  e2e::GroundTruth truth(requiredParam<int>("status_port"));
  CircleTarget target;
  ASSERT_TRUE(e2e::trackingStarted(truth));

  const EmulatorStatus before = truth.truth();
  target.lastSampleAhead(30.0);
  EmulatorStatus stopped;
  ASSERT_TRUE(truth.waitForStandstill(10.0, &stopped)) << "the robot kept driving to a frozen target";
  ros::Duration(2.0).sleep();
  EXPECT_EQ(truth.truth().v, 0.0) << "the robot moved again without a live target";

  const auto commands = e2e::readCommandLog(requiredParam<std::string>("command_log"));
  const double zero_at = e2e::firstZeroSetpoint(commands, before.t);
  ASSERT_GE(zero_at, 0.0) << "no zero setpoint reached the emulator";
  EXPECT_LE(zero_at - before.t, kPoseTimeout + 0.1 + kDriverSlot) << "zero setpoint late";
  RecordProperty("zero_setpoint_ms", static_cast<int>(1e3 * (zero_at - before.t)));
  RecordProperty("standstill_ms", static_cast<int>(1e3 * (stopped.t - before.t)));
  std::printf("future-stamped target: zero on the wire %.0f ms, standstill %.0f ms after the last sample\n",
              1e3 * (zero_at - before.t), 1e3 * (stopped.t - before.t));
}

// A second publisher on cmd_vel at 100 Hz, commanding a spin on the spot, while tracking drives
// the circle: the driver keeps to the first publisher (core/command_lock.h), so no spin
// setpoint reaches the wire and the robot keeps its course.
TEST(E2E, ASecondCmdVelPublisherIsNotFollowed) {
  ros::NodeHandle nh;
  e2e::GroundTruth truth(requiredParam<int>("status_port"));
  CircleTarget target;
  ASSERT_TRUE(e2e::trackingStarted(truth));

  ros::Publisher intruder = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  geometry_msgs::Twist spin;
  spin.angular.z = -0.7;  // the circle turns left (counter-clockwise): tracking never asks this
  const EmulatorStatus from = truth.truth();
  ros::WallRate rate(100.0);
  for (int i = 0; i < 500 && ros::ok(); ++i) {  // 5 s
    intruder.publish(spin);
    rate.sleep();
  }
  const EmulatorStatus to = truth.truth();

  const auto pairs = e2e::setpointPairs(e2e::readCommandLog(requiredParam<std::string>("command_log")));
  int total = 0, followed = 0;
  for (const auto& c : pairs) {
    if (c.t < from.t || c.t > to.t) continue;
    ++total;
    if (c.v == 0.0 && std::abs(c.w - spin.angular.z) < 0.02) ++followed;
  }
  EXPECT_GT(total, 20) << "too few setpoints while the intruder published";
  EXPECT_EQ(followed, 0) << followed << " of " << total << " setpoints were the intruder's";
  EXPECT_GT(to.v, 0.05) << "the robot no longer drives the circle";
  RecordProperty("intruder_setpoints", followed);
  std::printf("second publisher: %d of %d setpoints on the wire were its\n", followed, total);
}

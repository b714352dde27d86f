// End to end: a person of the world file walks across the robot's path (person_crossing.test)
// and the real laser chain (laser_emulator -> Laser nodelet -> tracking) must see it. The
// target is this test's own: it stands at A, then drives along y = 0 at 0.15 m/s, started so
// that it passes the person's line x = 1.8 m 0.6 s after the person crosses y = 0 there (the
// emulator's clock, on which the person moves, is read from its status socket). Judged from
// the ground truth (world_judge.h): no contact with the person, and tracking again after.
// Why it fails when the laser does not see the person (laser_world:=room.yaml): an
// undisturbed robot lags the target by r = 0.3 m (2 s at 0.15 m/s), so its centre reaches
// x = 1.8 m 2.6 s after the person crossed y = 0 there. The robot at 0.15 m/s along x and the
// person at 0.6 m/s along y then pass at a least centre distance of
// 2.6 s x 0.15 x 0.6 / |(0.15, 0.6)| = 0.38 m, under R + r_person = 0.43 m: a contact of
// about -0.05 m. (Measured, timed 0 s instead of 0.6 s: -0.137 m blind, as this predicts
// (-0.14 m); -0.019 m seeing, the law of the day not stepping back from a person walking into
// the point it tracks.)
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <thread>

#include <ros/ros.h>

#include "amigobot_tracking/world/world.h"
#include "experiment.h"
#include "judge.h"
#include "target_publisher.h"
#include "world_judge.h"

using e2e::EmulatorStatus;
using e2e::requiredParam;

namespace {

const Eigen::Vector2d kStart(0.8, 0.0), kEnd(3.0, 0.0);  // [m] the target's line, y = 0
constexpr double kSpeed = 0.15;                           // [m/s] the target's
constexpr double kCrossX = 1.8;                           // [m] the person's line x = 1.8
constexpr double kTargetAfter = 0.6;                      // [s] the target passes it this long after the person
constexpr double kRobotRadius = 0.18;                     // [m] R

// The target's tf: at kStart until startAt(t), then along the line at kSpeed to kEnd.
class LineTarget {
 public:
  void startAt(double ros_time) { start_ = ros_time; }
  Eigen::Vector2d at(double ros_time) const {
    const double walked = std::clamp(kSpeed * (ros_time - start_.load()), 0.0, (kEnd - kStart).norm());
    return kStart + walked * (kEnd - kStart).normalized();
  }

 private:
  std::atomic<double> start_{std::numeric_limits<double>::infinity()};
  e2e::TargetPublisher publisher_{[this](double t) {
    const Eigen::Vector2d p = at(t);
    return amigobot_tracking::core::Pose2{p.x(), p.y(), 0.0};
  }};  // last: stops first
};

// The first emulator time >= `from` at which the person crosses y = 0 going north (10 ms steps).
double nextCrossing(const amigobot_tracking::core::ObstacleMotion& motion, double from) {
  for (double t = from; t < from + 100.0; t += 0.01) {
    if (motion.positionAt(t).y() < 0.0 && motion.positionAt(t + 0.01).y() >= 0.0) return t + 0.01;
  }
  return -1.0;
}

}  // namespace

TEST(E2E, APersonCrossingThePathIsNotTouched) {
  const auto room = amigobot_tracking::world::loadWorld(requiredParam<std::string>("world_file"));
  ASSERT_EQ(room.people.size(), 1u) << "person_crossing.yaml has one person";
  const auto& person = room.people[0];
  e2e::GroundTruth truth(requiredParam<int>("status_port"));
  LineTarget target;
  ASSERT_TRUE(truth.waitForRobotReady(60.0));
  ros::Duration(2.0).sleep();  // the robot settles on the standing target

  // The emulator's clock against ROS time, and the crossing the target is timed to.
  const EmulatorStatus now = truth.truth();
  const double to_emulator = now.t - ros::Time::now().toSec();  // emulator time = ROS time + this
  const double travel = (kCrossX - kStart.x()) / kSpeed;        // [s] the target from its start to the line
  const double crossing = nextCrossing(person.motion, now.t + travel + 1.0);
  ASSERT_GT(crossing, 0.0) << "the person never crosses y = 0";
  target.startAt(crossing + kTargetAfter - travel - to_emulator);
  const double stops = crossing + kTargetAfter + ((kEnd - kStart).norm() - (kCrossX - kStart.x())) / kSpeed;  // at kEnd
  const double end = stops + 6.0;
  std::printf("emulator t %.2f s: person crosses y = 0 at %.2f s; target starts at %.2f s, stops at %.2f s\n", now.t,
              crossing, crossing + kTargetAfter - travel, stops);

  double least = std::numeric_limits<double>::infinity(), least_at = 0.0, robot_x_at_crossing = 0.0;
  double worst_late_error = 0.0, final_error = 0.0;
  int contacts = 0;  // status samples with a contact (the first one is reported)
  EmulatorStatus s = now;
  while (s.t < end && ros::ok()) {
    if (!truth.tryTruth(&s)) continue;
    const double clearance = e2e::bodyClearance(room, s, kRobotRadius);
    const double to_person = (s.pose.position() - person.motion.positionAt(s.t)).norm() - kRobotRadius - person.radius;
    if (to_person < least) {
      least = to_person;
      least_at = s.t;
    }
    if (clearance <= 0.0 && contacts++ == 0) ADD_FAILURE() << "contact at emulator t " << s.t << " s: " << clearance << " m";
    if (std::abs(s.t - crossing) < 0.05) robot_x_at_crossing = s.pose.x;
    // Tracking again: from 4 s after the target stopped, |p_d - p_r| (truth) within the bound.
    const double error = (target.at(s.t - to_emulator) - e2e::offsetPoint(s, e2e::kOffset)).norm();
    if (s.t > stops + 4.0) worst_late_error = std::max(worst_late_error, error);
    final_error = error;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::printf("least body clearance to the person %.3f m at emulator t %.2f s (%.2f s after it crossed); robot x "
              "%.2f m when the person crossed; worst |e| from 4 s after the stop %.3f m, final %.3f m\n",
              least, least_at, least_at - crossing, robot_x_at_crossing, worst_late_error, final_error);
  RecordProperty("least_clearance_to_person_m", std::to_string(least));
  RecordProperty("least_after_crossing_s", std::to_string(least_at - crossing));
  RecordProperty("robot_x_at_crossing_m", std::to_string(robot_x_at_crossing));
  RecordProperty("worst_late_error_m", std::to_string(worst_late_error));
  EXPECT_GT(least, 0.0) << "the robot's body touched the person";
  EXPECT_LT(robot_x_at_crossing, kCrossX) << "the person crossed ahead of the robot";
  EXPECT_LT(least, 0.5) << "the person passed close to the robot (else the test proves nothing)";
  EXPECT_LT(worst_late_error, e2e::kRhoInf + e2e::kPoseLagTolerance) << "no tracking after the person had gone";
}

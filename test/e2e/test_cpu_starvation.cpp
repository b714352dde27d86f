// End to end, issue 24 item 2: CPU starvation (fault_cpu_starvation.test). The nodelet manager
// that holds the driver, tracking and Laser nodelets is SIGSTOPped: on the Odroid a runaway
// process at higher priority, thermal throttling or swapping starves the whole ROS side at
// once, the driver included, so the driver's own cmd_vel_timeout cannot help (it is starved
// too; watchdog.test covers a silent tracking node with a live driver). What remains is the
// robot's firmware watchdog: no command for `watchdog` (2 s) stops the wheels. Busy loops at
// a higher priority would model it too but would starve the emulator and this judge with it
// on a 2-core machine; SIGSTOP starves exactly the robot's computer and nothing else.
// Judged from the emulator's ground truth (its watchdog flag, v, w) and its command journal;
// the nodelets must outlive the stall: the manager lists the same ones, their loaders the same pids.
#include <gtest/gtest.h>

#include <nodelet/NodeletList.h>
#include <signal.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "circle_target.h"
#include "experiment.h"
#include "fault_run.h"
#include "judge.h"

using e2e::CircleTarget;
using e2e::EmulatorStatus;
using e2e::requiredParam;

namespace {

// aria/robot_params.h watchdog (the AmigoBot firmware's 2 s); the emulator checks it every
// physics step (10 ms), so the trip is due 2 s after the last command before the stall.
constexpr double kFirmwareWatchdog = 2.0;
// [s] well past the watchdog and past the nodelet bonds' 4 s heartbeat timeout: with bonds,
// starved for 3.5 s, every `nodelet load` client's bond to the manager broke, the clients
// exited and the manager unloaded driver, tracking and Laser on SIGCONT, and the stack never
// came back. The launch files' loaders now run with --no-bond (launch/include/robot.launch).
constexpr double kStarve = 5.0;

// The nodelets the manager holds, sorted; empty when it does not answer.
std::vector<std::string> managerNodelets(const std::string& manager) {
  nodelet::NodeletList list;
  if (!ros::service::call(manager + "/list", list)) return {};
  std::sort(list.response.nodelets.begin(), list.response.nodelets.end());
  return list.response.nodelets;
}

}  // namespace

TEST(E2E, AStarvedStackIsStoppedByTheFirmwareWatchdog) {
  e2e::GroundTruth truth(requiredParam<int>("status_port"));
  CircleTarget target;
  ASSERT_TRUE(e2e::trackingStarted(truth));
  const int manager = e2e::nodePid("/amigobot_manager");
  ASSERT_GT(manager, 0);
  // Each nodelet's loader is a node of the nodelet's name (tracker.launch, robot.launch).
  const std::vector<std::string> nodelets = managerNodelets("/amigobot_manager");
  ASSERT_GE(nodelets.size(), 2u) << "the manager does not hold the driver and tracking nodelets";
  std::vector<int> loaders;
  for (const std::string& name : nodelets) loaders.push_back(e2e::nodePid(name));

  const EmulatorStatus before = truth.truth();
  ASSERT_EQ(::kill(manager, SIGSTOP), 0);
  EmulatorStatus tripped, stopped;
  const bool trip = e2e::waitFor([&] { return truth.tryTruth(&tripped) && tripped.watchdog; }, kStarve);
  const bool stood = truth.waitForStandstill(kStarve, &stopped);
  ros::WallDuration(std::max(0.0, kStarve - (truth.truth().t - before.t))).sleep();
  const EmulatorStatus still = truth.truth();
  ASSERT_EQ(::kill(manager, SIGCONT), 0);  // before any ASSERT can leave the manager stopped
  ASSERT_TRUE(trip) << "the firmware watchdog never tripped";
  ASSERT_TRUE(stood) << "the robot kept driving while its computer was starved";
  EXPECT_EQ(still.v, 0.0) << "the robot moved while its computer was starved";

  const EmulatorStatus resumed_from = truth.truth();
  ASSERT_TRUE(e2e::waitFor([&] { return truth.truth().v > 0.1; }, 30.0)) << "tracking never resumed";
  const EmulatorStatus resumed = truth.truth();
  ros::Duration(3.0).sleep();
  EXPECT_GT(truth.truth().v, 0.05) << "not tracking at the end";
  EXPECT_FALSE(truth.truth().watchdog) << "the watchdog is still tripped while commands flow";
  EXPECT_EQ(e2e::nodePid("/amigobot_manager"), manager) << "the nodelet manager died";
  EXPECT_EQ(managerNodelets("/amigobot_manager"), nodelets) << "the manager unloaded nodelets after the stall";
  for (std::size_t k = 0; k < nodelets.size(); ++k) {
    EXPECT_EQ(e2e::nodePid(nodelets[k]), loaders[k]) << "the loader of " << nodelets[k] << " exited or restarted";
  }

  // The last command before the stall: the watchdog counts from there.
  const auto commands = e2e::readCommandLog(requiredParam<std::string>("command_log"));
  double last_command = -1.0;
  for (const auto& c : commands) {
    if (c.t <= before.t + 0.05) last_command = c.t;  // one driver slot: it may have sent just then
  }
  ASSERT_GE(last_command, 0.0);
  EXPECT_LE(tripped.t - before.t, kFirmwareWatchdog + 0.1) << "watchdog trip late";
  RecordProperty("watchdog_trip_ms", static_cast<int>(1e3 * (tripped.t - before.t)));
  RecordProperty("standstill_ms", static_cast<int>(1e3 * (stopped.t - before.t)));
  RecordProperty("resume_ms", static_cast<int>(1e3 * (resumed.t - resumed_from.t)));
  std::printf("CPU starvation %.1f s: firmware watchdog tripped %.0f ms after SIGSTOP (%.0f ms after the last "
              "command), standstill %.0f ms; driving again %.0f ms after SIGCONT; %zu nodelets kept\n", kStarve,
              1e3 * (tripped.t - before.t), 1e3 * (tripped.t - last_command), 1e3 * (stopped.t - before.t),
              1e3 * (resumed.t - resumed_from.t), nodelets.size());
}

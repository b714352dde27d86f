// One command sequence (20 Hz, piecewise constant: start, curve, reversal, spin, stop) through
// the robot emulator's firmware and through the simulator's closed loop (a law that replays
// the sequence), both on the AmigoBot's dynamics: the two bodies must follow one trajectory.
//
// Tolerance 5 mm and 0.005 rad: both sides run the one actuator model with the same command
// arrivals (the emulator's VEL/RVEL at t_k after its physics reached t_k; the simulator's
// command at its step t_k), so only the pose integration differs (the emulator's 10 ms physics
// steps against the simulator's 5 ms sub-steps, both on each sub-step's mean velocity; their
// difference is ~0.1 mm here). A side without the model misses by far more: the latency alone
// moves the body 0.1 s x 0.3 m/s = 3 cm, the ramps 0.15 m (checked below with an ideal body, and
// with ramps alone).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/aria/emulator.h"
#include "amigobot_tracking/core/law/law_registry.h"
#include "amigobot_tracking/core/reference/reference.h"
#include "amigobot_tracking/sim/closed_loop.h"
#include "aria_packets.h"

using namespace amigobot_tracking;
using amigobot_test::openRobot;
using amigobot_test::packetOf;

namespace {

constexpr double kTrackingPeriod = 0.05;  // [s] the tracking nodelet's 20 Hz
constexpr double kDuration = 9.0;  // [s]
constexpr double kRadPerDegree = M_PI / 180.0;

// The sequence in the firmware's units (VEL mm/s, RVEL deg/s), so both sides see the same numbers.
struct CommandSegment {
  double until;  // [s]
  int vel_mm_s, rvel_deg_s;
};
const std::vector<CommandSegment> kCommands = {
    {2.0, 300, 0}, {4.0, 200, 60}, {5.5, -200, 0}, {6.5, 0, -120}, {7.0, 250, 30}, {kDuration + 1.0, 0, 0}};

core::Twist2 commandAt(double t) {
  for (const CommandSegment& s : kCommands)
    if (t < s.until - 1e-9) return {s.vel_mm_s * 1e-3, s.rvel_deg_s * kRadPerDegree};
  return {};
}

// The simulator's law: the sequence, whatever the target. It stands in the registry's
// mrpt_reactive slot (a law above core, built by a provided factory) for this test only.
class Replay : public core::ControlLaw {
 public:
  std::unique_ptr<core::ControlLaw> clone() const override { return std::make_unique<Replay>(); }
  std::string name() const override { return "mrpt_reactive"; }
  core::ControllerOutput step(double t, const core::PoseSample&, const core::TargetSample&,
                              const std::vector<core::Disk>&) override {
    core::ControllerOutput out;
    out.valid = true;
    out.u = commandAt(t);
    return out;
  }
  void reset() override {}
  void setConfig(const core::ControllerConfig& config) override { config_ = config; }
  const core::ControllerConfig& config() const override { return config_; }
  const core::DiamondSet& diamond() const override { return diamond_; }

 private:
  core::ControllerConfig config_;
  core::DiamondSet diamond_{10.0, 10.0};
};

std::vector<core::Pose2> emulatorTrajectory() {
  aria::RobotEmulator robot({});
  openRobot(robot, 0.0);
  robot.handle(packetOf(aria::commandPacket(aria::Command::kEnable, 1)), 0.0);
  std::vector<core::Pose2> poses;
  for (int k = 0; k * kTrackingPeriod <= kDuration + 1e-9; ++k) {
    const double t = k * kTrackingPeriod;
    robot.advance(t);
    poses.push_back(robot.truePose());
    const core::Twist2 u = commandAt(t);
    robot.handle(packetOf(aria::commandPacket(aria::Command::kVel, static_cast<int>(std::lround(u.v * 1e3)))), t);
    robot.handle(packetOf(aria::commandPacket(aria::Command::kRVel,
                                              static_cast<int>(std::lround(u.omega / kRadPerDegree)))), t);
  }
  return poses;
}

// ideal: no model; no_delay: the ramps without the cycle and the latency (the emulator before
// the model).
std::vector<core::Pose2> simulatorTrajectory(bool ideal, bool no_delay = false) {
  sim::ClosedLoopSetup setup;
  setup.controller.v_max = setup.controller.w_max = 10.0;
  setup.duration = kDuration;
  setup.control_period = kTrackingPeriod;
  setup.law = "mrpt_reactive";  // the slot Replay is provided in
  const core::LawFactory before =
      core::provideLaw("mrpt_reactive", [](const core::LawSetup&) { return std::make_unique<Replay>(); });
  setup.dynamics.ideal = ideal;  // firmware: the AmigoBot's values, as the emulator's
  if (no_delay) setup.dynamics.limits.cycle = setup.dynamics.limits.latency = 0.0;
  const core::CircleReference reference({0.0, 0.0}, 0.5, 10.0);
  std::vector<core::Pose2> poses;
  sim::runClosedLoop(setup, reference, [&](const sim::ClosedLoopStep& step) { poses.push_back(step.pose); });
  core::provideLaw("mrpt_reactive", before);
  return poses;
}

double largestGap(const std::vector<core::Pose2>& a, const std::vector<core::Pose2>& b, double* heading_gap) {
  double gap = 0.0;
  *heading_gap = 0.0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    gap = std::max(gap, std::hypot(a[i].x - b[i].x, a[i].y - b[i].y));
    *heading_gap = std::max(*heading_gap, std::abs(std::remainder(a[i].theta - b[i].theta, 2.0 * M_PI)));
  }
  return gap;
}

}  // namespace

TEST(ActuatorParity, EmulatorAndSimulatorFollowOneTrajectory) {
  const std::vector<core::Pose2> emulator = emulatorTrajectory();
  const std::vector<core::Pose2> simulator = simulatorTrajectory(false);
  ASSERT_EQ(emulator.size(), simulator.size());
  ASSERT_GT(std::hypot(emulator.back().x, emulator.back().y), 0.5) << "the sequence should move the robot";
  double heading_gap = 0.0;
  const double gap = largestGap(emulator, simulator, &heading_gap);
  EXPECT_LT(gap, 0.005);
  EXPECT_LT(heading_gap, 0.005);
  // The test can tell: a body without the model is far off.
  const double ideal_gap = largestGap(emulator, simulatorTrajectory(true), &heading_gap);
  EXPECT_GT(ideal_gap, 0.05);
  EXPECT_GT(largestGap(emulator, simulatorTrajectory(false, true), &heading_gap), 0.02);
  RecordProperty("largest_gap_mm", std::to_string(gap * 1e3));
  std::printf("largest position gap %.3f mm (firmware both sides), %.1f mm against an ideal body\n", gap * 1e3,
              ideal_gap * 1e3);
}

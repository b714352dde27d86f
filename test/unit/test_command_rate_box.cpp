// The recommended law's rate box (safety_filter.cpp, command_rise_time): the command moves by
// at most (v_bar, w_bar) h / T per step while every barrier row holds, and gives way where a
// barrier needs more. Under 3 cm of target noise the law without it followed the noise (|dv|
// up to 0.52 m/s and |dw| up to 1.59 rad/s in one 50 ms step of the clutter suite).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "amigobot_tracking/core/reference/reference.h"
#include "amigobot_tracking/core/law/safety_filter.h"
#include "amigobot_tracking/sim/closed_loop.h"

using namespace amigobot_tracking;

namespace {

core::SafetyFilterInput boxedInput(const core::Twist2& previous, const core::Twist2& nominal, double dv, double dw) {
  core::SafetyFilterInput in;
  in.pose = {0.0, 0.0, 0.0};
  in.offset = 0.3;
  in.robot_radius = 0.18;
  in.gamma = 5.333;
  in.body_rows = true;
  in.previous = previous;
  in.nominal = nominal;
  in.max_change = {dv, dw};
  return in;
}

struct Jumps {
  double dv = 0.0, dw = 0.0, true_ase = 0.0;
  std::uint64_t contacts = 0, widenings = 0;
};

// A target that parks beside a pillar, sampled at 10 Hz with 3 cm of noise (the clutter
// suite's pillar class without its spread): the largest per-step command change.
Jumps noisyPillar(double rise_time) {
  sim::ClosedLoopSetup setup;
  setup.law = "recommended";
  setup.controller.recommended.command_rise_time = rise_time;
  setup.controller.body_safe = true;
  core::Disk pillar;
  pillar.center = {2.0, 0.6};
  pillar.radius = 0.25;
  setup.obstacles = {pillar};
  setup.duration = 25.0;
  setup.control_period = 0.05;
  setup.sample_period = 0.1;
  setup.sensor.noise_std = 0.03;
  setup.sensor.seed = 7;
  const core::SplineReference reference({{0.6, 0.0}, {2.0, 0.0}, {2.6, 0.6}}, 12.0);
  Jumps r;
  core::Twist2 last{NAN, NAN};
  auto observe = [&](const sim::ClosedLoopStep& step) {
    if (std::isfinite(last.v) && step.output.valid) {
      r.dv = std::max(r.dv, std::abs(step.output.u.v - last.v));
      r.dw = std::max(r.dw, std::abs(step.output.u.omega - last.omega));
    }
    if (step.output.valid) last = step.output.u;
  };
  const sim::ClosedLoopSummary s = sim::runClosedLoop(setup, reference, observe);
  r.true_ase = s.metrics.true_ase;
  r.contacts = s.metrics.body_collisions + s.metrics.offset_collisions;
  r.widenings = s.envelope_widenings;
  return r;
}

}  // namespace

TEST(CommandRateBox, HoldsTheCommandWithinTheBoxInFreeSpace) {
  const core::DiamondSet diamond(0.3, 0.8);
  // A nominal across the diamond from the last command: one step reaches only the box's edge
  // (up to the slack's leak, K^2 |pull| / slack weight: 1e-4 here).
  const auto in = boxedInput({0.2, -0.2}, {-0.15, 0.3}, 0.06, 0.16);
  const core::SafetyFilterResult r = core::safetyFilter(in, diamond, {});
  ASSERT_TRUE(r.solved);
  EXPECT_NEAR(r.u.v, 0.2 - 0.06, 1e-3);
  EXPECT_NEAR(r.u.omega, -0.2 + 0.16, 1e-3);
  // With no box the same nominal is reached at once (inside the diamond: it is the answer).
  auto free = in;
  free.max_change = {INFINITY, INFINITY};
  const core::SafetyFilterResult f = core::safetyFilter(free, diamond, {});
  EXPECT_NEAR(f.u.v, -0.15, 1e-9);
  EXPECT_NEAR(f.u.omega, 0.3, 1e-9);
}

TEST(CommandRateBox, GivesWayWhereABarrierNeedsMore) {
  const core::DiamondSet diamond(0.3, 0.8);
  // Full speed at a disk whose barrier row allows far less than v_prev - dv: the box gives
  // way (v well below the box's floor, 0.24) and the barrier is short by a tenth at most of
  // what the box would have cost it.
  core::Disk disk;
  disk.center = {0.3 + 0.18 + 0.2 + 0.02, 0.0};  // p_r's disk 2 cm from contact
  disk.radius = 0.2;
  const auto in = boxedInput({0.3, 0.0}, {0.3, 0.0}, 0.06, 0.16);
  const core::SafetyFilterResult boxed = core::safetyFilter(in, diamond, {disk});
  auto free = in;
  free.max_change = {INFINITY, INFINITY};
  const core::SafetyFilterResult unboxed = core::safetyFilter(free, diamond, {disk});
  ASSERT_TRUE(boxed.solved && unboxed.solved);
  std::printf("barrier alone: v %.4f; with the box: v %.4f, slack %.5f\n", unboxed.u.v, boxed.u.v, boxed.slack);
  ASSERT_LT(unboxed.u.v, 0.3 - 2 * 0.06) << "the scene must ask for more than the box";
  EXPECT_LT(boxed.u.v, 0.3 - 0.06 - 0.5 * (0.3 - 0.06 - unboxed.u.v)) << "the box did not give way";
  EXPECT_LE(boxed.slack, 0.1 * (0.3 - 0.06 - unboxed.u.v) + 1e-9);
  EXPECT_LT(unboxed.slack, 1e-5);
}

TEST(CommandRateBox, StartsFromTheShrunkDiamondUnderAHeldCommand) {
  // The diamond shrank (reconfigure) under a command held at the old corner: the box is
  // centred on that command scaled into the new diamond, so it needs no slack (a slack would
  // loosen every barrier row as well).
  const core::DiamondSet diamond(0.1, 0.8);
  const auto in = boxedInput({0.3, 0.0}, {0.3, 0.0}, 0.01, 0.01);
  const core::SafetyFilterResult r = core::safetyFilter(in, diamond, {});
  ASSERT_TRUE(r.solved);
  EXPECT_LE(diamond.normalizedNorm(r.u), 1.0 + 1e-9);
  EXPECT_NEAR(r.u.v, 0.1, 1e-6);
  EXPECT_LT(r.slack, 1e-9);
}

TEST(CommandRateBox, KeepsNoisyCommandsSmooth) {
  const double rise = core::ControllerConfig().recommended.command_rise_time;
  const Jumps boxed = noisyPillar(rise), unboxed = noisyPillar(0.0);
  std::printf("box %.2f s: |dv| %.3f m/s, |dw| %.3f rad/s, ASE %.4f; none: |dv| %.3f, |dw| %.3f, ASE %.4f\n", rise,
              boxed.dv, boxed.dw, boxed.true_ase, unboxed.dv, unboxed.dw, unboxed.true_ase);
  const double dv = 0.3 * 0.05 / rise, dw = 0.8 * 0.05 / rise;
  EXPECT_GT(unboxed.dv, 2.0 * dv) << "the scene no longer shows the noise in the command";
  EXPECT_LE(boxed.dv, 1.5 * dv);
  EXPECT_LE(boxed.dw, 1.5 * dw);
  EXPECT_LT(boxed.true_ase, 1.25 * unboxed.true_ase);
  EXPECT_EQ(boxed.contacts, 0u);
  EXPECT_EQ(boxed.widenings, 0u);
}

TEST(CommandRateBox, IsAValidatedGain) {
  core::ControllerConfig c;
  c.recommended.command_rise_time = -0.1;
  EXPECT_NE(c.validate().find("command_rise_time"), std::string::npos) << c.validate();
  c.recommended.command_rise_time = 0.0;
  EXPECT_EQ(c.validate(), "");
}

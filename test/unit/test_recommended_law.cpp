// The recommended law (core/law/recommended_law.h) in the offline closed loop, class by class
// (clutter_scenes.h): no contact, inside the diamond, no widening of rho by the guard, no NaN,
// no orbit, few side flips, and a true ASE no worse than the paper's law's. The paper's law
// is run on the same scenes, and where it fails a check the test says so (so the checks can
// fail). Plus the continuity of the command in the geometry and the rho law (13').
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/core/law/navigation_field.h"
#include "amigobot_tracking/core/law/recommended_law.h"
#include "amigobot_tracking/core/reference/reference.h"
#include "amigobot_tracking/sim/closed_loop.h"
#include "amigobot_tracking/sim/scenario.h"
#include "amigobot_tracking/sim/simulator.h"
#include "clutter_scenes.h"

using namespace amigobot_tracking;
using clutter_scenes::Scene;

namespace {

struct Outcome {
  std::uint64_t contacts = 0, diamond_violations = 0, widenings = 0, nan = 0;
  double orbit_turns = 0.0;  // largest net winding of p_r around one disk [turns]
  int side_flips = 0;
  double true_ase = 0.0;
  double jump = 0.0;  // largest one-step command change, as a share of the diamond: max(|dv|/v_bar, |dw|/w_bar)
};

sim::ClosedLoopSetup setupOf(const Scene& scene, const std::string& law) {
  sim::ClosedLoopSetup setup;
  setup.controller.v_max = scene.v_max;
  setup.controller.w_max = scene.w_max;
  setup.controller.moving_obstacles = !scene.velocities.empty();
  setup.initial_pose = {0.0, 0.0, 0.0};
  setup.obstacles = scene.disks;
  for (size_t j = 0; j < scene.velocities.size(); ++j)
    setup.obstacle_motions.push_back(sim::constantMotion(scene.disks[j].center, scene.velocities[j]));
  setup.duration = scene.duration;
  setup.control_period = 0.05;
  setup.law = law;
  return setup;
}

Outcome run(const Scene& scene, const std::string& law) {
  const sim::ClosedLoopSetup setup = setupOf(scene, law);
  const core::SplineReference reference(scene.waypoints, scene.spline_duration);
  std::vector<double> winding(scene.disks.size(), 0.0), last_angle(scene.disks.size(), NAN);
  std::vector<int> last_side(scene.disks.size(), 0);
  Eigen::Vector2d last_p_r(NAN, NAN);
  std::vector<Eigen::Vector2d> last_center(scene.disks.size());
  Outcome o;
  const double zone = setup.controller.effectiveRadius() + setup.controller.delta;
  auto observe = [&](const sim::ClosedLoopStep& step) {
    const Eigen::Vector2d p = step.p_r_true;
    size_t nearest = 0;
    double nearest_clearance = INFINITY;
    for (size_t j = 0; j < step.obstacles->size(); ++j) {
      const core::Disk& d = (*step.obstacles)[j];
      const double angle = std::atan2(p.y() - d.center.y(), p.x() - d.center.x());
      if (!std::isnan(last_angle[j])) winding[j] += core::wrapAngle(angle - last_angle[j]);
      last_angle[j] = angle;
      const double c = (p - d.center).norm() - d.radius;
      if (c < nearest_clearance) nearest_clearance = c, nearest = j;
    }
    // The side: the sense in which p_r moves around the nearest disk (relative to the disk,
    // which may move), while near it and moving round it at 2 cm/s or more. A move straight
    // towards or away from the disk has no side (counted by |move| instead, the rounding of a
    // backing-off robot's 0.2 mm sideways drift counted 3 flips on the pillar).
    if (!std::isnan(last_p_r.x()) && nearest_clearance < zone) {
      const Eigen::Vector2d& center = (*step.obstacles)[nearest].center;
      const Eigen::Vector2d move = p - last_p_r - (center - last_center[nearest]), away = p - center;
      const double around = (away.x() * move.y() - away.y() * move.x()) / std::max(away.norm(), 1e-9);
      if (std::abs(around) > 0.02 * setup.control_period) {
        const int side = around > 0.0 ? 1 : -1;
        if (last_side[nearest] != 0 && side != last_side[nearest]) ++o.side_flips;
        last_side[nearest] = side;
      }
    }
    last_p_r = p;
    for (size_t j = 0; j < step.obstacles->size(); ++j) last_center[j] = (*step.obstacles)[j].center;
  };
  const sim::ClosedLoopSummary summary = sim::runClosedLoop(setup, reference, observe);
  o.contacts = summary.metrics.body_collisions + summary.metrics.offset_collisions;
  o.diamond_violations = summary.diamond_violations;
  o.widenings = summary.envelope_widenings;
  o.nan = summary.metrics.nan_count + summary.invalid_steps;
  for (double w : winding) o.orbit_turns = std::max(o.orbit_turns, std::abs(w) / (2.0 * M_PI));
  o.true_ase = summary.metrics.true_ase;
  o.jump = std::max(summary.metrics.max_delta_v / setup.controller.v_max,
                    summary.metrics.max_delta_omega / setup.controller.w_max);
  return o;
}

// The checks of issue 20 that `o` fails, given the paper's ASE on the same scene.
std::vector<std::string> failures(const Outcome& o, double paper_ase) {
  std::vector<std::string> f;
  if (o.contacts) f.push_back("contacts " + std::to_string(o.contacts));
  if (o.diamond_violations) f.push_back("diamond violations " + std::to_string(o.diamond_violations));
  if (o.widenings) f.push_back("widenings " + std::to_string(o.widenings));
  if (o.nan) f.push_back("NaN " + std::to_string(o.nan));
  if (!(o.orbit_turns < 1.0)) f.push_back("orbit turns " + std::to_string(o.orbit_turns));
  if (o.side_flips > 4) f.push_back("side flips " + std::to_string(o.side_flips));
  // Chatter towards and away from a disk has no side: it shows as the command's jumps (the
  // paper's law in the U: corner to corner of the diamond, 2.0; the recommended law's box allows h / command_rise_time = 0.2).
  if (!(o.jump <= 0.3)) f.push_back("command jump " + std::to_string(o.jump) + " of the diamond");
  if (!(o.true_ase <= paper_ase * (1.0 + 1e-9))) f.push_back("ASE " + std::to_string(o.true_ase) + " > paper's");
  return f;
}

std::string joined(const std::vector<std::string>& v) {
  std::ostringstream s;
  for (const std::string& x : v) s << x << "; ";
  return s.str();
}

// One step's input: the robot at the origin facing +x, p_r ahead of it, e and the rest to be set.
core::RecommendedInput atOrigin(const core::ControllerConfig& config) {
  core::RecommendedInput in;
  in.pose = {0.0, 0.0, 0.0};
  in.p_r = {config.offset, 0.0};
  return in;
}

}  // namespace

TEST(RecommendedLaw, PassesEveryClutterClassWhereThePaperLawFails) {
  std::map<std::string, std::vector<std::string>> paper_failures;
  for (const Scene& scene : clutter_scenes::clutterScenes()) {
    const Outcome paper = run(scene, "paper");
    const Outcome mine = run(scene, "recommended");
    std::printf("%-12s ASE paper %.4f recommended %.4f | widenings %llu / %llu | flips %d / %d | turns %.2f / %.2f"
                " | jump %.2f / %.2f\n", scene.name.c_str(), paper.true_ase, mine.true_ase,
                (unsigned long long)paper.widenings, (unsigned long long)mine.widenings, paper.side_flips,
                mine.side_flips, paper.orbit_turns, mine.orbit_turns, paper.jump, mine.jump);
    EXPECT_TRUE(failures(mine, paper.true_ase).empty()) << scene.name << ": " << joined(failures(mine, paper.true_ase));
    // The paper's law against the recommended one's ASE: where the paper's law is worse.
    paper_failures[scene.name] = failures(paper, mine.true_ase);
  }
  // The checks bite: the paper's law fails them in these classes (measured).
  for (const char* name : {"pillar_park", "u_behind", "u_through", "doorway", "fast_target"})
    EXPECT_FALSE(paper_failures[name].empty()) << name << ": the paper's law passed every check";
}

// A disk sliding toward another until their zones join (the group threshold of the escape,
// r_a + r_b + 2 (R + r + delta) = 1.76 m here, is crossed on the way): the recommended command
// changes by a small amount per millimetre, with no step anywhere.
TEST(RecommendedLaw, CommandIsContinuousAsADiskJoinsAGroup) {
  core::ControllerConfig config;
  config.law = "recommended";
  const core::DiamondSet diamond(config.v_max, config.w_max);
  core::RecommendedInput in;
  in.pose = {0.0, 0.3, 0.0};
  in.p_r = {0.3, 0.3};
  in.e = Eigen::Vector2d(3.2, -0.3);  // the target behind the pair, off its axis
  in.rho = 4.0;
  double largest_jump = 0.0;
  core::RecommendedCommand last;
  for (int k = 0; k <= 200; ++k) {
    const double gap = 1.90 - 0.001 * k;  // centre distance 1.90 m .. 1.70 m
    const std::vector<core::Disk> disks = {clutter_scenes::disk(2.0, 0.5 * gap, 0.15),
                                           clutter_scenes::disk(2.0, -0.5 * gap, 0.15)};
    const core::RecommendedCommand c = core::recommendedCommand(config, diamond, in, disks);
    ASSERT_TRUE(c.valid);
    ASSERT_TRUE(diamond.contains(c.u, 1e-9));
    if (k > 0) largest_jump = std::max(largest_jump, std::hypot(c.u.v - last.u.v, config.offset * (c.u.omega - last.u.omega)));
    last = c;
  }
  EXPECT_LT(largest_jump, 0.01);  // [m/s] per mm; the escape jumped 0 -> 0.305 m/s here
}

// Small state changes: the pose moved across the pillar's shadow, close to its zone, where the
// field turns fastest. Continuity, not only a small step: the largest change per step shrinks
// with the step (a jump would not).
TEST(RecommendedLaw, CommandIsContinuousInThePose) {
  core::ControllerConfig config;
  config.law = "recommended";
  config.recommended.body_margin = 0.0;  // the sweep below is laid out round the bare body's zone
  const core::DiamondSet diamond(config.v_max, config.w_max);
  const std::vector<core::Disk> disks = {clutter_scenes::disk(1.5, 0.0, 0.3)};
  const Eigen::Vector2d target(3.5, 0.0);
  bool bending = false;
  auto largestJump = [&](double step) {
    double largest = 0.0;
    core::RecommendedCommand last;
    for (int k = 0; k * step <= 0.2; ++k) {
      core::RecommendedInput in;
      in.pose = {0.65, -0.1 + step * k, 0.0};  // p_r 7 cm from the pillar's zone, where the field bends
      in.p_r = in.pose.position() + Eigen::Vector2d(config.offset, 0.0);
      in.e = target - in.p_r;
      in.rho = 4.0;
      const core::RecommendedCommand c = core::recommendedCommand(config, diamond, in, disks);
      EXPECT_TRUE(c.valid);
      bending = bending || c.blend > 0.5;
      if (k > 0) largest = std::max(largest, std::hypot(c.u.v - last.u.v, config.offset * (c.u.omega - last.u.omega)));
      last = c;
    }
    return largest;
  };
  const double coarse = largestJump(0.002), fine = largestJump(0.0005);
  EXPECT_LT(coarse, 0.05);        // [m/s] per 2 mm
  EXPECT_LT(fine, 0.5 * coarse);  // about a quarter for a Lipschitz command
  EXPECT_TRUE(bending) << "the field never bent in the sweep: it tests nothing";
  EXPECT_GT(coarse, 1e-4) << "the command did not change across the sweep: it tests nothing";
}

// While rho is still wide (rho_0 = 1 m) the pull of (9) is weak, about 0.6 |e| with Section
// 5.3's gains; the recommended law drives with at least the gain (9) has at steady state,
// k_d / rho_inf = 1.5 1/s. The extra drive is along e_hat only and is not counted in u_track, so
// (13')'s shortfall is what it was; off course, the law converges several times faster.
TEST(RecommendedLaw, DrivesAtLeastAtTheSteadyStateGainWhileRhoIsWide) {
  core::ControllerConfig config;
  config.law = "recommended";
  const core::DiamondSet diamond(config.v_max, config.w_max);
  core::RecommendedInput in = atOrigin(config);
  in.e = {0.1, 0.0};
  in.rho = 1.0;
  const core::RecommendedCommand c = core::recommendedCommand(config, diamond, in, {});
  ASSERT_TRUE(c.valid);
  const double paper_pull = config.k_d * std::atanh(0.1) + config.lambda * (1.0 - config.rho_inf) * 0.1;
  EXPECT_NEAR(c.u_track.x(), paper_pull, 1e-12);                          // (13')'s u_track unchanged
  EXPECT_NEAR(c.u_nom.x(), config.k_d / config.rho_inf * 0.1, 1e-12);     // 0.15 m/s, not 0.060
  EXPECT_NEAR(c.u.v, c.u_nom.x(), 1e-6);                                  // free space, inside the diamond
  EXPECT_EQ(c.shortfall, 0.0);

  // Closed loop: 0.2 m behind the start of a straight course driven at 0.1 m/s, no obstacles.
  auto ase = [](const std::string& law) {
    sim::ClosedLoopSetup setup;
    setup.initial_pose = {-0.2, 0.0, 0.0};
    setup.duration = 12.0;
    setup.control_period = 0.05;
    setup.law = law;
    const core::SplineReference reference({{0.3, 0.0}, {1.5, 0.0}}, 12.0);
    const sim::ClosedLoopSummary s = sim::runClosedLoop(setup, reference);
    EXPECT_EQ(s.envelope_widenings, 0u);
    return s.metrics.true_ase;
  };
  const double recommended = ase("recommended"), paper = ase("paper");
  std::printf("off-course start: true ASE recommended %.4f, paper %.4f\n", recommended, paper);
  EXPECT_LT(recommended, 0.6 * paper);
}

// 3 cm of noise on a target sampled at 10 Hz: the estimator's v_hat is off by about 0.5 m/s
// from one sample to the next. Fed forward as it is (max_acceleration 0), it swung the command
// between the diamond's corners; followed at most a_max h per step, the command moves by far
// less per step and the tracking is no worse. A target accelerating within a_max is followed.
// The noise also reaches rho_inf = 0.1 m: without the noise floor of rho (controller.h) the guard
// widened rho twice in this run.
TEST(RecommendedLaw, FeedForwardFollowsTheTargetNotTheNoise) {
  auto run = [](double a_max, double noise) {
    sim::ClosedLoopSetup setup;
    setup.initial_pose = {0.0, 0.0, 0.0};
    setup.duration = 20.0;
    setup.control_period = 0.05;
    setup.law = "recommended";
    setup.controller.estimator.max_acceleration = a_max;
    setup.controller.recommended.command_rise_time = 0.0;  // the feed-forward's bound alone (test_command_rate_box: the box's)
    setup.sensor.sample_period = 0.1;
    setup.sensor.noise_std = noise;
    setup.sensor.seed = 7;
    const core::SplineReference reference({{0.6, 0.0}, {2.0, 0.8}, {4.0, 0.0}}, 20.0);
    return sim::runClosedLoop(setup, reference);
  };
  const sim::ClosedLoopSummary bounded = run(1.0, 0.03), raw = run(0.0, 0.03), clean = run(1.0, 0.0);
  std::printf("noisy target: max |dv| %.3f m/s, |dw| %.3f rad/s, true ASE %.4f (v_hat fed raw: %.3f, %.3f, %.4f; "
              "no noise: %.4f)\n", bounded.metrics.max_delta_v, bounded.metrics.max_delta_omega,
              bounded.metrics.true_ase, raw.metrics.max_delta_v, raw.metrics.max_delta_omega, raw.metrics.true_ase,
              clean.metrics.true_ase);
  EXPECT_LT(bounded.metrics.max_delta_omega, 0.5 * raw.metrics.max_delta_omega);
  EXPECT_LT(bounded.metrics.true_ase, raw.metrics.true_ase);
  EXPECT_EQ(bounded.envelope_widenings, 0u);
  // Without noise the bound changes nothing on a course whose acceleration stays below a_max.
  const sim::ClosedLoopSummary clean_raw = run(0.0, 0.0);
  EXPECT_NEAR(clean.metrics.true_ase, clean_raw.metrics.true_ase, 0.05 * clean_raw.metrics.true_ase);
}

// (13') holds |e| < rho by itself against an infeasible reference (0.6 m/s against v_bar 0.3),
// where the paper's (13) needs the guard hundreds of times: |e|/rho stays below
// max(xi(0), 1/sqrt(1 + k_r), tanh(estimation error / k_d)).
TEST(RecommendedLaw, RhoLawKeepsTheErrorInsideWithoutTheGuard) {
  for (const Scene& scene : clutter_scenes::clutterScenes()) {
    if (scene.name != "fast_target") continue;
    for (const std::string law : {"recommended", "paper"}) {
      sim::ClosedLoopSetup setup = setupOf(scene, law);
      const core::SplineReference reference(scene.waypoints, scene.spline_duration);
      const sim::ClosedLoopSummary s = sim::runClosedLoop(setup, reference);
      if (law == "recommended") {
        EXPECT_EQ(s.envelope_widenings, 0u);
        EXPECT_LT(s.max_error_ratio, 0.99);
      } else {
        EXPECT_GT(s.envelope_widenings, 100u);  // measured 357: the paper's law leans on the guard
      }
    }
  }
}

// The band of (10) at 20 Hz with Table 1's delta = 0.016 m on the Section 5.3 course: the
// paper's law enters and leaves it step after step and rho jumps by metres (issue 20); the
// recommended law has no band (its barrier rows are continuous), so rho moves smoothly.
TEST(RecommendedLaw, RhoDoesNotJumpWithAThinBandAt20Hz) {
  double largest_step[2] = {0.0, 0.0}, largest_rho[2] = {0.0, 0.0};
  int i = 0;
  for (const char* variant : {"recommended", "paper"}) {
    sim::Scenario s = sim::loadScenario(std::string(AMIGOBOT_SOURCE_DIR) + "/config/scenarios/experiment_5_3.yaml",
                                        {std::string("controller.variant=") + variant, "controller.delta=0.016",
                                         "simulation.control_period=0.05", "simulation.max_step=0"});
    double last_rho = -1.0;
    const auto ref = s.makeReference();
    sim::runClosedLoop(s.setup, *ref, [&](const sim::ClosedLoopStep& step) {
      if (last_rho > 0.0) largest_step[i] = std::max(largest_step[i], std::abs(step.output.rho - last_rho));
      largest_rho[i] = std::max(largest_rho[i], step.output.rho);
      last_rho = step.output.rho;
    });
    ++i;
  }
  EXPECT_LT(largest_step[0], 0.1) << "recommended";
  EXPECT_LT(largest_rho[0], 3.0) << "recommended";
  EXPECT_GT(largest_step[1], 1.0) << "paper (measured 7.1 m in the audit)";
}

// A doorway the body passes (0.7 m between the disks' surfaces, the body 0.36 m wide) but the
// disk of radius R + r around p_r of (10) does not (0.96 m): the law holds the body itself
// (safety_filter.h, body_rows), so the robot drives through the door, with no contact, instead
// of going round the pair (as it did while the law held the R + r disk).
TEST(RecommendedLaw, DrivesThroughADoorTheBodyPassesButTheEffectiveDiskDoesNot) {
  Scene door{"door", {clutter_scenes::disk(2.5, 0.45, 0.1), clutter_scenes::disk(2.5, -0.45, 0.1)}, {},
             {{0.6, 0.0}, {5.0, 0.0}}, 25.0, 30.0};
  const sim::ClosedLoopSetup setup = setupOf(door, "recommended");
  const core::SplineReference reference(door.waypoints, door.spline_duration);
  double crossing_y = NAN;  // where the centre crosses the door's line
  double last_x = 0.0, last_y = 0.0;
  const sim::ClosedLoopSummary s = sim::runClosedLoop(setup, reference, [&](const sim::ClosedLoopStep& step) {
    if (last_x < 2.5 && step.pose.x >= 2.5 && std::isnan(crossing_y)) crossing_y = last_y;
    last_x = step.pose.x;
    last_y = step.pose.y;
  });
  ASSERT_FALSE(std::isnan(crossing_y)) << "the robot never crossed x = 2.5";
  EXPECT_LT(std::abs(crossing_y), 0.45 - 0.1 - 0.18) << "crossed outside the door";
  EXPECT_EQ(s.metrics.body_collisions + s.metrics.offset_collisions, 0u);
  EXPECT_GT(s.metrics.min_clearance_body, 0.0);
  EXPECT_EQ(s.envelope_widenings, 0u);
  EXPECT_LT(s.final_error, 0.2);
}

// The field's bridges (navigation_field.h): a corridor the 5 cm grid cannot resolve is shut,
// a wide one is left alone, and the slowness at the corridor's middle grows continuously as
// the disks close in (no bridge appears with a jump).
TEST(RecommendedLaw, FieldShutsCorridorsTheGridCannotResolve) {
  core::NavigationFieldConfig field;
  field.robot_radius = 0.18;
  auto middleSlowness = [&](double w) {  // two 0.2 m disks whose zones leave a corridor w wide
    const double half = 0.2 + 0.18 + 0.5 * w;
    const std::vector<core::Disk> disks = {clutter_scenes::disk(0.0, half, 0.2), clutter_scenes::disk(0.0, -half, 0.2)};
    return core::fieldSlowness(Eigen::Vector2d::Zero(), core::narrowGapsClosed(disks, field), field, disks.size());
  };
  EXPECT_DOUBLE_EQ(middleSlowness(0.5), 1.0);   // wide: free space in the middle, no bridge
  EXPECT_GT(middleSlowness(0.066), 20.0);       // the U's 6.6 cm corridor: shut (28 deep inside a bridge, 20 in a disk's zone)
  double largest_step = 0.0;
  for (double w = 0.25; w > 0.0; w -= 0.0005)
    largest_step = std::max(largest_step, std::abs(middleSlowness(w) - middleSlowness(w + 0.0005)));
  EXPECT_LT(largest_step, 1.5);  // per 0.5 mm, against 28 inside a bridge: no jump
}

// Catching up (|e| 0.7 m, the target 0.7 rad left of the heading and walking on at 0.2 m/s), the
// nominal offset-point velocity is 2.55 v_bar long, 0.53 rad left. The filter's nearest point of the diamond to
// so long a vector is its (v_bar, 0) corner unless it points far aside (in p_r's velocities the
// corner wins while c (0.24 sin phi - 0.3 cos phi) <= -0.09 m/s at length c, angle phi), so the turn
// was dropped: 3 s at v_bar with the heading 0.23 rad off the target's line (pedestrian benchmark,
// crossing_ahead). Shortened to nominal_speed_cap v_bar = 0.45 m/s first, it turns from 0.35 rad on.
TEST(RecommendedLaw, TurnsTowardsATargetItIsCatchingUpWith) {
  core::ControllerConfig config;
  config.law = "recommended";
  const core::DiamondSet diamond(config.v_max, config.w_max);
  config.recommended.nominal_speed_cap = 1.5;
  core::RecommendedInput in = atOrigin(config);
  in.e = 0.7 * Eigen::Vector2d(std::cos(0.7), std::sin(0.7));
  in.v_hat = {0.2, 0.0};
  in.v_smooth = in.v_hat;
  in.rho = 1.0;
  const core::RecommendedCommand capped = core::recommendedCommand(config, diamond, in, {});
  config.recommended.nominal_speed_cap = 0.0;
  const core::RecommendedCommand long_nominal = core::recommendedCommand(config, diamond, in, {});
  ASSERT_TRUE(capped.valid && long_nominal.valid);
  std::printf("nominal %.2f v_bar long at %.3f rad; omega capped %.3f, uncapped %.3f rad/s\n",
              long_nominal.u_nom.norm() / config.v_max, std::atan2(long_nominal.u_nom.y(), long_nominal.u_nom.x()),
              capped.u.omega, long_nominal.u.omega);
  EXPECT_GT(long_nominal.u_nom.norm(), 2.0 * config.v_max);
  EXPECT_NEAR(capped.u_nom.norm(), 1.5 * config.v_max, 1e-9);
  EXPECT_LT(std::abs(long_nominal.u.omega), 0.05) << "the long nominal turns: the test shows nothing";
  EXPECT_GT(capped.u.omega, 0.1);
  EXPECT_GT(capped.u.v, 0.5 * config.v_max);
}

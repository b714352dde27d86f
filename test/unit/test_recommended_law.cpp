// The recommended law (core/recommended_law.h) in the offline closed loop, class by class
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

#include "amigobot_tracking/core/controller.h"
#include "amigobot_tracking/core/recommended_law.h"
#include "amigobot_tracking/core/reference.h"
#include "amigobot_tracking/sim/closed_loop.h"
#include "clutter_scenes.h"

using namespace amigobot_tracking;
using clutter_scenes::Scene;

namespace {

struct Outcome {
  std::uint64_t contacts = 0, diamond_violations = 0, widenings = 0, nan = 0;
  double orbit_turns = 0.0;  // largest net winding of p_r around one disk [turns]
  int side_flips = 0;
  double true_ase = 0.0;
};

sim::ClosedLoopSetup setupOf(const Scene& scene, sim::ControlLaw law) {
  sim::ClosedLoopSetup setup;
  setup.controller.v_max = scene.v_max;
  setup.controller.w_max = scene.w_max;
  setup.controller.moving_obstacles = !scene.velocities.empty();
  setup.initial_pose = {0.0, 0.0, 0.0};
  setup.obstacles = scene.disks;
  setup.obstacle_velocities = scene.velocities;
  setup.duration = scene.duration;
  setup.control_period = 0.05;
  setup.law = law;
  return setup;
}

Outcome run(const Scene& scene, sim::ControlLaw law) {
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
    // which may move), while near it and moving.
    if (!std::isnan(last_p_r.x()) && nearest_clearance < zone) {
      const Eigen::Vector2d& center = (*step.obstacles)[nearest].center;
      const Eigen::Vector2d move = p - last_p_r - (center - last_center[nearest]), away = p - center;
      if (move.norm() > 0.02 * setup.control_period) {
        const int side = away.x() * move.y() - away.y() * move.x() > 0.0 ? 1 : -1;
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
  if (!(o.true_ase <= paper_ase * (1.0 + 1e-9))) f.push_back("ASE " + std::to_string(o.true_ase) + " > paper's");
  return f;
}

std::string joined(const std::vector<std::string>& v) {
  std::ostringstream s;
  for (const std::string& x : v) s << x << "; ";
  return s.str();
}

}  // namespace

TEST(RecommendedLaw, PassesEveryClutterClassWhereThePaperLawFails) {
  std::map<std::string, std::vector<std::string>> paper_failures;
  for (const Scene& scene : clutter_scenes::clutterScenes()) {
    const Outcome paper = run(scene, sim::ControlLaw::kPaper);
    const Outcome mine = run(scene, sim::ControlLaw::kRecommended);
    std::printf("%-12s ASE paper %.4f recommended %.4f | widenings %llu / %llu | flips %d / %d | turns %.2f / %.2f\n",
                scene.name.c_str(), paper.true_ase, mine.true_ase, (unsigned long long)paper.widenings,
                (unsigned long long)mine.widenings, paper.side_flips, mine.side_flips, paper.orbit_turns,
                mine.orbit_turns);
    EXPECT_TRUE(failures(mine, paper.true_ase).empty()) << scene.name << ": " << joined(failures(mine, paper.true_ase));
    // The paper's law against the recommended one's ASE: where the paper's law is worse.
    paper_failures[scene.name] = failures(paper, mine.true_ase);
  }
  // The checks bite: the paper's law fails them in these classes (measured).
  for (const char* name : {"pillar_park", "u_behind", "u_through", "doorway", "fast_target"})
    EXPECT_FALSE(paper_failures[name].empty()) << name << ": the paper's law passed every check";
}

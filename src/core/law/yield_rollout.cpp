#include "amigobot_tracking/core/law/yield_rollout.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "amigobot_tracking/core/robot/actuator_model.h"

namespace amigobot_tracking {
namespace core {
namespace {

// [s] the manoeuvres are judged at these steps (the body moves at most 3 cm between them at
// v_bar, far less than a person's radius), through the actuator model in sub-steps of kSubstep.
constexpr double kJudgeStep = 0.1;
constexpr double kSubstep = 0.02;
// [s] a manoeuvre is kept at most this long, then chosen afresh (it may be chosen again): kept
// while merely clear, a reversal in front of a person walking head-on down a corridor was kept
// the corridor's length (mean true ASE 1.96 in 50 runs; 1.25 with 3 s, 1.51 with 1.5 s and
// 10 contacts instead of 5).
constexpr double kCommitSpan = 3.0;

using Manoeuvre = YieldManoeuvre;

struct Outcome {
  double clearance;  // the least body clearance from every disk (moved along its velocity)
  double miss;       // how far p_r ends from where the target will be then
};

// What sending `m` does over the horizon to the base, moving as `base` does now.
Outcome judge(const YieldInput& in, const ActuatorModel& base, const Manoeuvre& m, const std::vector<Disk>& obstacles) {
  ActuatorModel model = base;
  Pose2 pose = in.pose;
  double least = std::numeric_limits<double>::infinity();
  for (double t = 0.0; t < in.horizon - 1e-9;) {
    const double step = std::min(kJudgeStep, in.horizon - t);
    pose = driveBody(&model, pose, t < m.first_duration - 1e-9 ? m.first : m.then, step, kSubstep);
    t += step;
    for (const Disk& o : obstacles)
      least = std::min(least, (pose.position() - (o.center + t * o.velocity)).norm() - in.radius - o.radius);
  }
  const Eigen::Vector2d p_r = pose.position() + in.offset * Eigen::Vector2d(std::cos(pose.theta), std::sin(pose.theta));
  return {least, (p_r - (in.target + in.horizon * in.target_velocity)).norm()};
}

}  // namespace

bool anyMoving(const std::vector<Disk>& obstacles) {
  return std::any_of(obstacles.begin(), obstacles.end(), [](const Disk& o) { return o.velocity.squaredNorm() > 0.0; });
}

YieldResult yieldToMovingDisks(const YieldInput& in, const DiamondSet& diamond, const std::vector<Disk>& obstacles) {
  YieldResult out;
  out.u = in.filtered;
  if (!(in.horizon > 0.0) || !anyMoving(obstacles)) return out;
  // The base as it moves now: the caller's model, or one brought to the last command (its ramps
  // from rest take at most v_bar / trans_accel; the model is run long enough to settle at it).
  auto settled = [&] {
    ActuatorModel model(in.limits, in.half_track > 0.0 ? in.half_track : kAmigoHalfTrack);
    const double settle = diamond.vMax() / in.limits.trans_accel + diamond.wMax() / in.limits.rot_accel + 2.0 * (in.limits.latency + in.limits.cycle);
    model.step(in.previous, std::isfinite(settle) ? settle : 1.0);
    return model;
  };
  const ActuatorModel base = in.base ? *in.base : settled();
  auto held = [](const Twist2& u) { return Manoeuvre{u, 0.0, u}; };
  out.filtered_clearance = judge(in, base, held(in.filtered), obstacles).clearance;
  out.chosen_clearance = out.filtered_clearance;
  if (out.filtered_clearance >= in.enough) return out;
  // A robot that stops is passed by a person crossing ahead of it, and the filter stops it
  // before such a person anyway: the manoeuvres are for a disk that comes to the robot, which
  // even a stopped base would not keep clear of.
  out.stopped_clearance = judge(in, base, held({0.0, 0.0}), obstacles).clearance;
  if (out.stopped_clearance >= in.enough) return out;

  // The manoeuvre under way, while it keeps the body clear: no search.
  if (in.committed && in.committed->held <= kCommitSpan) {
    const Outcome kept = judge(in, base, *in.committed, obstacles);
    if (kept.clearance >= 0.0) {
      out.acted = true;
      out.manoeuvre = *in.committed;
      out.chosen_clearance = kept.clearance;
      out.u = out.manoeuvre.first_duration > 0.0 ? out.manoeuvre.first : out.manoeuvre.then;
      return out;
    }
  }

  const double v = diamond.vMax(), w = diamond.wMax();
  std::vector<Manoeuvre> candidates;
  for (double fv : {-1.0, -0.5, 0.0, 0.5, 1.0})
    for (double fw : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
      const double omega = fw * w * (1.0 - std::abs(fv));
      if (fw != 0.0 && std::abs(fv) == 1.0) continue;  // a vertex: w is 0 there
      candidates.push_back(held({fv * v, omega}));
    }
  for (double turn : {-1.0, 1.0})
    for (double duration : {0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5})
      for (double drive : {-1.0, -0.5, 0.5, 1.0}) candidates.push_back({{0.0, turn * w}, duration, {drive * v, 0.0}});
  out.candidates = static_cast<int>(candidates.size());

  // Clearance first (up to `enough`), then the one whose p_r ends nearest where the target
  // will be (the target's last velocity held): among manoeuvres that keep clear, the one
  // that keeps tracking, not one that flees in any direction.
  constexpr double kTie = 1e-3;  // [m] clearances this close count as equal
  std::vector<Outcome> outcome(candidates.size());
  double best_score = -std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < candidates.size(); ++i) {
    outcome[i] = judge(in, base, candidates[i], obstacles);
    best_score = std::max(best_score, std::min(outcome[i].clearance, in.enough));
  }
  if (best_score <= out.filtered_clearance + kTie) return out;  // no manoeuvre does better
  const Manoeuvre* best = nullptr;
  double best_miss = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < candidates.size(); ++i)
    if (std::min(outcome[i].clearance, in.enough) >= best_score - kTie && outcome[i].miss < best_miss) {
      best = &candidates[i];
      best_miss = outcome[i].miss;
      out.chosen_clearance = outcome[i].clearance;
    }
  if (!best) return out;
  out.acted = true;
  out.manoeuvre = *best;
  out.u = best->first_duration > 0.0 ? best->first : best->then;
  return out;
}

}  // namespace core
}  // namespace amigobot_tracking

#include "amigobot_tracking/core/law/recommended_law.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "amigobot_tracking/core/law/navigation_field.h"
#include "amigobot_tracking/core/robot/offset_point.h"
#include "amigobot_tracking/core/law/prescribed_performance.h"
#include "amigobot_tracking/core/law/safety_filter.h"

namespace amigobot_tracking {
namespace core {

RecommendedCommand recommendedCommand(const ControllerConfig& config, const DiamondSet& diamond,
                                      const RecommendedInput& in, const std::vector<Disk>& obstacles) {
  RecommendedCommand out;
  // The law holds the body itself (body_safe: the body disk and the disk of radius R around
  // p_r, safety_filter.h), not the disk of radius R + r around p_r of (10), so its zones are
  // R wide (plus body_margin): a gap the body passes is a gap for the field.
  const double radius = config.robot_radius + config.recommended.body_margin;
  const double error_norm = in.e.norm();
  const double xi = error_norm / in.rho;
  const Eigen::Vector2d e_hat = error_norm > 1e-12 ? Eigen::Vector2d(in.e / error_norm) : Eigen::Vector2d::Zero();
  // The prescribed decay's term with the floor rho decays to, as in recommendedRhoStep: the two
  // cancel in the argument of docs/controller.md.
  const double rho_floor = std::max(config.rho_inf, in.rho_floor);
  const double pull = config.k_d * transformT(xi) + config.lambda * std::max(0.0, in.rho - rho_floor) * xi;
  out.u_track = pull * e_hat + in.v_hat;
  // While rho is wide the pull of (9) is weak: about (k_d / rho + lambda (1 - rho_inf / rho)) |e|,
  // 0.6 |e| at rho = 1 m with Section 5.3's gains, so an off-course start crawls in for seconds.
  // The law drives with at least the gain (9) has at its own steady state, k_d / rho_inf
  // (T(xi) >= xi at rho = rho_inf): 1.5 1/s there. It only adds along e_hat, so the shortfall and
  // (13') still count u_track (the argument of docs/controller.md holds as it is); it is
  // continuous (a max of two continuous terms) and no new gain. The floor stops at 2 v_bar: far
  // off, the pull of (9) is larger anyway, and an uncapped floor magnified the field's turns
  // near a pillar's zone into 0.12 m/s command changes per 2 mm (2.4x the law without it).
  const double drive = std::max(pull, std::min(config.k_d / config.rho_inf * error_norm, 2.0 * config.v_max));

  // Without body_safe, a moving disk is held off p_r by more: up to the full R + r of (10) for a
  // disk closing on p_r as fast as the robot, which the body, steering only along its heading,
  // cannot outrun sideways; only the speed at which it closes on p_r counts (a person crossing
  // ahead of the target is no faster at p_r for walking fast). With body_safe the body's row
  // holds a person off the stretch they walk while the base stops (safety_filter.h, personSpan),
  // which is where that room is needed, and the field sees their path (below): the widening on
  // top held the robot 0.3 m farther back and made it back from people crossing ahead of the
  // target (pedestrian benchmark, every class's mean true ASE lower without it: crossing_ahead
  // 0.0239 -> 0.0189, crowd 0.170 -> 0.119, 0 contacts; docs/pedestrians.md). A static disk is
  // never widened.
  std::vector<Disk> held = obstacles;
  if (!config.body_safe)
    for (Disk& o : held) {
      const Eigen::Vector2d to_p_r = in.p_r - o.center;
      const double distance = to_p_r.norm();
      const double closing = distance > 1e-9 ? std::max(0.0, o.velocity.dot(to_p_r) / distance) : o.velocity.norm();
      o.radius += config.offset * std::min(1.0, closing / config.v_max);
    }
  // The field routes round where a moving disk will be, not only where it is: its path over
  // obstacle_lookahead (withPredictedPaths), so the robot passes behind a person crossing its way
  // and steps out of the way of one coming from behind instead of fleeing ahead of them.
  const std::vector<Disk> seen = withPredictedPaths(held, config.recommended.obstacle_lookahead, in.p_r, config.v_max, radius);

  NavigationFieldConfig field;
  field.robot_radius = radius;
  field.margin = config.recommended.field_margin;
  // A target in or near a zone (the threshold, saddle and doorway classes: it drives over a
  // disk) pulls the field to the zone's near side, where the robot waited until the target came
  // out (4 s in front of a 0.2 m disk). The field aims instead up to tau |v_smooth| ahead of it,
  // weighted by how near the target's own next path p_d -> p_d + a comes to a zone (beta_d =
  // clamp(1 - q_d / margin, 0, 1), q_d that segment's clearance: 0 when it is in free space, so a
  // reachable target is tracked as before)
  // and at most |e| ahead (a robot that has caught up aims at the target: no overshoot past a
  // target that parks behind a pillar). Continuous in the state and the geometry. The
  // line-of-sight blend and (13') still use p_d itself.
  const Eigen::Vector2d p_d = in.p_r + in.e;
  Eigen::Vector2d ahead = config.recommended.field_lookahead * in.v_smooth;
  if (!ahead.allFinite()) ahead.setZero();
  if (ahead.norm() > error_norm) ahead *= error_norm / ahead.norm();
  const double q_d = segmentClearance(p_d, p_d + ahead, seen, radius);
  const double target_blocked = std::clamp(1.0 - q_d / field.margin, 0.0, 1.0);
  // A target on a person's path (where they walk within obstacle_lookahead): the field aims
  // beside that path, so the robot steps aside and lets them pass (goalOutOfPaths; the person's
  // own radius: the widened one of `held` would send it up to r farther aside than it needs).
  const Eigen::Vector2d goal = goalOutOfPaths(p_d + target_blocked * ahead, in.p_r, obstacles, config.recommended.obstacle_lookahead,
                                              radius, field.margin);
  const NavigationDirection nav = navigationDirection(in.p_r, p_d, goal, seen, field);
  out.direction = nav.direction;
  out.blend = nav.blend;
  const double feed_forward = std::clamp(nav.direction.dot(e_hat), 0.0, 1.0);
  out.u_nom = drive * nav.direction + (error_norm > 1e-12 ? feed_forward : 1.0) * in.v_hat;
  // While the robot catches up the nominal is up to 2.6 v_bar long; the filter's nearest point of
  // the diamond is then its (v_bar, 0) corner, whatever the nominal's direction: 3 s at v_bar with
  // the heading 0.23 rad off the target's line (crossing_ahead). Shortened, its turn survives.
  if (config.recommended.nominal_speed_cap > 0.0) {
    const double cap = config.recommended.nominal_speed_cap * config.v_max, length = out.u_nom.norm();
    if (length > cap) out.u_nom *= cap / length;
  }

  const Eigen::Vector2d heading(std::cos(in.pose.theta), std::sin(in.pose.theta));
  out.u_nominal = offsetVelocityToTwist(out.u_nom, heading, config.offset);
  if (!out.u_nominal.isFinite()) return out;
  SafetyFilterInput filter;
  filter.pose = in.pose;
  filter.offset = config.offset;
  filter.robot_radius = radius;
  filter.gamma = config.recommended.barrier_rate;
  filter.min_margin = config.min_margin;
  filter.obstacle_velocities = config.obstacleVelocities();
  filter.braking = config.recommended.plan_braking;
  filter.limits = config.actuator;
  filter.hold = in.h;
  filter.body_rows = config.body_safe;
  filter.nominal = out.u_nominal;
  // Under 3 cm of target noise the law's command followed the noise: |dv| up to 0.52 m/s and
  // |dw| up to 1.59 rad/s in one step (50 noisy runs per clutter class). No target motion
  // the robot can follow needs a corner of the diamond reached faster than command_rise_time.
  if (in.h > 0.0 && config.recommended.command_rise_time > 0.0) {
    filter.previous = in.previous;
    filter.max_change = {diamond.vMax() * in.h / config.recommended.command_rise_time,
                         diamond.wMax() * in.h / config.recommended.command_rise_time};
  }
  const SafetyFilterResult safe = safetyFilter(filter, diamond, held);
  if (!safe.solved || !safe.u.isFinite()) return out;
  out.valid = true;
  out.u = safe.u;
  if (config.recommended.yield_horizon > 0.0) {
    YieldInput look;
    look.pose = in.pose;
    look.previous = in.h > 0.0 ? in.previous : safe.u;
    look.filtered = safe.u;
    look.target = p_d;
    look.target_velocity = in.v_hat;
    look.offset = config.offset;
    look.radius = radius;
    look.horizon = config.recommended.yield_horizon;
    look.enough = config.recommended.yield_clearance;
    look.limits = config.actuator;
    look.committed = in.committed;
    look.base = in.base;
    const YieldResult yielded = yieldToMovingDisks(look, diamond, obstacles);
    out.yielded = yielded.acted;
    out.manoeuvre = yielded.manoeuvre;
    out.u = yielded.u;
    // The manoeuvre is chosen afresh at each step: the command moves to it within the rate box
    // as the filter's does (the base ramps slower still), so yielding does not jump.
    if (yielded.acted && std::isfinite(filter.max_change.v) && std::isfinite(filter.max_change.omega)) {
      out.u.v = std::clamp(out.u.v, in.previous.v - filter.max_change.v, in.previous.v + filter.max_change.v);
      out.u.omega = std::clamp(out.u.omega, in.previous.omega - filter.max_change.omega, in.previous.omega + filter.max_change.omega);
      if (const auto inside = diamond.saturate(out.u)) out.u = *inside;
    }
  }
  out.slack = safe.slack;
  out.barrier_rows = safe.rows;
  out.active_barriers = safe.active;
  // What was sent: the filter's command, or the manoeuvre that yields to a person (its shortfall counts too).
  const Eigen::Vector2d applied = out.u.v * heading + config.offset * out.u.omega * Eigen::Vector2d(-heading.y(), heading.x());
  out.shortfall = std::max(0.0, e_hat.dot(out.u_track - applied));
  // The relaxation is weighed against rho less the noise headroom 5 sigma (rho_floor - rho_inf):
  // one sample's noise can move the measured |e| by that much, so rho keeps it above |e| at any
  // height, not only at its floor. With xi alone, a robot turning in place in a U while the
  // target left had rho 4 cm above |e| when two 8 cm noise samples came (1 guard widening in
  // 1100 runs); 0 in 1650 with the headroom, ASE unchanged. Without noise xi_n = xi.
  const double headroom = std::max(0.0, rho_floor - config.rho_inf);
  const double xi_n = std::min(1.0, error_norm / std::max(in.rho - headroom, 1e-9));
  out.relaxation = (1.0 + config.k_r) * xi_n * xi_n * out.shortfall;
  out.min_clearance = safetyClearance(filter, obstacles);
  return out;
}

double recommendedRhoStep(const ControllerConfig& config, double rho, double relaxation, double h, double rho_floor) {
  // A floor that rose above rho (noise measured): rho rises to it at the prescribed rate.
  const double floor = std::max(config.rho_inf, rho_floor);
  const double decayed = floor + (rho - floor) * std::exp(-config.lambda * h);
  return decayed + std::min(h, config.max_relaxation_interval) * relaxation;
}

}  // namespace core
}  // namespace amigobot_tracking

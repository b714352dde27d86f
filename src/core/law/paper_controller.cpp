#include "amigobot_tracking/core/law/paper_controller.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "amigobot_tracking/core/law/avoidance.h"
#include "amigobot_tracking/core/law/band_implicit.h"
#include "amigobot_tracking/core/robot/offset_point.h"

namespace amigobot_tracking {
namespace core {
namespace {

PerformanceGains gainsOf(const ControllerConfig& config) {
  return {config.lambda, config.rho_inf, config.k_r, config.max_rho_rate};
}

// setImplicitHorizon: replaces the explicit term of the nearest obstacle the offset point
// can reach within h by its backward-Euler value (band_implicit.h), for the command held from
// `start`. `others` is the rest of u_r; the other obstacles keep their explicit terms.
// start_heading and command_heading: (cos, sin) of start.theta and of the command's heading.
void applyImplicitBand(const ControllerConfig& config, const DiamondSet& diamond, const Pose2& start,
                       const Eigen::Vector2d& start_heading, double command_theta,
                       const Eigen::Vector2d& command_heading, const Eigen::Vector2d& others,
                       const std::vector<Disk>& obstacles, double h, ControllerOutput& out) {
  const double radius = config.effectiveRadius();
  const Eigen::Vector2d p_start = start.position() + config.offset * start_heading;  // offsetPoint(start)
  const Disk* nearest = nullptr;
  double nearest_clearance = 0.0;  // from where the held command starts
  for (const Disk& o : obstacles) {
    const double c = (p_start - o.center).norm() - radius - o.radius;
    if (!nearest || c < nearest_clearance) {
      nearest = &o;
      nearest_clearance = c;
    }
  }
  if (!nearest) return;
  // Obstacle j's explicit term, as repulsiveTerm added it at the step's p_r.
  const double clearance_now = (out.p_r - nearest->center).norm() - radius - nearest->radius;
  Eigen::Vector2d explicit_term = Eigen::Vector2d::Zero();
  const bool detected = clearance_now <= config.delta;
  if (detected) {
    explicit_term = (1.0 / std::max(clearance_now, config.min_margin) - 1.0 / config.delta) *
                    (out.p_r - nearest->center);
  }
  const Eigen::Vector2d rest = others + config.k_o * (out.u_c - explicit_term);
  // A held command moves the offset point at the constant speed |(v, r w)|: at most the
  // diamond's bound, and at most |rest| while obstacle j adds nothing (the diamond only
  // shrinks u_r). Out of the band's reach within h, the zero term is the implicit one too.
  const double reach = h * std::min(maxOffsetSpeed(diamond, config.offset), rest.norm());
  if (nearest_clearance - reach > config.delta) return;
  BandImplicitProblem problem;
  problem.pose = start;
  problem.offset = config.offset;
  problem.rest = rest;
  problem.k_o = config.k_o;
  problem.obstacle = *nearest;
  problem.robot_radius = radius;
  problem.delta = config.delta;
  problem.min_margin = config.min_margin;
  problem.h = h;
  problem.command_theta = command_theta;
  problem.start_heading = start_heading;
  problem.command_heading = command_heading;
  const BandImplicitResult implicit = solveBandImplicit(problem, diamond);
  if (!implicit.solved) return;
  out.u_c += implicit.u_c - explicit_term;
  const bool implicit_detected = !implicit.u_c.isZero(0.0);
  if (implicit_detected && !detected) ++out.detected_obstacles;
  if (!implicit_detected && detected) --out.detected_obstacles;
  out.active.avoiding = out.detected_obstacles > 0;
}

}  // namespace

PaperController::PaperController(const ControllerConfig& config, bool fixed_rho)
    : BoundedLaw(config), fixed_rho_(fixed_rho), gains_(gainsOf(config)) {}

void PaperController::forgetLawState() {
  conflict_ = 0.0;
  passing_side_ = 0;
}

void PaperController::configureLaw() { gains_ = gainsOf(config_); }

ControllerOutput PaperController::step(double t, const PoseSample& robot, const TargetSample& target,
                                       const std::vector<Disk>& obstacles) {
  ControllerOutput out;
  const OpenedStep opened = openStep(t, robot, target, &out);
  if (!opened.error.empty()) return invalid(t, opened.error);
  const Pose2& pose = opened.pose;
  const Eigen::Vector2d& heading = opened.heading;
  const double error_norm = opened.error_norm;

  // rho: start rule, then (13) over the elapsed time with the last step's conflict.
  // The conflict is the last step's: over a stall it is stale, and near contact (1/margin)
  // it is large, so the relaxation is held for at most max_relaxation_interval.
  envelope_.update(t, error_norm, config_, [&](double rho, double dt) {
    out.active.rho_relaxed = conflict_ < 0.0;
    return rhoStep(gains_, rho, conflict_, dt, config_.max_relaxation_interval);
  }, &out.active);
  const double rho = envelope_.rho();
  out.rho = rho;

  const double ratio = error_norm / rho;
  const double t_ratio = transformT(ratio);
  const Eigen::Vector2d e_hat = error_norm > 1e-12 ? Eigen::Vector2d(out.e / error_norm) : Eigen::Vector2d::Zero();
  const double radius = config_.effectiveRadius();
  const AvoidanceResult avoidance =
      config_.moving_obstacles
          ? movingRepulsiveTerm(out.p_r, obstacles, radius, config_.delta, config_.paper.obstacle_horizon, heading,
                                config_.min_margin)
          : repulsiveTerm(out.p_r, obstacles, radius, config_.delta, heading, config_.min_margin);
  out.u_c = avoidance.u_c;
  bool escape_full = false;
  if (config_.paper.tangential_avoidance) {
    const TangentialResult tangential = tangentialTerm(out.p_r, obstacles, radius, config_.delta, e_hat,
                                                       passing_side_, config_.paper.tangential_hysteresis,
                                                       config_.min_margin);
    passing_side_ = tangential.side;
    out.passing_side = tangential.side;
    out.u_t = config_.paper.k_t * tangential.u_t;
    escape_full = tangential.full_strength;
  }
  // The tracking part of (9).
  const Eigen::Vector2d attraction =
      config_.k_d * t_ratio * e_hat + out.v_hat + config_.lambda * (rho - config_.rho_inf) * out.e / rho;
  // The escape redirects the attraction the barrier cancels; it needs no more than k_t times
  // that. Uncapped it grows like u_c (1/margin) and, after the diamond's radial scaling, takes
  // the radial barrier's share: 3 contacts with crossing obstacles on crossing_obstacles.yaml.
  const double escape_cap = config_.paper.k_t * attraction.norm() / config_.k_o;
  if (escape_full) {
    out.u_t *= escape_cap / config_.paper.k_t;  // a group of disks: the whole cap (u_t was k_t times a unit vector)
  } else if (out.u_t.norm() > escape_cap) {
    out.u_t *= escape_cap / out.u_t.norm();
  }
  out.detected_obstacles = avoidance.detected;
  out.min_clearance = avoidance.min_clearance;
  out.active.avoiding = avoidance.detected > 0;
  if (hold_.h > 0.0 && !config_.moving_obstacles) {
    applyImplicitBand(config_, diamond_, hold_.start_given ? hold_.start : pose,
                      hold_.start_given ? hold_.start_heading : heading, pose.theta, heading,
                      attraction + config_.k_o * out.u_t, obstacles, hold_.h, out);
  }

  // (9): u_r = k_d T e_hat + v_hat + lambda (rho - rho_inf) e / rho + k_o u_c.
  out.u_r = attraction + config_.k_o * (out.u_c + out.u_t);
  out.u_d = offsetVelocityToTwist(out.u_r, heading, config_.offset);  // (11)
  const auto saturated = diamond_.saturate(out.u_d);                     // (12)
  if (!saturated) return invalid(t, "desired command is not finite");
  out.u = *saturated;
  applied(t, out.u);

  const double alignment = e_hat.dot(out.u_c);
  const double clipping = std::hypot(out.u.v - out.u_d.v, out.u.omega - out.u_d.omega);
  out.active.saturated = clipping > 0.0;
  out.active.conflict = alignment < 0.0;
  // The fixed-rho baseline never relaxes: (13) without its adaptive term.
  conflict_ = config_.adaptive_rho && !fixed_rho_ ? t_ratio * alignment - clipping : 0.0;
  return out;
}

}  // namespace core
}  // namespace amigobot_tracking

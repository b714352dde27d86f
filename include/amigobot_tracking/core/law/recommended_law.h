// The recommended law (ControllerConfig::law = "recommended"): the paper's tracking terms of
// (9) steered along a navigation field (navigation_field.h), passed through a safety filter
// (safety_filter.h) instead of the repulsion (10) and the saturation (12), with rho following
// (13'), whose relaxation counts the shortfall of the applied motion (docs/controller.md):
//
//   u_track = k_d T(xi) e_hat + v_f + lambda (rho - rho_f) e / rho        (the tracking part of (9))
//   u_nom   = max(k_d T(xi) + lambda (rho - rho_f) xi, min((k_d / rho_inf) |e|, 2 v_bar)) d + clamp(d^T e_hat, 0, 1) v_f
//             (d: the field's direction; d = e_hat with a clear line of sight; the max keeps
//             at least the gain (9) has at steady state while rho is still wide)
//   u       = safetyFilter(G^-1 u_nom), at most (v_bar, w_bar) h / command_rise_time from the last u
//             while every barrier row holds (safety_filter.h's rate box); replaced by a manoeuvre
//             judged on the base's dynamics when it and a stop would both let a moving disk reach
//             the body within yield_horizon (yield_rollout.h)
//   Delta   = max(0, e_hat^T (u_track - G u))                               (the shortfall)
//   rho'    = -lambda (rho - rho_f) + (1 + k_r) xi^2 Delta                 (13')
//   v_f: v_hat slew-limited to a_max (RecommendedInput::v_hat); rho_f: rho_inf plus the measured
//   noise's reach (RecommendedInput::rho_floor); both kept by PerformanceController.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/law/controller_config.h"
#include "amigobot_tracking/core/law/yield_rollout.h"
#include "amigobot_tracking/core/robot/diamond.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

struct RecommendedInput {
  Pose2 pose;
  Eigen::Vector2d p_r = Eigen::Vector2d::Zero();
  Eigen::Vector2d e = Eigen::Vector2d::Zero();   // p_d - p_r
  Eigen::Vector2d v_hat = Eigen::Vector2d::Zero();  // the feed-forward v_f
  Eigen::Vector2d v_smooth = Eigen::Vector2d::Zero();  // v_f averaged over field_lookahead (controller.h)
  double rho = 1.0;
  double rho_floor = 0.0;  // where rho decays to: rho_inf, or more under measurement noise (controller.h)
  Twist2 previous;         // the last command, which u leaves at most (v_accel, w_accel) h away from
  double h = 0.0;          // [s] since that command; 0: none (the first step is not bounded)
  std::optional<YieldManoeuvre> committed;  // the manoeuvre yielding to a person, advanced to now (yield_rollout.h)
  const ActuatorModel* base = nullptr;      // the base as it moves now (yield_rollout.h), null: settled at `previous`
};

struct RecommendedCommand {
  bool valid = false;
  Twist2 u;                                           // inside the diamond
  Twist2 u_nominal;                                   // G^-1 u_nom, before the filter
  Eigen::Vector2d u_track = Eigen::Vector2d::Zero();  // the tracking part of (9)
  Eigen::Vector2d u_nom = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();
  double blend = 0.0;       // 0: straight at the target; 1: the field's direction
  double shortfall = 0.0;   // Delta of (13')
  double relaxation = 0.0;  // (1 + k_r) xi^2 Delta, the relaxation term of (13')
  double slack = 0.0;       // the filter's slack (0 unless the barrier rows conflict)
  bool yielded = false;     // u is yield_rollout.h's manoeuvre, not the filter's command
  YieldManoeuvre manoeuvre; // that manoeuvre (when yielded): the next step's `committed`
  int barrier_rows = 0;
  int active_barriers = 0;
  double min_clearance = 0.0;  // of the disks the filter holds (safetyClearance) [m]; +inf without obstacles
};

RecommendedCommand recommendedCommand(const ControllerConfig& config, const DiamondSet& diamond,
                                      const RecommendedInput& in, const std::vector<Disk>& obstacles);

// One step of (13') of length h: the prescribed decay integrated exactly, plus the relaxation
// term (RecommendedCommand::relaxation, from the last step) held over min(h, max_relaxation_interval).
// rho_floor: where rho decays to (>= rho_inf; RecommendedInput::rho_floor).
double recommendedRhoStep(const ControllerConfig& config, double rho, double relaxation, double h, double rho_floor);

}  // namespace core
}  // namespace amigobot_tracking

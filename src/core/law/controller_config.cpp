#include "amigobot_tracking/core/law/controller_config.h"

#include <cmath>
#include <sstream>

#include "amigobot_tracking/core/law/band_implicit.h"
#include "amigobot_tracking/core/robot/diamond.h"
#include "amigobot_tracking/core/law/law_registry.h"

namespace amigobot_tracking {
namespace core {
namespace {

FieldTable<ControllerConfig> makeTable() {
  using C = ControllerConfig;
  using P = PaperOptions;
  using R = RecommendedOptions;
  FieldTable<C> t = {
      field("robot_radius", &C::robot_radius, "m", "body radius R", boundedRadius()),
      field("offset", &C::offset, "m", "distance r of the controlled point ahead of the centre", positive()),
      live(field("v_max", &C::v_max, "m/s", "diamond half-width in v", positive())),
      live(field("w_max", &C::w_max, "rad/s", "diamond half-width in omega", positive())),
      live(field("k_d", &C::k_d, "m/s", "tracking gain on T(|e|/rho), eq. (9)", positive())),
      live(field("k_o", &C::k_o, "-", "gain of the repulsive term u_c", positive())),
      live(field("lambda", &C::lambda, "1/s", "prescribed decay rate of rho", positive())),
      live(field("rho_inf", &C::rho_inf, "m", "steady-state tracking bound", positive())),
      field("rho_0", &C::rho_0, "m", "rho(0), > rho_inf and > |e(0)|", positive()),
      live(field("k_r", &C::k_r, "-", "relaxation gain of the adaptive law (13)", positive())),
      live(field("delta", &C::delta, "m", "obstacle detection distance beyond contact, eq. (10)", positive())),
      field("body_safe", &C::body_safe, "-", "effective radius R + r in (10), so the body stays clear"),
      field("min_margin", &C::min_margin, "m", "floor of the distance to contact in (10), < delta", positive()),
      field("max_error_ratio", &C::max_error_ratio, "-",
            "|e|/rho is kept at or below this by widening rho; > xi* with xi* atanh xi* = k_o/k_r",
            interval(0.0, true, 1.0, true)),
      field("max_relaxation_interval", &C::max_relaxation_interval, "s",
            "longest gap between steps the relaxation term of (13) spans (stalls)", duration()),
      field("max_rho_rate", &C::max_rho_rate, "m/s",
            "cap of the relaxation term's rate in (13) (band chattering); 0 = none, the paper", nonNegative()),
      field("law", &C::law, "-", "control law: paper (eqs. 9-13), fixed_rho (paper without adaptation) or recommended (field, safety filter, 13')",
            oneOf(controlLawNames())),
      // The recommended law's options (RecommendedOptions).
      nested(&C::recommended, field("barrier_rate", &R::barrier_rate, "1/s",
                                    "recommended law: barrier rate gamma, clearance' >= -gamma (clearance - min_margin)",
                                    positive())),
      nested(&C::recommended, field("body_margin", &R::body_margin, "m",
                                    "recommended law: the body and p_r's R-disk are held this much wider (sensing error)",
                                    boundedRadiusOrOff())),
      nested(&C::recommended, field("field_margin", &R::field_margin, "m",
                                    "recommended law: width of the field's bend around a disk's zone", positive())),
      nested(&C::recommended,
             field("field_lookahead", &R::field_lookahead, "s",
                   "recommended law: a target in or near a zone, the field aims this far ahead along its smoothed velocity",
                   durationOrZero())),
      live(nested(&C::recommended,
                  field("command_rise_time", &R::command_rise_time, "s",
                        "recommended law: the command moves by at most (v_max, w_max) h / this per step (0: no bound)",
                        durationOrZero()))),
      nested(&C::recommended,
             field("plan_braking", &R::plan_braking, "-",
                   "recommended law: barrier rows bound the approach speed by the base's braking (ramps, latency)")),
      nested(&C::recommended,
             field("obstacle_lookahead", &R::obstacle_lookahead, "s",
                   "recommended law: the field sees a moving disk along its path over this long (0: where it is)",
                   durationOrZero())),
      nested(&C::recommended,
             field("yield_horizon", &R::yield_horizon, "s",
                   "recommended law: a command that would bring the body within yield_clearance of a moving obstacle within this is replaced by a manoeuvre judged on the base's ramps (0: off)",
                   durationOrZero())),
      nested(&C::recommended,
             field("yield_clearance", &R::yield_clearance, "m",
                   "recommended law: the predicted body clearance from a moving obstacle that counts as enough (yield_horizon)",
                   nonNegative())),
      // Beyond the paper: each default is the paper's law.
      nested(&C::paper, field("tangential_avoidance", &P::tangential_avoidance, "-",
                              "tangential escape from the saddle behind a disk")),
      nested(&C::paper, field("k_t", &P::k_t, "-", "gain of the tangential term relative to u_c", nonNegative())),
      nested(&C::paper, field("tangential_hysteresis", &P::tangential_hysteresis, "-",
                              "sine margin before the passing side may switch", interval(0.0, false, 1.0, true))),
      field("moving_obstacles", &C::moving_obstacles, "-", "obstacle velocities in (10): feed-forward, wider band"),
      nested(&C::paper, field("obstacle_horizon", &P::obstacle_horizon, "s",
                              "detection band grows by approach speed times this", durationOrZero())),
      field("predict_target", &C::predict_target, "-", "p_d = latest sample + v_hat x sample age"),
      field("compensate_pose_age", &C::compensate_pose_age, "-",
            "move the pose forward along the commands applied over its age"),
      field("max_prediction", &C::max_prediction, "s", "ages beyond this are not extrapolated further",
            durationOrZero()),
  };
  include(&t, "estimator/", &C::estimator, estimatorFields());
  return t;
}

}  // namespace

const std::vector<std::string>& controlLawNames() {
  static const std::vector<std::string> names = robotLawNames();
  return names;
}

const FieldTable<ControllerConfig>& controllerFields() {
  static const FieldTable<ControllerConfig> table = makeTable();
  return table;
}

bool ControllerConfig::obstacleVelocities() const {
  if (moving_obstacles) return true;
  const LawEntry* entry = findLaw(law);
  return entry && entry->obstacle_velocities;
}

std::string ControllerConfig::validate() const {
  const std::string bad = checkFields(controllerFields(), *this);
  if (!bad.empty()) return bad;
  std::ostringstream err;
  if (rho_0 <= rho_inf) {
    err << "rho_0: must be > rho_inf = " << rho_inf << ", got " << rho_0;
  } else if (!(max_error_ratio > sustainedConflictRatio(k_r, k_o))) {
    err << "max_error_ratio: must be above " << sustainedConflictRatio(k_r, k_o)
        << ", the |e|/rho of a sustained conflict for k_r = " << k_r << " and k_o = " << k_o
        << " (xi atanh xi = k_o / k_r; raise max_error_ratio or k_r), got " << max_error_ratio;
  } else if (min_margin >= delta) {
    err << "min_margin: must be < delta = " << delta << ", got " << min_margin;
  } else {
    const std::string estimator_error = estimator.validate();
    if (!estimator_error.empty()) err << "estimator/" << estimator_error;
  }
  return err.str();
}

double sustainedConflictRatio(double k_r, double k_o) {
  const double target = k_o / k_r;
  double lo = 0.0, hi = 1.0;  // xi atanh xi increases from 0 to +inf on [0, 1)
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid * std::atanh(mid) < target) lo = mid; else hi = mid;
  }
  return hi;
}

std::string bandReachError(const ControllerConfig& config, double control_period, double obstacle_speed) {
  const double worst_period = kWorstPeriodFactor * control_period;
  const double speed = maxOffsetSpeed(DiamondSet(config.v_max, config.w_max), config.offset) + obstacle_speed;
  const double reach = speed * worst_period;
  if (reach < config.delta) return "";
  std::ostringstream err;
  err << "delta = " << config.delta << " m is crossed in one control period: the offset point closes up to "
      << reach << " m on a disk in a worst period of " << worst_period << " s (" << kWorstPeriodFactor << " x "
      << control_period << " s, timer jitter; v_max = " << config.v_max << " m/s, w_max = " << config.w_max
      << " rad/s, offset = " << config.offset << " m, obstacle speed " << obstacle_speed << " m/s); raise delta above "
      << reach << " m, lower v_max/w_max or raise control_rate";
  return err.str();
}

}  // namespace core
}  // namespace amigobot_tracking

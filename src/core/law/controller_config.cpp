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
      defaultText(field("robot_radius", &C::robot_radius, "m",
                        "body radius R: the URDF's base_frame collision (else visual) footprint radius when "
                        "robot_description has one; this parameter overrides it",
                        boundedRadius()),
                  "URDF, else 0.18"),
      defaultText(field("offset", &C::offset, "m",
                        "distance r of the controlled point p_r ahead of the centre: the x of urdf_offset_link "
                        "in the URDF when robot_description has it; this parameter overrides it",
                        positive()),
                  "URDF, else 0.3"),
      defaultText(live(field("v_max", &C::v_max, "m/s",
                             "diamond half-width in v, at most the robot file's v_max: a larger one is refused at "
                             "start and on reconfigure, so cmd_vel never leaves the driver's diamond",
                             positive()),
                       0.01, 2.0),
                  "the robot file's v_max (amigo: 0.3)"),
      defaultText(live(field("w_max", &C::w_max, "rad/s",
                             "diamond half-width in omega, at most the robot file's w_max: a larger one is refused "
                             "at start and on reconfigure, so cmd_vel never leaves the driver's diamond",
                             positive()),
                       0.01, 10.0),
                  "the robot file's w_max (amigo: 0.8)"),
      live(field("k_d", &C::k_d, "m/s", "tracking gain on T(|e|/rho), eq. (9)", positive()), 0.001, 10.0),
      live(field("k_o", &C::k_o, "-", "repulsive gain: weight of the obstacle term u_c of (10) in (9)", positive()),
           0.001, 10.0),
      live(field("lambda", &C::lambda, "1/s", "prescribed decay rate of the performance bound rho", positive()),
           0.001, 20.0),
      live(field("rho_inf", &C::rho_inf, "m",
                 "steady-state bound of |e|: rho decays to it; on the robot also the largest pose jump per cycle, "
                 "beyond what the robot file's max_velocity explains, before a localisation stop",
                 positive()),
           0.001, 5.0),
      field("rho_0", &C::rho_0, "m",
            "rho at (re)start, > rho_inf (not given for the paper's experiment: our choice); the node starts rho at "
            "max(rho_0, 2|e|) on enable and every restart, as the paper requires |e(0)| < rho(0)",
            positive()),
      live(field("k_r", &C::k_r, "-", "relaxation gain of the adaptive law (13)", positive()), 0.001, 10.0),
      live(field("delta", &C::delta, "m",
                 "obstacle detection distance beyond contact, eq. (10); the node refuses one the offset point "
                 "can cross in a control period (stretched 1.5x for timer jitter)",
                 positive()),
           0.002, 3.0),
      field("body_safe", &C::body_safe, "-",
            "effective radius R + r in (10), so the body, not only p_r, stays clear (the recommended law: "
            "barrier rows for the body disk itself)"),
      field("min_margin", &C::min_margin, "m",
            "numerical guard: floor of the distance to contact in (10), keeping u_c finite, < delta; the "
            "recommended law's barriers keep the clearance above it",
            positive()),
      field("max_error_ratio", &C::max_error_ratio, "-",
            "numerical guard: rho is widened to keep |e|/rho at or below this (far start, discretisation); must "
            "exceed xi*, with xi* atanh xi* = k_o/k_r (0.968 for k_o = 1, k_r = 0.5)",
            interval(0.0, true, 1.0, true)),
      field("max_relaxation_interval", &C::max_relaxation_interval, "s",
            "the relaxation term of (13) spans at most this much of a gap between steps (timer stall), so a "
            "stale near-contact conflict is not multiplied by the gap; the prescribed decay spans all of it",
            duration()),
      field("max_rho_rate", &C::max_rho_rate, "m/s",
            "cap of the relaxation term's rate in (13), so band chattering (a band entered and left every step) "
            "cannot make rho jump; 0: none, the paper",
            nonNegative()),
      defaultText(field("law", &C::law, "-",
                        "control law: paper (eqs. (9)-(13) as published, with the switches beyond the paper), "
                        "fixed_rho (the same without the adaptation of (13)) or recommended (navigation field, "
                        "safety filter over the diamond, rho law (13'); docs/recommended_law.md); the list is "
                        "core/law/law_registry.cpp",
                        oneOf(controlLawNames())),
                  "paper (tracking.yaml: recommended)"),
      // The recommended law's options (RecommendedOptions).
      nested(&C::recommended,
             field("barrier_rate", &R::barrier_rate, "1/s",
                   "recommended law: barrier rate gamma of the safety filter, clearance' >= -gamma (clearance - "
                   "min_margin); from amigobot_sim --tune on the clutter suite (at 2 the ring class averaged "
                   "1.07 m^2)",
                   positive())),
      defaultText(nested(&C::recommended,
                         field("body_margin", &R::body_margin, "m",
                               "recommended law: the body and p_r's R-disk are held this much wider (field zones "
                               "and safety filter), for laser noise and localisation error; in the simulator it "
                               "keeps the true body at least 3 cm off obstacles",
                               boundedRadiusOrOff())),
                  "0.035 (tracking.yaml: 0.05)"),
      nested(&C::recommended,
             field("field_margin", &R::field_margin, "m",
                   "recommended law: the navigation field bends around a disk's zone within this, and blends in "
                   "where the line of sight to the target passes closer",
                   positive())),
      nested(&C::recommended,
             field("field_lookahead", &R::field_lookahead, "s",
                   "recommended law: when the target is in or near a zone, the field aims up to this far ahead of "
                   "it along its velocity averaged over the same time (at most |e| ahead); 0: at the target",
                   durationOrZero())),
      live(nested(&C::recommended,
                  field("command_rise_time", &R::command_rise_time, "s",
                        "recommended law: the command moves by at most (v_max, w_max) x period / this per step, a "
                        "rate box in the safety filter that gives way (K = 10 times faster than a barrier row is "
                        "short) where a barrier cannot hold inside it; 0: no bound",
                        durationOrZero())),
           0.0, 5.0),
      nested(&C::recommended,
             field("plan_braking", &R::plan_braking, "-",
                   "recommended law: the barrier rows bound the approach speed by what the base can still brake "
                   "(the robot file's ramps, firmware cycle and latency); false: barrier_rate alone")),
      nested(&C::recommended,
             field("nominal_speed_cap", &R::nominal_speed_cap, "-",
                   "recommended law: the nominal offset-point velocity is shortened to at most this times v_max "
                   "along its direction before the safety filter, which otherwise projects a long one onto the "
                   "diamond's (v_max, 0) corner and drops the turn (0: no cap)",
                   nonNegative())),
      nested(&C::recommended,
             field("obstacle_lookahead", &R::obstacle_lookahead, "s",
                   "recommended law: the navigation field sees a moving obstacle along the path it walks over "
                   "this long, so the robot passes behind a person and steps out of one's way (0: where it is now)",
                   durationOrZero())),
      nested(&C::recommended,
             field("yield_horizon", &R::yield_horizon, "s",
                   "recommended law: when the command would bring the body within yield_clearance of a moving "
                   "obstacle within this, a manoeuvre judged on the base's ramps replaces it, stepping aside from "
                   "a person it cannot outrun (0: off)",
                   durationOrZero())),
      nested(&C::recommended,
             field("yield_clearance", &R::yield_clearance, "m",
                   "recommended law: the predicted body clearance from a moving obstacle that counts as enough "
                   "(yield_horizon), beyond body_margin",
                   nonNegative())),
      // Beyond the paper: each default is the paper's law.
      nested(&C::paper, field("tangential_avoidance", &P::tangential_avoidance, "-",
                              "beyond the paper: tangential escape from the saddle behind a disk (disks whose "
                              "detection zones overlap: around the group)")),
      nested(&C::paper, field("k_t", &P::k_t, "-",
                              "beyond the paper: gain of the tangential term u_t relative to u_c, capped so "
                              "k_o |u_t| <= k_t |attraction of (9)| (a group of disks: the whole cap)",
                              nonNegative())),
      nested(&C::paper, field("tangential_hysteresis", &P::tangential_hysteresis, "-",
                              "beyond the paper: sine margin before the passing side may switch (0.2 flipped sides "
                              "on the saddle)",
                              interval(0.0, false, 1.0, true))),
      field("moving_obstacles", &C::moving_obstacles, "-",
            "beyond the paper: use obstacle velocities in (10) (feed-forward, band widened by obstacle_horizon); "
            "on the robot the laser disks carry the velocities of obstacle_tracker (tracked across scans) only "
            "when true"),
      nested(&C::paper, field("obstacle_horizon", &P::obstacle_horizon, "s",
                              "beyond the paper, with moving_obstacles: the detection band of (10) grows by each "
                              "obstacle's approach speed times this",
                              durationOrZero())),
      field("predict_target", &C::predict_target, "-",
            "beyond the paper: extrapolate the target sample to the control time with the estimated velocity, "
            "p_d = latest sample + v_hat x sample age"),
      field("compensate_pose_age", &C::compensate_pose_age, "-",
            "beyond the paper: move the robot pose forward along the commands applied over its age"),
      field("max_prediction", &C::max_prediction, "s",
            "ages beyond this are not extrapolated further (predict_target, compensate_pose_age)",
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

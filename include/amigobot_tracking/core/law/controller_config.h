// Parameters of the tracking controller, SI units. Defaults are the paper's real-robot
// experiment (Section 5.3) on an AmigoBot; values the paper leaves open are marked.
#pragma once

#include <string>

#include "amigobot_tracking/core/robot/actuator_limits.h"
#include "amigobot_tracking/core/law/estimator.h"
#include "amigobot_tracking/core/support/field_table.h"

namespace amigobot_tracking {
namespace core {

// The paper's law's own switches beyond the paper (paper_controller.h; fixed_rho too): each
// default reproduces the paper exactly.
struct PaperOptions {
  bool tangential_avoidance = false;   // escape the saddle behind a disk (avoidance.h)
  double k_t = 1.0;                    // [-] gain of the tangential term, relative to u_c;
                                       // k_o |u_t| <= k_t |attraction of (9)|
  double tangential_hysteresis = 0.6;  // [-] sine margin before the passing side may switch
                                       // (0.2 flipped sides 4 times in 0.6 s on the saddle:
                                       // near the disk a short e turns by more than 0.2 as the
                                       // escape itself moves p_r sideways; docs/beyond_paper.md)
  double obstacle_horizon = 1.0;       // [s] with moving_obstacles, (10)'s detection band grows
                                       // by approach speed * horizon
};

// The recommended law's own options (recommended_law.h; its keys are read at the top level:
// barrier_rate, body_margin, ...). The paper's law never reads them.
struct RecommendedOptions {
  double barrier_rate = 5.333;         // [1/s] gamma of the barrier rows (amigobot_sim --tune):
                                       // clearance' >= -gamma (clearance - min_margin)
  double body_margin = 0.035;          // [m] the recommended law holds the body (and the disk of
                                       // radius R around p_r) this much wider: laser noise and
                                       // localisation error on a real robot (config/tracking.yaml:
                                       // 0.05); in the simulator it keeps the true body >= 3 cm off
                                       // (at 0 the clutter benchmark's U classes grazed at 0.15 mm)
  double field_margin = 0.1;           // [m] the recommended law's field bends around a disk's
                                       // zone within this, and blends in when the line of sight
                                       // to the target passes closer than this
  double field_lookahead = 1.5;        // [s] a target in or near a zone: the field aims this far
                                       // ahead along its smoothed velocity (0: at the target)
  double command_rise_time = 0.25;     // [s] the recommended law's command changes by at most
                                       // (v_bar, w_bar) h / this per step: the safety filter's
                                       // rate box, which gives way to a barrier (0: no bound)
  bool plan_braking = true;            // the recommended law's barrier rows bound the approach speed
                                       // by what the base can still brake (`actuator`'s ramps and
                                       // delays: safety_filter.h); false: gamma alone
  double obstacle_lookahead = 2.0;     // [s] the recommended law's field sees a moving disk along
                                       // the path it walks over this long (0: where it is now)
  double yield_horizon = 5.0;          // [s] when the filter's command would bring the body within
                                       // yield_clearance of a moving disk within this, a manoeuvre
                                       // judged on the base's ramps replaces it (yield_rollout.h; 0: off)
  double yield_clearance = 0.115;      // [m] the predicted body clearance that counts as enough there
                                       // (beyond body_margin: 0.15 m from the true body by default)
  double nominal_speed_cap = 0.0;      // [-] the nominal offset-point velocity is shortened to at most
                                       // this times v_bar along its direction before the filter (0: no cap;
                                       // 1.5 helped the benchmarks but stalled the robot near a virtual
                                       // obstacle in make demo: docs/recommended_law.md)
};

struct ControllerConfig {
  // Robot.
  double robot_radius = 0.18;  // R [m]: AmigoBot body radius (ARIA RobotRadius 180 mm).
  double offset = 0.3;         // r [m]: distance of the controlled point ahead of the centre.
  double v_max = 0.3;          // v_bar [m/s]: diamond half-width in v.
  double w_max = 0.8;          // w_bar [rad/s]: diamond half-width in w.
  // Control law (9).
  double k_d = 0.15;           // [m/s] tracking gain on T(|e|/rho).
  double k_o = 1.0;            // [-] gain of the repulsive term u_c.
  double lambda = 0.5;         // [1/s] prescribed decay rate of rho.
  double rho_inf = 0.1;        // [m] steady-state tracking bound.
  double rho_0 = 1.0;          // [m] rho(0) (not given for the experiment: our choice).
  // Adaptive law (13).
  double k_r = 0.5;            // [-] relaxation gain.
  bool adaptive_rho = true;    // false: the fixed-rho baseline, rho follows the prescribed
                               // decay only (the relaxation term of (13) is dropped).
  // Avoidance (10).
  double delta = 0.25;         // [m] detection distance beyond contact (not given for the
                               // experiment; Table 1's 0.016 m is too short at 20 Hz).
  bool body_safe = true;       // effective radius R + r, so the body (not only p_r) stays clear.
  double min_margin = 1e-3;    // [m] floor of the distance to contact in (10): keeps u_c finite.
  // Envelope: |e|/rho is kept at or below this ratio by widening rho (start far away,
  // discretisation); T is undefined at 1. It must lie above the ratio a sustained conflict
  // settles at under (13), xi* with xi* atanh(xi*) = k_o / k_r (sustainedConflictRatio;
  // 0.968 for the paper's k_r = 0.5, k_o = 1): below it the rule, not (13), holds rho.
  // Saturation presses |e|/rho closer to 1 still (0.99956 on the rose with Table 1's limits,
  // held by (13) alone): hence 0.9999, a guard for the start and overshooting steps only
  // (docs/controller.md).
  double max_error_ratio = 0.9999;
  // [s] the relaxation term of (13) uses the last step's conflict over at most this long,
  // so a stall of the control loop does not multiply a stale (near contact, huge) conflict
  // by the gap: a few control periods. The prescribed decay still spans the whole gap.
  double max_relaxation_interval = 0.2;
  // [m/s] > 0: the relaxation term of (13) raises rho at most this fast, so band chattering
  // (a band entered and left every step, each entry with a near-contact conflict) cannot make
  // rho jump (prescribed_performance.h); 0: unbounded, the paper's (13).
  double max_rho_rate = 0.0;
  EstimatorConfig estimator;

  // Which law: a robot law of the registry (law_registry.h): "paper" ((9)-(13) as published,
  // with its options `paper`), "fixed_rho" (the same without (13)'s adaptation) or "recommended"
  // (recommended_law.h: a navigation field, a safety filter over the diamond and (13')).
  std::string law = "paper";
  // The base's dynamics the recommended law brakes with: not a parameter of its own, the robot
  // description's (config/robots/); defaults the AmigoBot's.
  ActuatorLimits actuator;
  // The paper's law's options (its keys are read at this level: tangential_avoidance, k_t, ...).
  PaperOptions paper;
  // The recommended law's options (barrier_rate, body_margin, field_margin, ...: this level too).
  RecommendedOptions recommended;
  // Beyond the paper: each switch off reproduces the paper exactly.
  bool moving_obstacles = false;       // use obstacle velocities in (10) (avoidance.h), and on the
                                       // robot the laser disks carry the tracker's velocities
  bool predict_target = false;         // p_d = latest sample + v_hat * (t - sample stamp)
  bool compensate_pose_age = false;    // move the pose forward along the commands applied over its age
  double max_prediction = 0.5;         // [s] ages beyond this are not extrapolated further

  // Whether obstacle velocities are used: with moving_obstacles, or whenever a disk carries one
  // by a law the registry says does so (law_registry.h's obstacle_velocities: the recommended
  // law's barrier rows and field). On the robot the laser disks carry the tracker's velocities
  // only with moving_obstacles (tracking_node.cpp says why).
  bool obstacleVelocities() const;
  // The radius used in (10): R, or R + r when body_safe.
  double effectiveRadius() const { return body_safe ? robot_radius + offset : robot_radius; }
  // Empty when valid, otherwise "key: reason" naming the first bad field (the table's
  // bounds, then rho_0 > rho_inf, min_margin < delta and the estimator's own rules).
  std::string validate() const;
};

// The values of `law`: the registry's laws that the tracking node runs (law_registry.h).
const std::vector<std::string>& controlLawNames();

// Every field read from parameters and scenarios, the estimator's under "estimator/"
// (adaptive_rho follows the scenario's controller variant). Live rows: dynamic_reconfigure.
const FieldTable<ControllerConfig>& controllerFields();

// xi* in (0, 1) with xi* atanh(xi*) = k_o / k_r: where |e|/rho settles when the barrier holds
// the offset point against the attraction for long with large rho (then
// rho' ~ lambda rho (k_r xi T(xi) / k_o - 1) in (13)). 1 when that is 1 in double precision.
double sustainedConflictRatio(double k_r, double k_o);

// A timer period can stretch: the band check assumes a period up to this times the nominal one.
constexpr double kWorstPeriodFactor = 1.5;

// Empty when a command held for the worst period (kWorstPeriodFactor * control_period [s])
// cannot close the detection band on a disk moving at obstacle_speed [m/s] toward the offset
// point ((max offset-point speed of the diamond + obstacle_speed) * worst period < delta);
// otherwise an error naming delta, v_max, w_max, offset, the periods and the obstacle speed.
// The explicit (10) then never sees the band it jumps over (the offline simulator avoids
// this with its band-implicit step; a fixed-rate node cannot): the band is entered and left
// on alternate steps and rho jumps (Section 5.3's course with delta = 0.016 at 20 Hz).
std::string bandReachError(const ControllerConfig& config, double control_period, double obstacle_speed = 0.0);

}  // namespace core
}  // namespace amigobot_tracking

// Offline closed loop: a control law driving an ideal unicycle after a reference, the
// target seen through a sampled, noisy, delayed sensor, among static or moving disks.
// Fixed or variable step (step_size.h). Shared by tests, the demo, the benchmarks and the
// offline simulator.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "amigobot_tracking/core/robot/actuator_limits.h"
#include "amigobot_tracking/core/robot/actuator_model.h"
#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/core/perception/obstacle_motion.h"
#include "amigobot_tracking/sim/metrics.h"
#include "amigobot_tracking/core/reference/reference.h"
#include "amigobot_tracking/core/supervision/resume_ramp.h"
#include "amigobot_tracking/sim/step_size.h"
#include "amigobot_tracking/sim/target_sensor.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace sim {

// Where the v_hat of the law comes from.
enum class VelocitySource {
  kPaperEstimator,    // eqs. (3)-(4)
  kFiniteDifference,  // finite differences + first-order low-pass (baseline_estimators.h)
  kKalman,            // constant-velocity Kalman filter
};

// How a step's command is formed from the state (the command is always held over the step).
enum class Integrator {
  kExplicit,      // from the state at the step start; with a variable step, the fine step
                  // inside detection bands, where (10) is stiff
  kBandImplicit,  // the same, but the repulsive term of the nearest reachable obstacle is
                  // backward-Euler over the step (band_implicit.h), so the variable step stays
                  // long in the bands too. The paper and fixed-rho laws only; the proportional
                  // baseline, and moving obstacles (whose term stays explicit), fall back to kExplicit.
  kSecondOrder,   // kBandImplicit, and each command is computed at the middle of its step (the
                  // pose predicted there with the previous command, the target sampled there)
                  // with the estimator stepping BDF2 (estimator.h): the held command, the
                  // estimator and the averages become second order in the step instead of first.
                  // Falls back to kExplicit where kBandImplicit does.
};

struct BaselineParams {
  double k_p = 30.0;             // [1/s] gain of the proportional law
  double lowpass_tau = 0.05;     // [s] time constant of kFiniteDifference
  double kalman_accel_std = 10.0;       // [m/s^2] process noise of kKalman
  double kalman_measurement_std = 0.01; // [m] measurement noise of kKalman (> 0)
};

// What the robot's base does to the law's command (core/robot/actuator_model.h).
struct RobotDynamics {
  // true: the command moves the body at once (the paper's unicycle; Section 5 stays exact).
  // A setup built in code is ideal unless it says otherwise; a scenario file is `firmware`
  // (ideal = false) unless it says `robot.dynamics: ideal`.
  bool ideal = true;
  core::ActuatorLimits limits;                 // the AmigoBot's (config/robots/amigo.yaml)
  double half_track = core::kAmigoHalfTrack;   // [m] b of the wheel-speed limit
};

struct ClosedLoopSetup {
  core::ControllerConfig controller;
  core::Pose2 initial_pose;
  RobotDynamics dynamics;        // the base between the law's command and the body
  std::vector<core::Disk> obstacles;
  // How the obstacles move (core/perception/obstacle_motion.h), one per obstacle; empty: all static. Each
  // path is walked from its obstacle's centre: centre(t) = centre + positionAt(t) - start (a
  // scenario sets start = centre); the controller is given Disk::velocity = velocityAt(t)
  // (ground truth; used with moving_obstacles).
  std::vector<core::ObstacleMotion> obstacle_motions;
  double duration = 10.0;        // [s]
  double control_period = 1e-3;  // [s] controller and integration step (the fine step)
  double max_step = 0.0;         // [s] > control_period: variable step up to this (step_size.h)
  double sample_period = 0.0;    // [s] target sampling; 0 = every control step. Steps land on
                                 // sample deliveries when sample_period >= max_step.
  StepPolicy step_policy;        // thresholds of the variable step (its min/max come from above)
  Integrator integrator = Integrator::kExplicit;
  TargetSensorConfig sensor;     // noise, delay, jumps (its sample_period is replaced by the one above)
  PoseSensorConfig pose_sensor;  // how late and how often the robot's own pose arrives
  // Which law closes the loop: a name of the law registry (core/law/law_registry.h).
  std::string law = "paper";
  // The robot's laws (LawEntry::on_robot) run core::TrackingLoop (the nodelet's cycle) with inputs
  // that never go stale. resume_at_start: start as the robot resumes (controller restart,
  // the command leaving zero on resume_ramp) instead of the paper's start.
  bool resume_at_start = false;
  core::RampLimits resume_ramp;
  VelocitySource velocity_source = VelocitySource::kPaperEstimator;
  BaselineParams baseline;
  double estimator_settle_time = 0.5;  // [s] estimator errors after this count as "settled"
};

// What an observer sees at every step: the state before the command is applied.
struct ClosedLoopStep {
  double t = 0.0;
  double h = 0.0;                  // [s] how long the command is held (0 at the last step)
  core::Pose2 pose;
  core::ReferenceState reference;        // the true target
  core::TargetSample sample;             // what the controller was given
  core::PoseSample pose_sample;          // the robot pose the controller was given (== pose, stamp t
                                   // without a pose sensor)
  core::ControllerOutput output;
  Eigen::Vector2d p_r_true = Eigen::Vector2d::Zero();  // the true offset point (output.p_r is
                                                      // the controller's belief)
  double clearance_offset = 0.0;   // disk of radius R around the true p_r to the nearest obstacle [m]
  double clearance_body = 0.0;     // disk of radius R around the centre p [m]
  core::Twist2 body_velocity;      // what the body does now (== output.u with ideal dynamics)
  const std::vector<core::Disk>* obstacles = nullptr;  // where the obstacles are at t
};

struct ClosedLoopSummary {
  std::uint64_t steps = 0;
  double max_error_ratio = 0.0;      // max |e|/rho over the steps
  double final_error = 0.0;          // |e| at the end [m]
  double min_clearance_offset = 0.0; // disk of the effective radius around p_r as the controller
                                     // sees it (its pose may be late) [m]
  double min_clearance_body = 0.0;   // disk of radius R around the centre [m]
  std::uint64_t diamond_violations = 0;
  std::uint64_t invalid_steps = 0;   // NaN or unusable inputs
  std::uint64_t envelope_widenings = 0;
  std::uint64_t saturated_steps = 0;
  RunMetrics metrics;                // metrics.h (its offset clearance uses R, not R + r)
};

using ClosedLoopObserver = std::function<void(const ClosedLoopStep&)>;

// Setup errors ("field: reason"), checked before anything runs; empty when valid.
std::string validateSetup(const ClosedLoopSetup& setup);

// A motion at a constant velocity from t = 0 (what a scenario's `velocity: [vx, vy]` means).
core::ObstacleMotion constantMotion(const Eigen::Vector2d& start, const Eigen::Vector2d& velocity);
// The velocity of a motion made by constantMotion; false for any other motion.
bool isConstantMotion(const core::ObstacleMotion& motion, Eigen::Vector2d* velocity);

// The setup must be valid (validateSetup empty). Throws std::invalid_argument for a law whose
// library has not registered it (core::makeLaw: mrpt_reactive without sim_mrpt::provideReactiveLaw).
ClosedLoopSummary runClosedLoop(const ClosedLoopSetup& setup, const core::Reference& reference,
                                const ClosedLoopObserver& observer = {});

}  // namespace sim
}  // namespace amigobot_tracking

#include "amigobot_tracking/sim/closed_loop.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "amigobot_tracking/core/law/avoidance.h"
#include "amigobot_tracking/core/law/law_registry.h"
#include "amigobot_tracking/sim/baseline_estimators.h"
#include "amigobot_tracking/core/robot/offset_point.h"
#include "amigobot_tracking/core/support/small_angle.h"
#include "amigobot_tracking/core/supervision/tracking_loop.h"
#include "amigobot_tracking/core/robot/unicycle.h"

namespace amigobot_tracking {
namespace sim {
namespace {

// The duration of a constant-velocity motion's one leg [s]: longer than any run (about 30 years).
constexpr double kForever = 1e9;

// The setup's law, chosen once from the registry. A law the robot runs (LawEntry::on_robot)
// runs inside the tracking nodelet's own loop, as on the robot; the others run bare.
class Law {
 public:
  explicit Law(const ClosedLoopSetup& setup) {
    const core::LawEntry* entry = core::findLaw(setup.law);
    if (!entry) throw std::invalid_argument("controller.variant: unknown law '" + setup.law + "'");
    core::ControllerConfig config = setup.controller;
    if (!entry->on_robot) {
      bare_ = core::makeLaw(setup.law, core::LawSetup{config, setup.baseline.k_p});
      return;
    }
    config.law = setup.law;  // the variant names the law
    // The band-implicit step treats (10), which only some laws use.
    implicit_band_ = entry->band_implicit && setup.integrator != Integrator::kExplicit && !config.moving_obstacles;
    config.estimator.bdf2 = implicit_band_ && setup.integrator == Integrator::kSecondOrder;
    // A law that brakes with the base it drives (the recommended law) gets the scene's ramps
    // and delays, or none on the ideal body (infinite decelerations, no cycle, no latency).
    if (setup.dynamics.ideal) {
      config.actuator.trans_decel = config.actuator.rot_decel = std::numeric_limits<double>::infinity();
      config.actuator.cycle = config.actuator.latency = 0.0;
    } else {
      config.actuator = setup.dynamics.limits;
    }
    // The tracking nodelet's own loop, with inputs that never go stale: the scene's
    // disks are the operator's (never dropped), the start is the paper's (no restart, no
    // ramp) unless the setup asks for the robot's resume.
    core::TrackingLoopConfig loop;
    loop.controller = config;
    loop.supervisor.pose_timeout = loop.supervisor.scan_timeout = std::numeric_limits<double>::infinity();
    loop.supervisor.require_scan = false;
    loop.supervisor.control_period = setup.control_period;
    loop.supervisor.ramp = setup.resume_ramp;
    loop_ = std::make_unique<core::TrackingLoop>(loop);
    loop_->enable(setup.resume_at_start);
  }
  core::ControllerOutput step(double t, const core::PoseSample& robot, const core::TargetSample& sample,
                              const std::vector<core::Disk>& obstacles) {
    if (bare_) return bare_->step(t, robot, sample, obstacles);
    core::TrackingLoopInputs in;
    in.t = t;
    in.supervisor.have_pose = in.supervisor.have_target = true;
    in.supervisor.pose_age = t - robot.stamp;
    in.pose = robot;
    in.supervisor.target_age = t - sample.stamp;
    in.target = sample;
    in.virtual_disks = &obstacles;
    const core::TrackingLoopResult r = loop_->step(in);
    core::ControllerOutput out = r.output;
    out.u = r.u;  // what was sent (a zero when the supervisor refused the step)
    return out;
  }
  const core::DiamondSet& diamond() const { return bare_ ? bare_->diamond() : loop_->controller().diamond(); }
  // The setup's integrator applies (otherwise the loop runs kExplicit).
  bool implicitBand() const { return implicit_band_; }
  void setImplicitHorizon(double h) {
    if (implicit_band_) loop_->controller().setImplicitHorizon(h);
  }
  void setImplicitHorizon(double h, const core::Pose2& start, const Eigen::Vector2d& start_heading) {
    if (implicit_band_) loop_->controller().setImplicitHorizon(h, start, start_heading);
  }

 private:
  std::unique_ptr<core::TrackingLoop> loop_;  // a robot law, in the nodelet's loop
  std::unique_ptr<core::ControlLaw> bare_;    // any other law
  bool implicit_band_ = false;
};

std::unique_ptr<TargetVelocityFilter> makeFilter(const ClosedLoopSetup& setup) {
  switch (setup.velocity_source) {
    case VelocitySource::kFiniteDifference:
      return std::make_unique<FiniteDifferenceFilter>(setup.baseline.lowpass_tau);
    case VelocitySource::kKalman:
      return std::make_unique<ConstantVelocityKalman>(setup.baseline.kalman_accel_std,
                                                      setup.baseline.kalman_measurement_std);
    case VelocitySource::kPaperEstimator:
      break;
  }
  return nullptr;
}

// Where the robot stands relative to the obstacles, for the step choice.
StepSituation situationOf(const core::ControllerOutput& out, const core::Pose2& pose, const Eigen::Vector2d& p_r,
                          const core::ControllerConfig& c, const std::vector<core::Disk>& obstacles, double max_speed) {
  StepSituation s;
  s.max_speed = max_speed;
  s.error_ratio = out.rho > 0.0 ? out.e.norm() / out.rho : 0.0;
  s.distance = std::numeric_limits<double>::infinity();
  for (const core::Disk& o : obstacles) {
    const double band = (p_r - o.center).norm() - (c.effectiveRadius() + o.radius + c.delta);
    s.in_band = s.in_band || band <= 0.0;
    s.distance = std::min({s.distance, std::max(band, 0.0),
                           (pose.position() - o.center).norm() - (c.robot_radius + o.radius)});
  }
  return s;
}

// The pose after holding u for tau, to second order (chord at the mid heading): what the
// midpoint command needs. heading = (cos, sin) of pose.theta; the half turn by series.
core::Pose2 predictPose(const core::Pose2& pose, const Eigen::Vector2d& heading, const core::Twist2& u, double tau) {
  double cos_mid, sin_mid;
  core::rotateBySmall(0.5 * u.omega * tau, heading.x(), heading.y(), &cos_mid, &sin_mid);
  return {pose.x + u.v * tau * cos_mid, pose.y + u.v * tau * sin_mid, pose.theta + u.omega * tau};
}

}  // namespace

std::string validateSetup(const ClosedLoopSetup& setup) {
  std::ostringstream err;
  const std::string controller = setup.controller.validate();
  if (!controller.empty()) return controller;
  const std::string sensor = setup.sensor.validate();
  if (!sensor.empty()) return sensor;
  const std::string pose_sensor = setup.pose_sensor.validate();
  if (!pose_sensor.empty()) return pose_sensor;
  const std::string ramp = setup.resume_ramp.validate();
  if (!ramp.empty()) return "resume_ramp: " + ramp;
  if (!setup.dynamics.ideal) {
    const std::string limits = core::validateActuatorLimits(setup.dynamics.limits, setup.dynamics.half_track);
    if (!limits.empty()) return "robot dynamics: " + limits;
  }
  if (!setup.initial_pose.isFinite()) err << "initial_pose must be finite";
  else if (!(std::isfinite(setup.duration) && setup.duration > 0.0)) err << "duration must be > 0, got " << setup.duration;
  else if (!(std::isfinite(setup.control_period) && setup.control_period > 0.0))
    err << "control_period must be > 0, got " << setup.control_period;
  else if (!std::isfinite(setup.max_step) || setup.max_step < 0.0)
    err << "max_step must be >= 0 (0 = fixed step), got " << setup.max_step;
  else if (!std::isfinite(setup.sample_period) || setup.sample_period < 0.0)
    err << "sample_period must be >= 0, got " << setup.sample_period;
  else if (!setup.obstacle_motions.empty() && setup.obstacle_motions.size() != setup.obstacles.size())
    err << "obstacle_motions must be empty or one per obstacle";
  else if (!(setup.baseline.k_p > 0.0 && std::isfinite(setup.baseline.k_p))) err << "k_p must be > 0";
  else if (!(setup.baseline.lowpass_tau > 0.0 && std::isfinite(setup.baseline.lowpass_tau)))
    err << "lowpass_tau must be > 0";
  else if (!(setup.baseline.kalman_accel_std > 0.0 && std::isfinite(setup.baseline.kalman_accel_std)))
    err << "kalman_accel_std must be > 0";
  else if (!(setup.baseline.kalman_measurement_std > 0.0 && std::isfinite(setup.baseline.kalman_measurement_std)))
    err << "kalman_measurement_std must be > 0";
  else
    for (const core::Disk& o : setup.obstacles)
      if (!o.center.allFinite() || !(o.radius > 0.0 && std::isfinite(o.radius))) {
        err << "obstacles: every obstacle needs a finite centre and a radius > 0";
        break;
      }
  for (size_t j = 0; err.str().empty() && j < setup.obstacle_motions.size(); ++j) {
    const std::string why = setup.obstacle_motions[j].validate();
    if (!why.empty()) err << "obstacles[" << j << "].motion." << why;
  }
  return err.str();
}

core::ObstacleMotion constantMotion(const Eigen::Vector2d& start, const Eigen::Vector2d& velocity) {
  core::ObstacleMotion m;
  m.start = start;
  m.legs.push_back({kForever, velocity});
  return m;
}

bool isConstantMotion(const core::ObstacleMotion& motion, Eigen::Vector2d* velocity) {
  if (motion.start_time != 0.0 || motion.repeat || motion.legs.size() != 1 || motion.legs[0].duration != kForever)
    return false;
  *velocity = motion.legs[0].velocity;
  return true;
}

ClosedLoopSummary runClosedLoop(const ClosedLoopSetup& setup, const core::Reference& reference,
                                const ClosedLoopObserver& observer) {
  Law law(setup);
  std::unique_ptr<TargetVelocityFilter> filter = makeFilter(setup);
  TargetSensorConfig sensor_config = setup.sensor;
  sensor_config.sample_period = setup.sample_period;
  TargetSensor sensor(sensor_config, reference);
  PoseSensor pose_sensor(setup.pose_sensor);
  const bool pose_sensed = setup.pose_sensor.active();
  const core::ControllerConfig& config = setup.controller;
  StepPolicy policy = setup.step_policy;
  policy.min_step = setup.control_period;
  policy.max_step = std::max(setup.control_period, setup.max_step);
  const bool land_on_samples = setup.sample_period >= policy.max_step;
  const bool fixed_step = policy.max_step <= policy.min_step;
  double max_obstacle_speed = 0.0;
  for (const core::ObstacleMotion& m : setup.obstacle_motions)
    for (const core::MotionLeg& leg : m.legs) max_obstacle_speed = std::max(max_obstacle_speed, leg.velocity.norm());
  const double max_speed = std::max(config.v_max, config.offset * config.w_max) + max_obstacle_speed;

  ClosedLoopSummary summary;
  summary.min_clearance_offset = summary.min_clearance_body = std::numeric_limits<double>::infinity();
  MetricsAccumulator metrics;
  core::Pose2 pose = setup.initial_pose;
  // The firmware's base (ramps, cycle, latency, wheel limit) unless the setup is ideal.
  std::unique_ptr<core::ActuatorModel> base;
  if (!setup.dynamics.ideal) base = std::make_unique<core::ActuatorModel>(setup.dynamics.limits, setup.dynamics.half_track);
  std::vector<core::Disk> obstacles = setup.obstacles;
  const auto fixed_steps = static_cast<std::uint64_t>(std::llround(setup.duration / setup.control_period));
  double t = 0.0;
  double last_filter_stamp = -std::numeric_limits<double>::infinity();
  auto moveObstacles = [&](double at) {
    for (size_t j = 0; j < setup.obstacle_motions.size(); ++j) {
      // From the obstacle's centre (code that shifts a centre, Monte Carlo, moves its path too).
      const core::ObstacleMotion& motion = setup.obstacle_motions[j];
      obstacles[j].center = setup.obstacles[j].center + (motion.positionAt(at) - motion.start);
      obstacles[j].velocity = motion.velocityAt(at);
      // What a tracker knows of a person who stopped (core/perception/obstacle_tracker.h).
      obstacles[j].resume_velocity = motion.resumeVelocityAt(at);
    }
  };
  // The newest target sample at time `at`, with the baseline filter's velocity when one is used.
  auto measure = [&](double at) {
    core::TargetSample sample = sensor.at(at);
    if (filter) {
      if (sample.stamp > last_filter_stamp) {
        filter->update(sample.stamp, sample.position);
        last_filter_stamp = sample.stamp;
      }
      sample.has_velocity = true;
      sample.velocity = filter->velocity();
    }
    return sample;
  };
  const bool ideal_sensor = !filter && sensor_config.ideal();
  const bool implicit = law.implicitBand();
  const bool midpoint = implicit && setup.integrator == Integrator::kSecondOrder;
  double last_ratio = 1.0;  // the first step is the fine one
  core::Twist2 last_u;            // the command held over the last step
  // Land on the next sample delivery (when samples are sparser than steps) and on the end.
  auto landed = [&](double h) {
    const double delivery = sensor.nextDelivery(t);
    if (land_on_samples && delivery - t > 1e-9) h = std::min(h, delivery - t);
    const double pose_delivery = pose_sensor.nextDelivery(t);
    if (pose_delivery - t > 1e-9) h = std::min(h, pose_delivery - t);
    return std::min(h, setup.duration - t);
  };
  for (std::uint64_t k = 0;; ++k) {
    // Fixed step: t = k h exactly (no drift). Variable step: t accumulates.
    if (fixed_step) t = static_cast<double>(k) * setup.control_period;
    const bool last = fixed_step ? k >= fixed_steps : t >= setup.duration - 1e-9;
    moveObstacles(t);
    core::ReferenceState ref, ref_cmd;
    // Band-implicit: the step is chosen first (from the last step's |e|/rho; the bands need
    // no short step) and the controller is told how long its command will be held.
    double h = 0.0;
    if (implicit && !last) {
      StepSituation s;
      s.max_speed = max_speed;
      s.error_ratio = last_ratio;
      s.distance = std::numeric_limits<double>::infinity();
      h = fixed_step ? setup.control_period : landed(chooseStep(policy, s));
    }
    // Second order: the command is computed at the middle of the step it is held over.
    const double t_cmd = midpoint ? t + 0.5 * h : t;
    if (t_cmd > t) {
      reference.atPair(t, t_cmd, &ref, &ref_cmd);
    } else {
      ref = ref_cmd = reference.at(t);
    }
    // An ideal sensor's sample is the reference just evaluated (what sensor.at would return).
    const core::TargetSample sample = ideal_sensor ? core::TargetSample{t_cmd, ref_cmd.position} : measure(t_cmd);
    // (cos, sin) of the heading once per step: p_r, the prediction, the band and the arc share it.
    const Eigen::Vector2d heading(std::cos(pose.theta), std::sin(pose.theta));
    core::PoseSample robot{t_cmd, t_cmd > t ? predictPose(pose, heading, last_u, t_cmd - t) : pose};
    if (pose_sensed) {
      pose_sensor.record(t, pose);
      robot = pose_sensor.at(t_cmd);
    }
    const Eigen::Vector2d p_r = pose.position() + config.offset * heading;  // offsetPoint(pose)
    if (t_cmd > t) law.setImplicitHorizon(h, pose, heading);
    else law.setImplicitHorizon(h);
    const core::ControllerOutput out = law.step(t_cmd, robot, sample, obstacles);
    if (pose_sensed) pose_sensor.hold(out.u);
    last_ratio = out.rho > 0.0 ? out.e.norm() / out.rho : 0.0;
    last_u = out.u;

    if (!implicit && !last) {
      h = fixed_step ? setup.control_period
                     : landed(chooseStep(policy, situationOf(out, pose, p_r, config, obstacles, max_speed)));
    }
    const double clearance_offset = core::clearance(p_r, config.robot_radius, obstacles);
    const double clearance_body = core::clearance(pose.position(), config.robot_radius, obstacles);

    ++summary.steps;
    if (!out.valid) ++summary.invalid_steps;
    if (out.rho > 0.0) summary.max_error_ratio = std::max(summary.max_error_ratio, out.e.norm() / out.rho);
    summary.final_error = out.e.norm();
    summary.min_clearance_offset = std::min(summary.min_clearance_offset, out.min_clearance);
    summary.min_clearance_body = std::min(summary.min_clearance_body, clearance_body);
    if (!law.diamond().contains(out.u, kDiamondTolerance)) ++summary.diamond_violations;
    if (out.active.envelope_widened) ++summary.envelope_widenings;
    if (out.active.saturated) ++summary.saturated_steps;

    MetricSample m;
    m.h = h;
    m.e = out.e;
    m.rho = out.rho;
    m.u = out.u;
    m.diamond_norm = law.diamond().normalizedNorm(out.u);
    m.clearance_offset = clearance_offset;
    m.clearance_body = clearance_body;
    m.velocity_error = ref_cmd.velocity - out.v_hat;
    m.estimator_settled = t_cmd >= setup.estimator_settle_time;
    m.valid = out.valid;
    m.saturated = out.active.saturated;
    m.envelope_widened = out.active.envelope_widened;
    m.e_true = ref.position - p_r;
    m.t = t;
    m.p_r = p_r;
    m.conflict = out.active.conflict;
    m.escaping = !out.u_t.isZero(0.0);
    m.passing_side = out.passing_side;
    m.avoiding = out.active.avoiding;
    m.obstacles = &obstacles;
    m.zone_radius = config.effectiveRadius();
    metrics.add(m);

    if (observer) {  // (filled only for an observer: the benchmark has none)
      ClosedLoopStep step;
      step.t = t;
      step.h = h;
      step.pose = pose;
      step.reference = ref;
      step.sample = sample;
      step.pose_sample = robot;
      step.output = out;
      step.p_r_true = p_r;
      step.clearance_offset = clearance_offset;
      step.clearance_body = clearance_body;
      step.body_velocity = base ? base->velocity() : out.u;
      step.obstacles = &obstacles;
      observer(step);
    }
    if (last) break;
    pose = base ? core::driveBody(base.get(), pose, out.u, h) : core::integrateUnicycle(pose, heading, out.u, h);
    if (!fixed_step) t += h;
  }
  summary.metrics = metrics.result();
  return summary;
}

}  // namespace sim
}  // namespace amigobot_tracking

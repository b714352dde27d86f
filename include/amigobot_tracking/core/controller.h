// The paper's controller, eqs. (3)-(13), as one object with a `step` per control period;
// with config.law == "recommended" the same object runs the recommended law
// (recommended_law.h) on the same estimator, start rule and envelope guard.
//
// Start and envelope rule: T(|e|/rho) is undefined for |e| >= rho. When the target starts
// farther than max_error_ratio * rho_0, rho(0) is set to |e(0)| / max_error_ratio (the
// robot goes, and rho then decays at the prescribed rate); whenever a discrete step leaves
// |e| >= max_error_ratio * rho, rho is widened the same way. Both events are reported in
// the output flags, so tests can check they did not happen where the theory says so.
#pragma once

#include <cmath>
#include <cstdint>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/controller_config.h"
#include "amigobot_tracking/core/diamond.h"
#include "amigobot_tracking/core/estimator.h"
#include "amigobot_tracking/core/prescribed_performance.h"
#include "amigobot_tracking/core/types.h"

namespace amigobot_tracking {
namespace core {

// A measurement of the target position p_d taken at `stamp` [s].
struct TargetSample {
  double stamp = 0.0;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  // Optional target velocity from elsewhere (another estimator, the target's odometry):
  // when has_velocity, it replaces the estimator's v_hat in (9); the estimator still runs.
  bool has_velocity = false;
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
};

// A measurement of the robot pose taken at `stamp` [s].
struct PoseSample {
  double stamp = 0.0;
  Pose2 pose;
};

// Which constraints shaped this step's command.
struct ActiveConstraints {
  bool saturated = false;         // u != u_d: the diamond clipped the command
  bool avoiding = false;          // at least one obstacle within the detection distance
  bool conflict = false;          // e_hat^T u_c < 0: avoidance opposes tracking
  bool rho_relaxed = false;       // the adaptive term of (13) widened rho this step
  bool envelope_widened = false;  // rho widened to keep |e|/rho <= max_error_ratio
};

struct ControllerOutput {
  bool valid = false;             // false: inputs were not usable; u is zero
  std::string error;              // why not valid
  Twist2 u;                       // applied command sigma(u_d), always inside the diamond
  Twist2 u_d;                     // desired command (11)
  double t = 0.0;
  double rho = 0.0;
  double rho_floor = 0.0;         // recommended law: rho's floor, rho_inf plus the measured noise's reach [m]
  Eigen::Vector2d e = Eigen::Vector2d::Zero();       // p_d - p_r
  Eigen::Vector2d p_r = Eigen::Vector2d::Zero();     // offset point
  Eigen::Vector2d p_d = Eigen::Vector2d::Zero();     // target position used
  Eigen::Vector2d v_hat = Eigen::Vector2d::Zero();   // estimated target velocity
  Eigen::Vector2d u_c = Eigen::Vector2d::Zero();     // repulsive term (10), before k_o
  Eigen::Vector2d u_t = Eigen::Vector2d::Zero();     // tangential escape term, before k_o (extension)
  Eigen::Vector2d u_r = Eigen::Vector2d::Zero();     // offset-point velocity (9)
  int passing_side = 0;           // latched side of the tangential term (+1 ccw, -1 cw, 0 released)
  int detected_obstacles = 0;
  double min_clearance = 0.0;     // of the effective disk around p_r [m]; +inf if none
  ActiveConstraints active;
};

class PerformanceController {
 public:
  // The config must be valid (validate() empty); the constructor does not check it.
  explicit PerformanceController(const ControllerConfig& config = ControllerConfig());

  // One control step at time t [s] (monotonic). The target sample updates the estimator
  // when its stamp is newer than the last one. Non-finite pose or target, or time going
  // backwards, gives valid = false and a zero command.
  ControllerOutput step(double t, const Pose2& pose, const TargetSample& target,
                        const std::vector<Disk>& obstacles);
  // The same with the pose's own stamp (used when compensate_pose_age is on).
  ControllerOutput stepStamped(double t, const PoseSample& robot, const TargetSample& target,
                               const std::vector<Disk>& obstacles);

  // Forget all state: the next step starts afresh (estimator, rho, start rule).
  void reset();
  // reset(), and the next step starts rho at max(rho_0, |e| / start_ratio) instead of rho_0,
  // so |e|/rho <= start_ratio (0 < start_ratio): resuming far from the target does not
  // start with the envelope pressed against |e|. Only that step; rho then follows (13).
  void restart(double start_ratio);
  // Offline simulation only: the next command will be held for h [s]. h > 0 evaluates the
  // repulsive term of the nearest obstacle the offset point can reach within h backward-Euler,
  // at the clearance it has at the end of the step (band_implicit.h), so long steps neither
  // chatter across the detection band nor enter the disk. 0 (the default, and what the robot
  // uses): the paper's explicit (10). Ignored with moving_obstacles.
  void setImplicitHorizon(double h) {
    implicit_horizon_ = h;
    implicit_start_given_ = false;
  }
  // The same when the command will be held from `start`, not from the pose of the step (the
  // simulator's midpoint evaluation: the step's pose is a prediction half a step ahead).
  void setImplicitHorizon(double h, const Pose2& start) {
    setImplicitHorizon(h, start, Eigen::Vector2d(std::cos(start.theta), std::sin(start.theta)));
  }
  // The same with start_heading = (cos, sin) of start.theta already at hand.
  void setImplicitHorizon(double h, const Pose2& start, const Eigen::Vector2d& start_heading) {
    implicit_horizon_ = h;
    implicit_start_ = start;
    implicit_start_heading_ = start_heading;
    implicit_start_given_ = true;
  }
  // Swap the parameters between steps, keeping the state (rho is re-clamped to its rules).
  void setConfig(const ControllerConfig& config);

  const ControllerConfig& config() const { return config_; }
  const VelocityEstimator& estimator() const { return estimator_; }
  const DiamondSet& diamond() const { return diamond_; }
  bool started() const { return started_; }
  double rho() const { return rho_; }
  std::uint64_t envelopeWidenings() const { return envelope_widenings_; }

 private:
  ControllerOutput invalid(double t, std::string why);
  // The pose moved from its stamp to t along the commands applied meanwhile (at most
  // max_prediction seconds of them): exact for the unicycle, what odometry would give.
  Pose2 compensatedPose(double t, const PoseSample& robot) const;
  void remember(double t, const Twist2& u);
  // config.law == "recommended": u from recommended_law.h into `out` (p_r, e, v_hat, rho set).
  bool commandRecommended(const Pose2& pose, const std::vector<Disk>& obstacles, double h, ControllerOutput& out);

  ControllerConfig config_;
  DiamondSet diamond_;
  PerformanceGains gains_;
  VelocityEstimator estimator_;
  bool started_ = false;
  double last_t_ = 0.0;
  double rho_ = 0.0;
  double start_ratio_ = 0.0;  // > 0: the next start uses restart()'s rule
  double conflict_ = 0.0;  // second argument of the min in (13), from the last step
  double shortfall_ = 0.0; // relaxation term of (13') (recommended law), from the last step
  // The recommended law's feed-forward: v_hat followed at most estimator.max_acceleration per
  // second (recommended_law.h); NaN until the first step.
  Eigen::Vector2d feed_forward_ = Eigen::Vector2d::Constant(NAN);
  Eigen::Vector2d smoothed_velocity_ = Eigen::Vector2d::Constant(NAN);  // v_f, first-order over field_lookahead
  Twist2 last_command_;  // the recommended law's last u: its rate box is centred on it
  // The recommended law's noise estimate: the last target sample and the running mean of the
  // squared innovation of the samples against the feed-forward's prediction.
  double noise_variance_ = 0.0;
  double last_sample_stamp_ = NAN;
  Eigen::Vector2d last_sample_ = Eigen::Vector2d::Zero();
  void observeNoise(const TargetSample& target, bool jumped);
  double rhoFloor() const;
  int passing_side_ = 0;   // latched side of the tangential term (0 = released)
  // Applied commands, each held from its time to the next one's (zero before the first),
  // over the last max_prediction seconds: pose-age compensation replays them.
  std::deque<std::pair<double, Twist2>> commands_;
  std::uint64_t envelope_widenings_ = 0;
  double implicit_horizon_ = 0.0;
  Pose2 implicit_start_;
  Eigen::Vector2d implicit_start_heading_ = Eigen::Vector2d::UnitX();
  bool implicit_start_given_ = false;
};

}  // namespace core
}  // namespace amigobot_tracking

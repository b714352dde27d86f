// One interface for every control law that closes the loop: the paper's (paper_controller.h),
// the recommended law (recommended_controller.h), the proportional baseline
// (proportional_controller.h) and, in its own layer, MRPT's reactive navigator
// (sim_mrpt/reactive_law.h). A law is chosen once, by name, from law_registry.h; the code
// that runs it (the tracking loop, the simulator) never asks which one it holds.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/law/controller_config.h"
#include "amigobot_tracking/core/robot/diamond.h"
#include "amigobot_tracking/core/support/types.h"

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
  bool yielding = false;          // recommended law: a manoeuvre stepped out of a moving obstacle's way (yield_rollout.h)
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

// Offline simulation only: the next command will be held for h [s] from `start` (heading
// (cos, sin) of start.theta), or from the step's own pose when !start_given. A law whose
// avoidance is stiff across a step (the paper's explicit (10)) uses it; the others ignore it.
struct CommandHold {
  double h = 0.0;  // 0: the robot's case, the command is held one control period as usual
  bool start_given = false;
  Pose2 start;
  Eigen::Vector2d start_heading = Eigen::Vector2d::UnitX();
};

class ControlLaw {
 public:
  virtual ~ControlLaw() = default;
  // A copy with the same state (MRPT's navigator: a fresh one, its state cannot be copied).
  virtual std::unique_ptr<ControlLaw> clone() const = 0;
  // The law's registry name (law_registry.h).
  virtual std::string name() const = 0;

  // One control step at time t [s] (monotonic): the applied command inside diamond(),
  // e = p_d - p_r at the offset point, rho <= 0 when the law has no performance bound.
  // Non-finite inputs, or time going backwards, give valid = false and a zero command.
  virtual ControllerOutput step(double t, const PoseSample& robot, const TargetSample& target,
                                const std::vector<Disk>& obstacles) = 0;
  // Forget all state: the next step starts afresh.
  virtual void reset() = 0;
  // reset(), and a law with a performance bound starts rho at max(rho_0, |e| / start_ratio)
  // on the next step (0 < start_ratio): resuming far away does not start pressed against |e|.
  virtual void restart(double start_ratio) {
    (void)start_ratio;
    reset();
  }
  // Swap the parameters between steps, keeping the state. The config must be valid.
  virtual void setConfig(const ControllerConfig& config) = 0;
  virtual const ControllerConfig& config() const = 0;
  virtual const DiamondSet& diamond() const = 0;
  // See CommandHold; ignored by default.
  virtual void holdNextCommand(const CommandHold& hold) { (void)hold; }

  // The performance bound's state (0 for a law without one).
  virtual bool started() const { return false; }
  virtual double rho() const { return 0.0; }
  virtual std::uint64_t envelopeWidenings() const { return 0; }
  // The target velocity estimator (3)-(4) the law runs, if it runs one.
  virtual const VelocityEstimator* estimator() const { return nullptr; }
};

}  // namespace core
}  // namespace amigobot_tracking

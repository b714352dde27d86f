// What the tracking node may send, around the controller (the paper leaves target loss
// open). ROS-free: ages and times are plain seconds, so every rule is unit-tested.
//
// - Disabled: nothing is sent (cmd_vel is left to others), except one zero on disable.
// - Stale inputs: a robot pose or target missing or older than pose_timeout, or (with
//   require_scan) no scan within scan_timeout, gives an immediate zero and a reason.
// - Resume: when the inputs are fresh again (and on enable) the controller is restarted:
//   the estimator starts at the first fresh target sample with zero velocity (no spike from
//   differentiating across the gap), and rho restarts at max(rho_0, |e| / 0.5)
//   (TrackingLoop::kRestartErrorRatio),
//   so |e|/rho <= 1/2 and T(|e|/rho) <= 0.55 (no saturating burst from an envelope pressed
//   against |e|); rho then decays at lambda.
// - A refused step (controller output invalid, or a command outside the diamond) gives zero.
// - Every zero of the supervisor's own re-arms the resume ramp (resume_ramp.h): from the next
//   step the command leaves zero by at most the ramp's accelerations times the time since the
//   last command (capped at one control period), until the controller's command is within
//   reach; then it passes unchanged. Braking is never held back.
// - Bad localisation (its status, or a pose jump larger than the tracking bound) gives zero
//   until localisation has been good for jump_settle; then the resume is the usual one.
// - Something inside the body (a scan point, a virtual obstacle around the robot) gives zero:
//   the laser is blind or the robot is already where it must not be.
// Non-finite ages or times count as stale; a non-finite command is never sent.
#pragma once

#include <string>

#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/core/robot/diamond.h"
#include "amigobot_tracking/core/supervision/resume_ramp.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

struct SupervisorConfig {
  double pose_timeout = 0.5;    // [s] older robot pose or target -> zero
  double scan_timeout = 0.5;    // [s] older scan -> not fresh
  bool require_scan = true;     // a stale scan -> zero
  double control_period = 0.05; // [s] the ramp's time step never exceeds it
  RampLimits ramp;
  // Localisation jumps: the robot's pose moving further in one cycle than pose_jump_limit
  // (the tracking bound rho_inf) beyond what max_speed explains is a jump; tracking stops and
  // resumes when localisation has been good for jump_settle. 0 = off.
  double pose_jump_limit = 0.0;  // [m]
  double max_speed = 1.0;        // [m/s] the robot's own motion between two cycles
  double jump_settle = 1.0;      // [s]
  // Named in the reasons: "no robot pose <pose_link>", "no target <target_link>".
  std::string pose_link = "map -> base_link";
  std::string target_link = "map -> target";
};

// One control cycle's inputs, as the node found them.
struct SupervisorInputs {
  bool have_pose = false;   // the transform to the robot exists
  double pose_age = 0.0;    // [s]
  bool have_target = false;
  double target_age = 0.0;  // [s]
  double scan_age = -1.0;   // [s] of the last scan turned into disks; < 0: none yet
  // Why a stamp is not trusted (core/supervision/input_age.h: "stamp is 0", "stamped 30 s in the
  // future"); "" when usable. Non-empty is stale, named in the status.
  std::string pose_problem, target_problem, scan_problem;
  // What is inside the robot's body ("" when nothing): a scan point, or a virtual obstacle
  // containing the robot. Non-empty stops with "body intrusion: ...".
  std::string body_intrusion;
  // Localisation quality (the localisation_status topic): "" when good or not watched, else
  // why it is bad ("match 0.31 < min_match 0.5"). Non-empty stops with "localisation: ...".
  std::string localization_problem;
  Eigen::Vector2d pose_position = Eigen::Vector2d::Zero();  // [m] the robot in the global frame (jumps)
};

class TrackingSupervisor {
 public:
  enum class State {
    kDisabled,
    kTracking,       // the controller's command (ramped) was sent
    kInputsStale,    // zero: pose, target or scan missing or old
    kStepInvalid,    // zero: the controller refused the step (output invalid)
    kCommandRefused  // zero: the command was outside the diamond or not finite (never expected)
  };

  struct Decision {
    bool step = false;     // run the controller this cycle, then call finish()
    bool restart = false;  // first restart it (TrackingLoop::kRestartErrorRatio)
    bool publish = false;  // send `u` now (a zero, when !step)
    Twist2 u;
  };

  explicit TrackingSupervisor(const SupervisorConfig& config = SupervisorConfig()) : config_(config) {}

  // True when this enabled tracking (it was off): the caller restarts the controller now.
  // The robot is taken as standing: the command leaves zero on the ramp (ramp = false: the
  // first command passes unchanged; the offline simulator's start).
  bool enable(bool ramp = true);
  // Disables at t [s]; returns the one zero to send.
  Twist2 disable(double t);

  // Start of a cycle at t [s].
  Decision begin(double t, const SupervisorInputs& in);
  // After the controller's step: the command to send (always sent).
  Twist2 finish(double t, const ControllerOutput& out, const DiamondSet& diamond);

  // A scan of this age gives laser obstacles (fresh, and not missing).
  bool scanFresh(double scan_age) const { return scan_age >= 0.0 && scan_age <= config_.scan_timeout; }

  bool enabled() const { return enabled_; }
  bool ramping() const { return ramping_; }  // the resume ramp is on
  State state() const { return state_; }
  // "disabled", "tracking", or why the command is zero.
  const std::string& status() const { return status_; }
  const SupervisorConfig& config() const { return config_; }
  // Between two cycles (the tracking bound changed by reconfigure); 0 = off.
  void setPoseJumpLimit(double limit) { config_.pose_jump_limit = limit; }

 private:
  std::string staleReason(double t, const SupervisorInputs& in) const;  // "" when fresh
  std::string localizationReason(double t, const SupervisorInputs& in);  // "" when good; tracks jumps
  Twist2 stop(double t, State state, std::string why);  // an immediate zero; re-arms the ramp
  Twist2 ramp(double t, const Twist2& u);

  SupervisorConfig config_;
  bool enabled_ = false;
  bool lost_ = false;  // inputs were stale or the step invalid: restart on the next fresh step
  bool ramping_ = true;
  Twist2 last_command_;          // last command sent (zero after a stop)
  bool have_command_time_ = false;
  double last_command_time_ = 0.0;  // [s]
  bool have_position_ = false, jumped_ = false;
  Eigen::Vector2d last_position_ = Eigen::Vector2d::Zero();
  double last_position_time_ = 0.0, good_since_ = 0.0;  // [s]
  std::string jump_;  // the last jump, while it holds tracking
  State state_ = State::kDisabled;
  std::string status_ = "disabled";
};

}  // namespace core
}  // namespace amigobot_tracking

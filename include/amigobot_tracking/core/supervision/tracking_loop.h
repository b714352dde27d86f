// One control cycle of the tracking stack behind one call, ROS-free: the supervisor (what may
// be sent: enable, stale inputs, resume, ramp), the paper's controller, the obstacle set
// (laser disks while the scan is fresh, minus those on the target, plus the operator's
// virtual disks) and the swap of a new ControllerConfig between two steps. The tracking
// nodelet, the offline simulator (paper and fixed-rho laws), the benchmarks and the replay
// test run this same object; all times are seconds on one clock.
//
// The controller holds the one ControllerConfig in use; a config from reconfigure waits in
// `pending` until the start of the next step.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/core/supervision/tracking_supervisor.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

struct TrackingLoopConfig {
  SupervisorConfig supervisor;
  ControllerConfig controller;        // must be valid (validate() empty)
  double target_exclusion_radius = 0.0;  // [m] laser disks this near the target are the target; 0: none dropped
  // A localisation jump larger than the tracking bound stops (the robot): the supervisor's
  // pose_jump_limit is the controller's rho_inf, at start and after every config swap.
  bool pose_jump_limit_is_rho_inf = false;
};

// What one cycle sees. The disk vectors are read during step() only.
struct TrackingLoopInputs {
  double t = 0.0;  // [s] now
  // Presence, ages and why an input is not trusted (stamps, localisation, something inside
  // the body); each non-empty problem stops the robot, named in the status. Its
  // pose_position is taken from `pose` by step().
  SupervisorInputs supervisor;
  PoseSample pose;  // its stamp in the same clock as t
  TargetSample target;
  const std::vector<Disk>* scan_disks = nullptr;     // laser; used only while supervisor.scan_age is fresh
  const std::vector<Disk>* virtual_disks = nullptr;  // always used
};

struct TrackingLoopResult {
  bool publish = false;     // send u now (a zero of the supervisor's, or the command)
  Twist2 u;
  bool tracking = false;    // the controller's (ramped) command was sent: output is its step
  bool stepped = false;     // the controller ran (output filled; u refused when !tracking)
  ControllerOutput output;  // with output.u = what was sent when tracking
  std::size_t laser_disks = 0, virtual_disks = 0;  // in obstacles()
};

class TrackingLoop {
 public:
  // |e|/rho at a restart (resume and enable): rho restarts at max(rho_0, |e| / this), so
  // T(|e|/rho) <= 0.55 and the resume has no saturating burst (tracking_supervisor.h).
  static constexpr double kRestartErrorRatio = 0.5;

  explicit TrackingLoop(const TrackingLoopConfig& config = TrackingLoopConfig());

  TrackingLoopResult step(const TrackingLoopInputs& in);

  // True when this enabled tracking. resume (the robot, always): the controller restarts
  // (kRestartErrorRatio) and the command leaves zero on the ramp. resume = false: the
  // controller's own start (the paper's start rule) and its first command unramped: the
  // offline simulator's t = 0.
  bool enable(bool resume = true);
  Twist2 disable(double t);  // the one zero to send

  // Applied at the start of the next step (the controller keeps its state). Must be valid.
  void setPendingConfig(const ControllerConfig& config) { pending_ = config; }
  // The config the next step runs with: the pending one, else the one in use.
  const ControllerConfig& nextConfig() const { return pending_ ? *pending_ : controller_.config(); }
  bool configPending() const { return pending_.has_value(); }

  bool scanFresh(double scan_age) const { return supervisor_.scanFresh(scan_age); }
  const TrackingSupervisor& supervisor() const { return supervisor_; }
  const PerformanceController& controller() const { return controller_; }
  PerformanceController& controller() { return controller_; }  // the simulator's implicit horizon
  const std::vector<Disk>& obstacles() const { return obstacles_; }  // of the last step
  double targetExclusionRadius() const { return target_exclusion_radius_; }

 private:
  void assembleObstacles(const TrackingLoopInputs& in, TrackingLoopResult* result);

  TrackingSupervisor supervisor_;
  PerformanceController controller_;
  std::optional<ControllerConfig> pending_;
  double target_exclusion_radius_;
  bool pose_jump_limit_is_rho_inf_;
  std::vector<Disk> obstacles_;
};

}  // namespace core
}  // namespace amigobot_tracking

#include "amigobot_tracking/core/supervision/tracking_loop.h"

#include "amigobot_tracking/core/perception/scan_obstacles.h"

namespace amigobot_tracking {
namespace core {

namespace {

SupervisorConfig supervisorConfigOf(const TrackingLoopConfig& config) {
  SupervisorConfig s = config.supervisor;
  if (config.pose_jump_limit_is_rho_inf) s.pose_jump_limit = config.controller.rho_inf;
  return s;
}

}  // namespace

TrackingLoop::TrackingLoop(const TrackingLoopConfig& config)
    : supervisor_(supervisorConfigOf(config)),
      controller_(config.controller),
      target_exclusion_radius_(config.target_exclusion_radius),
      pose_jump_limit_is_rho_inf_(config.pose_jump_limit_is_rho_inf) {}

bool TrackingLoop::enable(bool resume) {
  if (!supervisor_.enable(resume)) return false;
  if (resume) controller_.restart(kRestartErrorRatio);
  return true;
}

Twist2 TrackingLoop::disable(double t) { return supervisor_.disable(t); }

void TrackingLoop::assembleObstacles(const TrackingLoopInputs& in, TrackingLoopResult* result) {
  obstacles_.clear();
  if (in.scan_disks && supervisor_.scanFresh(in.supervisor.scan_age)) {
    obstacles_ = *in.scan_disks;
    // Laser disks on the followed robot are the target, not obstacles.
    if (in.supervisor.have_target) dropDisksNear(in.target.position, target_exclusion_radius_, &obstacles_);
  }
  result->laser_disks = obstacles_.size();
  if (in.virtual_disks) obstacles_.insert(obstacles_.end(), in.virtual_disks->begin(), in.virtual_disks->end());
  result->virtual_disks = obstacles_.size() - result->laser_disks;
}

TrackingLoopResult TrackingLoop::step(const TrackingLoopInputs& in) {
  TrackingLoopResult r;
  if (pending_) {  // reconfigure: swapped between two steps only
    controller_.setConfig(*pending_);
    if (pose_jump_limit_is_rho_inf_) supervisor_.setPoseJumpLimit(pending_->rho_inf);
    pending_.reset();
  }
  assembleObstacles(in, &r);
  SupervisorInputs s = in.supervisor;
  s.pose_position = in.pose.pose.position();
  const TrackingSupervisor::Decision decision = supervisor_.begin(in.t, s);
  r.publish = decision.publish;
  r.u = decision.u;
  if (!decision.step) return r;

  if (decision.restart) controller_.restart(kRestartErrorRatio);  // resume: start afresh
  r.output = controller_.stepStamped(in.t, in.pose, in.target, obstacles_);
  r.stepped = true;
  // The output shows what was sent: u is the ramped command while ramping.
  r.u = supervisor_.finish(in.t, r.output, controller_.diamond());
  r.publish = true;
  r.tracking = supervisor_.state() == TrackingSupervisor::State::kTracking;
  if (r.tracking) r.output.u = r.u;
  return r;
}

}  // namespace core
}  // namespace amigobot_tracking

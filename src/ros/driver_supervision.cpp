// The driver's watch of what it cannot see through the link's own state: a ROS master that
// is gone (nobody could stop the robot through ROS) and a link that carries only the
// robot's half (the robot stops by its watchdog, the driver must say why).
#include "amigobot_tracking/ros/driver.h"

namespace amigobot_tracking {
namespace ros_layer {

void AmigobotDriver::checkMaster() {
  const MasterWatch::State master = master_->state();
  switch (master_outage_.check(master.reachable, master.unreachable_for, master.identity, params_.master_timeout)) {
    case MasterOutage::Action::kStop:
      master_stop_ = true;
      motors_before_outage_ = client_->status().motors_requested;
      client_->setVelocity({});
      client_->requestMotors(false);
      ROS_ERROR_STREAM_NAMED("driver", "ROS master unreachable for " << master.unreachable_for << " s (master_timeout "
                                                                      << params_.master_timeout
                                                                      << " s): robot stopped, motors disabled until "
                                                                         "the same master answers again");
      updater_.force_update();
      break;
    case MasterOutage::Action::kResume:
      master_stop_ = false;
      if (motors_before_outage_) client_->requestMotors(true);
      ROS_WARN_STREAM_NAMED("driver", "the same ROS master answers again (it was busy or the link hiccuped): cmd_vel "
                                      "accepted"
                                          << (motors_before_outage_ ? ", the motors on again as before the outage"
                                                                    : "; the motors stay off as they were"));
      updater_.force_update();
      break;
    case MasterOutage::Action::kStayStopped:  // a new master: said below, once it has our registrations
      master_stop_ = false;
      updater_.force_update();
      break;
    case MasterOutage::Action::kNone:
      break;
  }
  if (master.registrations != master_registrations_) {
    master_registrations_ = master.registrations;
    ROS_INFO_STREAM_NAMED("driver", "a new ROS master answers: this process registered again ("
                                        << master.last_registration
                                        << "); cmd_vel accepted, the motors stay disabled until enable_motors");
  }
}

void AmigobotDriver::reportOneWayLink(const aria::ClientStatus& status) {
  const bool one_way = status.link == aria::LinkState::kConnected &&
                       status.acknowledgement == aria::AcknowledgementState::kUnacknowledged;
  if (one_way) {
    ROS_ERROR_STREAM_THROTTLE_NAMED(2.0, "driver", "one-way link: the robot has not answered for "
                                                       << status.unanswered_for
                                                       << " s while its SIPs arrive; it does not hear the driver "
                                                          "and its watchdog stops it");
  }
  if (one_way != one_way_reported_) {
    one_way_reported_ = one_way;
    updater_.force_update();  // diagnostics now, not at the next 1 s tick
  }
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
